//! The compliant 3-D peg with the stiffness from the curvatures
//! (`HertzMode::Curvature`): the term `−(2/5) δ^{5/2} ∂k/∂(pose)` against
//! central differences of `k` and of the contact potential over the pose.

use crate::common::peg3d;

use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector3};
use peg3d::{orientation, rim_on_mouth};
use pegdyn::compliant_peg_3d::{HertzMode, Peg3d, Peg3dParams, pose_state};
use std::f64::consts::PI;

/// The Fig. 9 peg (D = 50 mm, d = 49.95 mm, L = 70 mm) with 1 mm fillets
/// and a 100 mm bore, steel on steel, stiffness from the curvatures.
fn fig9() -> Peg3dParams {
    let prm = peg3d::fig9();
    assert_eq!(prm.hertz, HertzMode::Curvature);
    prm
}

/// The state at rest moved by `s` along pose direction `i`: a translation
/// along hole axis `i < 3`, a rotation about hole axis `i − 3` through the
/// centre of mass.
fn moved(y: &SVector<f64, 15>, i: usize, s: f64) -> SVector<f64, 15> {
    let mut z = *y;
    if i < 3 {
        z[i] += s;
    } else {
        let mut e = Vector3::zeros();
        e[i - 3] = s;
        let q = UnitQuaternion::from_quaternion(Quaternion::new(y[3], y[4], y[5], y[6]));
        let q = UnitQuaternion::from_scaled_axis(e) * q;
        z[3] = q.w;
        z[4] = q.i;
        z[5] = q.j;
        z[6] = q.k;
    }
    z
}

/// Central differences of `f` over the 6 pose directions of [`moved`],
/// Richardson-extrapolated from steps `h` and `2h` (error `O(h⁴)`).
fn gradient(y: &SVector<f64, 15>, h: f64, f: impl Fn(&SVector<f64, 15>) -> f64) -> [f64; 6] {
    let central = |i: usize, h: f64| (f(&moved(y, i, h)) - f(&moved(y, i, -h))) / (2.0 * h);
    std::array::from_fn(|i| (4.0 * central(i, h) - central(i, 2.0 * h)) / 3.0)
}

/// Rim tube-centre circle tilted by `gamma` towards azimuth `psi`, its
/// lowest point `depth` below `ρ_p` above the plane `z0`, the rim circle's
/// centre over `(cx, 0)`.
fn rim_on_plane(
    prm: &Peg3dParams,
    gamma: f64,
    psi: f64,
    z0: f64,
    depth: f64,
    cx: f64,
) -> SVector<f64, 15> {
    let q = orientation(gamma, psi, 1.1);
    let axis = q * Vector3::z();
    let rr = prm.peg_radius() - prm.rim_fillet;
    let h = prm.rim_fillet - 0.5 * prm.length;
    let (ex, ey) = (q * Vector3::x(), q * Vector3::y());
    let lowest = h * axis.z - rr * ex.z.hypot(ey.z);
    let p = Vector3::new(
        cx - h * axis.x,
        -h * axis.y,
        z0 + prm.rim_fillet - depth - lowest,
    );
    pose_state(p, q, Vector3::zeros(), Vector3::zeros())
}

/// Tilted by `gamma` (axis leaning to −x), low in the bore, the rim pushed
/// `depth` into the wall at +x.
fn rim_on_wall(prm: &Peg3dParams, gamma: f64, depth: f64) -> SVector<f64, 15> {
    let q = orientation(gamma, PI, 0.3);
    let a = q * Vector3::z();
    let rr = prm.peg_radius() - prm.rim_fillet;
    let h = prm.rim_fillet - 0.5 * prm.length;
    let x = prm.bore_radius() + depth - prm.rim_fillet - rr * (1.0 - a.x * a.x).sqrt() - h * a.x;
    pose_state(
        Vector3::new(x, 0.0, -0.06),
        q,
        Vector3::zeros(),
        Vector3::zeros(),
    )
}

/// Tilted by `gamma` about `y`, the axis through the mouth's tube-centre
/// circle's centre with the rim 2 mm below it, then moved along `−x` until
/// the peg's side is `depth` into the mouth fillet at angle 0 (gap
/// `(R+ρ_h) cos γ − r − ρ_h` before the move, which raises it by
/// `s cos γ`), and along `y` by `y`.
fn side_on_mouth(prm: &Peg3dParams, gamma: f64, depth: f64, y: f64) -> SVector<f64, 15> {
    let (r, big_r, rho) = (prm.peg_radius(), prm.bore_radius(), prm.mouth_fillet);
    let q = orientation(gamma, 0.0, 0.4);
    let pen0 = r + rho - (big_r + rho) * gamma.cos();
    let shift = Vector3::new(-(pen0 - depth) / gamma.cos(), y, 0.0);
    let p =
        Vector3::new(0.0, 0.0, -rho) + q * Vector3::new(0.0, 0.0, 0.5 * prm.length - 2e-3) + shift;
    pose_state(p, q, Vector3::zeros(), Vector3::zeros())
}

fn poses(prm: &Peg3dParams) -> Vec<(&'static str, SVector<f64, 15>)> {
    vec![
        (
            "rim on top face, γ 0.05",
            rim_on_plane(prm, 0.05, 0.7, 0.0, 5e-6, 0.08),
        ),
        (
            "rim on top face, γ 0.3",
            rim_on_plane(prm, 0.3, 2.0, 0.0, 3e-6, -0.09),
        ),
        (
            "rim on bore bottom, γ 0.02",
            rim_on_plane(prm, 0.02, -1.0, -prm.bore_depth, 4e-6, 0.0),
        ),
        ("rim on wall, γ 0.01", rim_on_wall(prm, 0.01, 5e-6)),
        ("side on mouth, γ 0.1", side_on_mouth(prm, 0.1, 4e-6, 0.0)),
        ("side on mouth, γ 0.2", side_on_mouth(prm, 0.2, 2e-6, -1e-4)),
        ("rim on mouth, one point", rim_on_mouth(prm, 0.02, 8e-6)),
        ("rim on mouth, γ 0.01", rim_on_mouth(prm, 0.01, 3e-6)),
    ]
}

#[test]
fn stiffness_term_is_minus_two_fifths_depth_to_five_halves_times_the_gradient_of_k() {
    // At poses with one contact per pair and no col: the reported term
    // −(2/5) δ^{5/2} (∂k/∂p, ∂k/∂φ) against k at the poses moved by ±1e-6 m
    // and ±1e-6 rad and twice that, extrapolated (truncation (h/ρ)⁴ ≈ 1e-12
    // with the fillet ρ = 1 mm; the pose's rounding 1e-17 m / h ≈ 1e-11).
    // Errors relative to |F_k| + |T_k|/(0.05 m) (a translation-invariant
    // contact, the rim on a flat, has no force part).
    let prm = fig9();
    let sys = Peg3d::new(prm);
    let mut checked = 0;
    for (name, y) in poses(&prm) {
        let forces = sys.forces(&y).unwrap();
        assert!(!forces.is_empty(), "{name}: no contact");
        for f in &forces {
            let pair = f.contact.pair;
            if f.contact.saddle.is_some()
                || forces.iter().filter(|g| g.contact.pair == pair).count() > 1
            {
                continue;
            }
            let k_at = |z: &SVector<f64, 15>| -> f64 {
                let fs = sys.forces(z).unwrap();
                let mine: Vec<_> = fs.iter().filter(|g| g.contact.pair == pair).collect();
                assert_eq!(mine.len(), 1, "{name}: {pair:?} split");
                mine[0].stiffness
            };
            let gk = gradient(&y, 1e-6, k_at);
            let d = f.contact.penetration;
            let e = -0.4 * d * d * d.sqrt();
            let expect: Vec<f64> = gk.iter().map(|g| e * g).collect();
            let got = [
                f.stiffness_force.x,
                f.stiffness_force.y,
                f.stiffness_force.z,
                f.stiffness_torque.x,
                f.stiffness_torque.y,
                f.stiffness_torque.z,
            ];
            let scale_f = expect[..3].iter().map(|v| v * v).sum::<f64>().sqrt();
            let scale_t = expect[3..].iter().map(|v| v * v).sum::<f64>().sqrt();
            let scale = scale_f + scale_t / 0.05;
            let worst = (0..6)
                .map(|i| (got[i] - expect[i]).abs() / if i < 3 { scale } else { scale * 0.05 })
                .fold(0.0_f64, f64::max);
            eprintln!(
                "{name}, {pair:?}: δ {d:.3e} m, k {:.4e}, |F_k| {scale_f:.3e} N (Hertz {:.3e} N), |T_k| {scale_t:.3e} N·m, worst relative error {worst:.2e}",
                f.stiffness, f.elastic
            );
            assert!(scale > 1e-5 * f.elastic, "{name}: term {scale} N");
            assert!(worst < 1e-5, "{name}, {pair:?}: {got:?} vs {expect:?}");
            checked += 1;
        }
    }
    assert!(checked >= 6, "only {checked} contacts checked");
}

#[test]
fn contact_wrench_at_rest_is_minus_the_gradient_of_the_curvature_potential() {
    // V = Σ (2/5) k δ^{5/2} (less the cols') with k from the curvatures:
    // the wrench at rest against −∂V/∂(pose) by central differences (steps
    // 2e-8 and 4e-8 m or rad, extrapolated: truncation (h/δ)⁴ ≈ 1e-10 at
    // δ = 2 µm, the pose's rounding 1e-17 m over h·(lever 0.05 m) ≈ 1e-9),
    // with and without the stiffness term.
    let prm = fig9();
    let sys = Peg3d::new(prm);
    let mut pairs = std::collections::BTreeSet::new();
    for (name, y) in poses(&prm) {
        let forces = sys.forces(&y).unwrap();
        for f in &forces {
            pairs.insert(format!("{:?}", f.contact.pair));
        }
        let w = Peg3d::wrench(&y, &forces);
        let mut without = w;
        for f in &forces {
            for k in 0..3 {
                without[k] -= f.stiffness_force[k];
                without[3 + k] -= f.stiffness_torque[k];
            }
        }
        let pot = |z: &SVector<f64, 15>| -> f64 {
            sys.forces(z).unwrap().iter().map(|f| f.potential).sum()
        };
        let g = gradient(&y, 2e-8, pot);
        let fs = w.fixed_rows::<3>(0).norm();
        let ts = w.fixed_rows::<3>(3).norm().max(fs * 0.01);
        let err = |w: &SVector<f64, 7>| {
            (0..6)
                .map(|i| (w[i] + g[i]).abs() / if i < 3 { fs } else { ts })
                .fold(0.0_f64, f64::max)
        };
        let (with_term, without_term) = (err(&w), err(&without));
        eprintln!(
            "{name}: {} contacts, |F| {fs:.3e} N, residual of −∇V relative: {with_term:.2e} with the term, {without_term:.2e} without",
            forces.len()
        );
        assert!(with_term < 1e-7, "{name}: residual {with_term}");
        assert!(
            without_term > 1e-5,
            "{name}: the term is negligible here ({without_term})"
        );
    }
    assert!(
        pairs.contains("RimTop")
            && pairs.contains("RimWall")
            && pairs.contains("EdgeSide")
            && pairs.contains("RimEdge")
            && pairs.contains("RimBottom"),
        "{pairs:?}"
    );
}

#[test]
fn fixed_stiffness_has_no_stiffness_term() {
    // With HertzMode::Fixed nothing of the term is computed or added: the
    // same poses report it as exactly zero.
    let mut prm = fig9();
    prm.hertz = HertzMode::Fixed(2e10);
    let sys = Peg3d::new(prm);
    for (name, y) in poses(&prm) {
        let forces = sys.forces(&y).unwrap();
        assert!(!forces.is_empty(), "{name}");
        for f in forces {
            assert_eq!(f.stiffness_force, Vector3::zeros());
            assert_eq!(f.stiffness_torque, Vector3::zeros());
        }
    }
}

#[test]
fn closed_form_log_slope_of_k_matches_differences() {
    // φ′ = d ln k/d ln(B/A) at fixed A + B from the elliptic integrals'
    // derivatives against central differences of ln k (step 2e-5 in ln r,
    // error about 1e-10), from near the circle to a slender ellipse.
    use pegdyn::compliant_peg_3d::stiffness::{log_slope, log_slope_by_differences};
    use pegdyn::hertz::{Curvatures, EllipticityMethod, HertzContact, Material};
    let steel = Material::STEEL;
    let mut worst = 0.0_f64;
    let mut checked = 0;
    for ratio in [1.05, 1.3, 2.0, 5.0, 30.0, 500.0, 1e4, 1e6] {
        let (a, b) = (10.0, 10.0 * ratio);
        let c = HertzContact::try_new(
            &Curvatures::aligned([2.0 * a, 2.0 * b], [0.0, 0.0]),
            &steel,
            &steel,
            EllipticityMethod::Exact,
        )
        .unwrap();
        let numeric = log_slope_by_differences(a, b, &steel, &steel).unwrap();
        let Some(closed) = log_slope(&c.ellipticity) else {
            assert!(ratio < 1.1, "no closed form at B/A = {ratio}");
            continue;
        };
        let err = (closed - numeric).abs() / numeric.abs();
        eprintln!(
            "B/A = {ratio:e}: φ′ {closed:.12e} (differences {numeric:.12e}), relative {err:.1e}"
        );
        worst = worst.max(err);
        checked += 1;
    }
    assert!(checked >= 7, "{checked}");
    assert!(worst < 1e-8, "worst {worst}");
}
