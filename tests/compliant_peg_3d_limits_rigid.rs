//! The compliant 3-D peg contains the rigid three-point peg as a limit:
//! its orientation driven along the rigid model's prescribed motion
//! (γ̇ = −2 1/s, ψ̇ = 0 and 10 1/s, the Fig. 9 peg), its translation free
//! under gravity with contact damping, the three contact forces approach
//! the rigid model's N_K, N_B1, N_B2 and the contact points approach K, B1,
//! B2 as the contacts stiffen.
//!
//! K is the peg's side on the mouth edge (pair `edge_side`), B1 and B2 the
//! peg's bottom rim on the mouth edge (the rim–mouth pair of
//! `compliant_peg_3d::prescribed`). The rigid model's edges are sharp; the
//! 3-D model's fillets shrink with the penetration (`ρ ∝ k^{−2/3}`), so that
//! both the fillets' and the compliance's departures from the rigid
//! geometry vanish together.

use nalgebra::{Matrix3, SVector, Vector2, Vector3};
use pegdyn::compliant_peg_3d::prescribed::{Motion, PrescribedPeg, Site, rim_mouth_minima};
use pegdyn::compliant_peg_3d::system::axis_of;
use pegdyn::compliant_peg_3d::{HertzMode, Pair, Peg3dParams, Search};
use pegdyn::integrate::{Method, Options, OutputMode, solve};
use pegdyn::rigid_peg::kinematics::Pose;
use pegdyn::rigid_peg::prescribed::reactions;
use pegdyn::rigid_peg::{Loads, PegParams};

const GAMMADOT: f64 = -2.0;

/// Contact forces and points of one state: `[K, B1, B2]` (N, m); a missing
/// contact has force 0 and point NaN. B1 is the rim contact on the `+e_n`
/// side (the one that leads when ψ̇ > 0). A merged B1–B2 counts as B1 or
/// B2 by the side it lies on.
fn three_points(sys: &PrescribedPeg, t: f64, y: &SVector<f64, 7>) -> ([f64; 3], [Vector3<f64>; 3]) {
    let (_, psi) = sys.motion.angles(t);
    let e_n = Vector3::new(-psi.sin(), psi.cos(), 0.0);
    let mut n = [0.0; 3];
    let mut pts = [Vector3::repeat(f64::NAN); 3];
    for f in sys.forces(t, y).unwrap() {
        let k = match f.site {
            Site::Pair(Pair::EdgeSide) => 0,
            Site::RimMouth | Site::Pair(Pair::RimWall) => {
                if f.point.dot(&e_n) >= 0.0 {
                    1
                } else {
                    2
                }
            }
            other => panic!("unexpected contact {other:?}"),
        };
        n[k] += f.normal_force;
        pts[k] = f.point;
    }
    (n, pts)
}

/// The gaps `[K, B1, B2]` (m) with the centre of mass at `c` at time 0:
/// the smallest valid edge–side minimum and the valid rim–mouth minima on
/// either side of the symmetry plane.
fn gaps(sys: &PrescribedPeg, c: &Vector3<f64>) -> [f64; 3] {
    let prm = &sys.peg.params;
    let q = sys.motion.orientation(0.0);
    let x = SVector::<f64, 7>::from_column_slice(&[c.x, c.y, c.z, q.w, q.i, q.j, q.k]);
    let axis = axis_of(&x);
    let pv = sys.peg.param_vector();
    let mut g = [f64::NAN; 3];
    for a in Search::default().minima(Pair::EdgeSide, prm, &x, pv) {
        let (gap, _, _, _, n, pt, axial) = Pair::EdgeSide.eval(&x, a, pv);
        if Pair::EdgeSide.valid(prm, &axis, &n, &pt, axial) && (g[0].is_nan() || gap < g[0]) {
            g[0] = gap;
        }
    }
    let e_n = Vector3::new(-sys.motion.psi.sin(), sys.motion.psi.cos(), 0.0);
    for m in rim_mouth_minima(prm, c, &q, 1e-3) {
        let k = if m.point.dot(&e_n) >= 0.0 { 1 } else { 2 };
        if m.valid && (g[k].is_nan() || m.gap < g[k]) {
            g[k] = m.gap;
        }
    }
    g
}

/// The centre of mass at which the three gaps are `−(N_i/k)^{2/3}`: the
/// compliant peg preloaded with the rigid model's reactions (Newton with a
/// central-difference Jacobian, from the rigid model's centre of mass).
fn preloaded_centre(
    sys: &PrescribedPeg,
    start: Vector3<f64>,
    normal: [f64; 3],
    k: f64,
) -> Vector3<f64> {
    let target = Vector3::from_fn(|i, _| -(normal[i].max(0.0) / k).powf(2.0 / 3.0));
    let resid = |c: &Vector3<f64>| Vector3::from(gaps(sys, c)) - target;
    let mut c = start;
    for _ in 0..30 {
        let r = resid(&c);
        assert!(
            r.iter().all(|v| v.is_finite()),
            "a contact is missing at {c}: {r}"
        );
        if r.norm() < 1e-14 {
            break;
        }
        let h = 1e-9;
        let jac = Matrix3::from_fn(|i, j| {
            let mut e = Vector3::zeros();
            e[j] = h;
            (resid(&(c + e))[i] - resid(&(c - e))[i]) / (2.0 * h)
        });
        c -= jac.lu().solve(&r).unwrap();
    }
    c
}

/// One row of the comparison: γ, the 3-D and rigid forces over m g, the
/// distance of each 3-D contact point from the rigid one.
#[derive(Clone, Copy, Debug)]
struct Row {
    gamma: f64,
    three_d: [f64; 3],
    rigid: [f64; 3],
    point_error: [f64; 3],
}

/// Fillet radius of both edges for stiffness `k`: 20 µm at
/// `k = 2.4·10¹⁰ N/m^{3/2}` (steel fillets of that size), scaled like the
/// penetration `(Q/k)^{2/3}`, about ten times the penetration under the
/// Fig. 9 loads (and below `ρ_p + ρ_h`, where the tube circles would cross).
fn fillet(k: f64) -> f64 {
    2e-5 * (k / 2.4e10).powf(-2.0 / 3.0)
}

/// The prescribed run from `gamma_s` (the compliant peg preloaded with the
/// rigid reactions there, moving with the rigid centre-of-mass velocity)
/// with stiffness `k`, Hunt–Crossley damping 50 s/m, friction 0.2 with
/// `v_s = 10⁻⁴ m/s`, sampled at `gammas`.
fn run(k: f64, psidot: f64, gamma_s: f64, gammas: &[f64]) -> Vec<Row> {
    let rho = fillet(k);
    let rigid = PegParams::fig9();
    let mut prm = Peg3dParams::steel(
        rigid.peg_diameter,
        rigid.height,
        rigid.hole_diameter,
        rho,
        rho,
        0.1,
    );
    prm.mass = rigid.mass;
    prm.gravity = rigid.gravity;
    prm.friction = rigid.friction;
    prm.slip_scale = 1e-4;
    prm.damping = 50.0;
    prm.hertz = HertzMode::Fixed(k);
    let motion = Motion {
        gamma: gamma_s,
        gammadot: GAMMADOT,
        psi: 0.0,
        psidot,
    };
    let sys = PrescribedPeg::try_new(prm, motion).unwrap();
    let react = |gamma: f64, psi: f64| {
        reactions(
            &rigid,
            &Loads::default(),
            Vector2::new(gamma, psi),
            Vector2::new(GAMMADOT, psidot),
            Vector2::zeros(),
        )
        .unwrap()
        .normal
    };
    let pose = Pose::try_new(&rigid, gamma_s, 0.0).unwrap();
    let v = pose.kinematics(Vector2::new(GAMMADOT, psidot)).v_c;
    let c = preloaded_centre(&sys, pose.c, react(gamma_s, 0.0), k);
    let y0 = SVector::<f64, 7>::from_column_slice(&[c.x, c.y, c.z, v.x, v.y, v.z, 0.0]);
    let times: Vec<f64> = gammas.iter().map(|g| (g - gamma_s) / GAMMADOT).collect();
    let mut opts = Options::with_tolerances(1e-8, 1e-12);
    opts.output = OutputMode::AtTimes(times.clone());
    let t_end = *times.last().unwrap();
    let sol = solve(&sys, Method::Dopri5, (0.0, y0), t_end, &opts).unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    let w = rigid.mass * rigid.gravity;
    sol.t
        .iter()
        .zip(&sol.x)
        .map(|(&t, y)| {
            let (gamma, psi) = motion.angles(t);
            let (n, pts) = three_points(&sys, t, y);
            let rp = Pose::try_new(&rigid, gamma, psi).unwrap();
            Row {
                gamma,
                three_d: n.map(|f| f / w),
                rigid: react(gamma, psi).map(|f| f / w),
                point_error: [0, 1, 2].map(|i| (pts[i] - rp.contacts[i]).norm()),
            }
        })
        .collect()
}

/// Largest force difference (over m g) and point distance (m) over rows.
fn worst(rows: &[Row]) -> (f64, f64) {
    rows.iter().fold((0.0_f64, 0.0_f64), |(f, p), r| {
        let df = (0..3)
            .map(|i| (r.three_d[i] - r.rigid[i]).abs())
            .fold(0.0, f64::max);
        let dp = r.point_error.iter().cloned().fold(0.0, f64::max);
        (f.max(df), p.max(dp))
    })
}

fn print(label: &str, rows: &[Row]) {
    for r in rows {
        eprintln!(
            "{label} γ {:.4}: 3-D [{:.3} {:.3} {:.3}] rigid [{:.3} {:.3} {:.3}] points [{:.1e} {:.1e} {:.1e}] m",
            r.gamma,
            r.three_d[0],
            r.three_d[1],
            r.three_d[2],
            r.rigid[0],
            r.rigid[1],
            r.rigid[2],
            r.point_error[0],
            r.point_error[1],
            r.point_error[2]
        );
    }
}

/// `count + 1` values of γ from `from` down to `to`.
fn grid(from: f64, to: f64, count: usize) -> Vec<f64> {
    (0..=count)
        .map(|i| from + (to - from) * i as f64 / count as f64)
        .collect()
}

#[test]
fn rigid_limit_with_precession_converges_as_the_contacts_stiffen() {
    // ψ̇ = 10 1/s from γ = 0.3 rad (where the rigid model's three-point
    // motion is feasible) to 0.06 rad; compared from 0.26 rad on.
    let gammas = grid(0.3, 0.06, 12);
    let mut table = Vec::new();
    for k in [2.4e9, 2.4e10, 2.4e11] {
        let rows = run(k, 10.0, 0.3, &gammas);
        print(&format!("k = {k:.1e}"), &rows);
        let (force, point) = worst(&rows[2..]);
        eprintln!(
            "k = {k:.1e} N/m^1.5, fillets {:.1e} m: max |N − N_rigid| = {force:.4} m g, max point distance {point:.2e} m",
            fillet(k)
        );
        table.push((force, point));
    }
    for w in table.windows(2) {
        assert!(
            w[1].0 < 0.3 * w[0].0,
            "force error does not shrink: {table:?}"
        );
        assert!(
            w[1].1 < 0.3 * w[0].1,
            "point error does not shrink: {table:?}"
        );
    }
    assert!(table[2].0 < 0.06, "{table:?}");
    assert!(table[2].1 < 3e-4, "{table:?}");
}

#[test]
fn rigid_limit_without_precession_follows_the_planar_motion_and_loses_k_where_the_rigid_one_pulls()
{
    // ψ̇ = 0: the rigid motion needs N_K < 0 for γ > 0.1426 rad. From
    // γ = 0.14 the 3-D peg follows it on three points with B1, B2
    // symmetric; from γ = 0.3 its K stays unloaded while the rigid one
    // pulls.
    let rows = run(2.4e10, 0.0, 0.14, &grid(0.14, 0.06, 8));
    print("ψ̇ = 0", &rows);
    let (force, point) = worst(&rows);
    eprintln!(
        "ψ̇ = 0 from 0.14 rad: max |N − N_rigid| = {force:.4} m g, max point distance {point:.2e} m"
    );
    assert!(force < 0.15 && point < 1e-3, "{force} {point}");
    for r in &rows {
        assert!(r.three_d.iter().all(|&n| n > 0.0));
        let asym = (r.three_d[1] - r.three_d[2]).abs() / r.three_d[1];
        assert!(asym < 1e-6, "B1, B2 differ by {asym:e} relative");
    }
    let rows = run(2.4e10, 0.0, 0.3, &grid(0.3, 0.16, 7));
    for r in &rows {
        assert!(r.rigid[0] < 0.0 && r.three_d[0] == 0.0, "{r:?}");
        assert!(r.three_d[1] > 0.0 && r.three_d[2] > 0.0, "{r:?}");
    }
}

#[test]
fn rigid_limit_with_precession_unloads_b1_towards_gamma0() {
    // ψ̇ = 10 1/s: the rigid model's leading contact B1 unloads towards γ0
    // (and lifts off for γ/γ0 − 1 < 5.5e-5); the stiff 3-D peg's B1 carries
    // less than B2 all the way and the gap between them widens, until the
    // two points merge.
    let rows = run(2.4e11, 10.0, 0.06, &grid(0.06, 0.0455, 29));
    print("near γ0", &rows);
    for r in &rows {
        assert!(r.three_d[1] < r.three_d[2], "{r:?}");
    }
    let (first, last) = (rows[0].three_d, rows[rows.len() - 1].three_d);
    let (ratio0, ratio1) = (first[1] / first[2], last[1] / last[2]);
    eprintln!("N_B1/N_B2: {ratio0:.4} at γ = 0.06, {ratio1:.4} at γ = 0.0455");
    assert!(ratio1 < ratio0 - 0.04, "{ratio0} {ratio1}");
}

#[test]
fn prescribed_peg_refuses_a_curvature_or_invalid_stiffness() {
    let motion = Motion {
        gamma: 0.3,
        gammadot: GAMMADOT,
        psi: 0.0,
        psidot: 0.0,
    };
    let mut prm = Peg3dParams::steel(0.04995, 0.07, 0.05, 1e-5, 1e-5, 0.1);
    for (mode, value) in [
        (HertzMode::Curvature, 0.0),
        (HertzMode::Fixed(-1.0), -1.0),
        (HertzMode::Fixed(0.0), 0.0),
    ] {
        prm.hertz = mode;
        match PrescribedPeg::try_new(prm, motion) {
            Err(pegdyn::hertz::HertzError::Invalid {
                field, value: v, ..
            }) => {
                assert_eq!(field, "hertz");
                assert_eq!(v, value);
            }
            Err(e) => panic!("{mode:?}: {e:?}"),
            Ok(_) => panic!("{mode:?} accepted"),
        }
    }
}

#[test]
fn rim_mouth_pair_matches_brute_force_and_its_direction_is_the_gap_gradient() {
    // Poses of the lean: the rigid pose at γ with ψ and a spin-free
    // orientation, the centre moved by up to ±50 µm. For each, the minima of
    // the rim–mouth gap against a dense double sampling of the two
    // tube-centre circles, and the force direction against the gradient of
    // the smallest gap in the centre position (envelope theorem).
    let rigid = PegParams::fig9();
    let rho = 2e-5;
    let prm = Peg3dParams::steel(
        rigid.peg_diameter,
        rigid.height,
        rigid.hole_diameter,
        rho,
        rho,
        0.1,
    );
    let (rr, rc) = (prm.peg_radius() - rho, prm.bore_radius() + rho);
    let (n_beta, n_alpha) = (1500, 1500);
    let mut checked = 0;
    for (i, gamma) in [0.05, 0.08, 0.12, 0.2, 0.3].into_iter().enumerate() {
        let psi = 0.7 * i as f64;
        let motion = Motion {
            gamma,
            gammadot: 0.0,
            psi,
            psidot: 0.0,
        };
        let q = motion.orientation(0.0);
        let pose = Pose::try_new(&rigid, gamma, psi).unwrap();
        let shift = Vector3::new(3e-5, -2e-5, -5e-5 * (i as f64 - 2.0) / 2.0);
        let c = pose.c + shift;
        let found = rim_mouth_minima(&prm, &c, &q, 1e-3);
        // Brute force: the smallest distance between the two circles on a
        // 1500 × 1500 grid of (β, α), then twice on a 400 × 400 grid of
        // ±2 cells around the best pair (cells 100 times smaller each time).
        let tau = std::f64::consts::TAU;
        let rim = |b: f64| c + q * Vector3::new(rr * b.cos(), rr * b.sin(), rho - 0.5 * prm.length);
        let mouth = |a: f64| Vector3::new(rc * a.cos(), rc * a.sin(), -rho);
        let mut best_pair = (0.0, 0.0, f64::MAX);
        let mut centre = (0.0, 0.0);
        let mut span = tau;
        for (level, n) in [(0, n_beta), (1, 400), (2, 400)] {
            let h = span / n as f64;
            let (b0, a0) = if level == 0 {
                (0.0, 0.0)
            } else {
                (centre.0 - 0.5 * span, centre.1 - 0.5 * span)
            };
            let mouth_pts: Vec<Vector3<f64>> = (0..n_alpha.min(n))
                .map(|k| mouth(a0 + k as f64 * h))
                .collect();
            for kb in 0..n {
                let b = b0 + kb as f64 * h;
                let p = rim(b);
                for (ka, m) in mouth_pts.iter().enumerate() {
                    let dist = (p - m).norm();
                    if dist < best_pair.2 {
                        best_pair = (b, a0 + ka as f64 * h, dist);
                    }
                }
            }
            centre = (best_pair.0, best_pair.1);
            span = 4.0 * h;
        }
        let brute = best_pair.2 - 2.0 * rho;
        let best = found.iter().map(|m| m.gap).fold(f64::MAX, f64::min);
        // The finest cells are 2.7e-8 rad: 7e-10 m along the circles.
        assert!(
            best <= brute + 1e-12 && best >= brute - 1e-9,
            "γ = {gamma}: found {best:e}, brute force {brute:e}"
        );
        // Direction = gradient of the smallest gap in the centre.
        let m = found.iter().min_by(|a, b| a.gap.total_cmp(&b.gap)).unwrap();
        let d = 1e-9;
        let grad = Vector3::from_fn(|j, _| {
            let mut e = Vector3::zeros();
            e[j] = d;
            let g = |cc: Vector3<f64>| {
                rim_mouth_minima(&prm, &cc, &q, 1e-3)
                    .iter()
                    .map(|m| m.gap)
                    .fold(f64::MAX, f64::min)
            };
            (g(c + e) - g(c - e)) / (2.0 * d)
        });
        assert!(
            (grad - m.normal).norm() < 1e-5,
            "γ = {gamma}: gradient {grad} vs direction {}",
            m.normal
        );
        eprintln!(
            "γ = {gamma}: {} minima, smallest gap {best:.3e} m (brute force {brute:.3e}), gradient error {:.1e}",
            found.len(),
            (grad - m.normal).norm()
        );
        checked += 1;
    }
    assert_eq!(checked, 5);
}
