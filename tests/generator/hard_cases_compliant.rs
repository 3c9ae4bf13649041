//! Hard cases of the compliant planar peg through the generated
//! code, `f64` against double-double (the same generic function at
//! `pegdyn::scalar::Dd`) and against closed forms: small clearances, Hertz
//! approaches of steel from 1 pm to 10 µm, zero and tiny velocities, and
//! the jamming factor k3 of Eq. (52) going to zero.

use nalgebra::SVector;
use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, Load};
use pegdyn::generated::compliant_peg_lean as lean;
use pegdyn::jamming::forces::{k_factors, try_sliding_contact_forces};
use pegdyn::jamming::{PegHole, SlidingIndeterminate};
use pegdyn::scalar::Dd;

const U: f64 = f64::EPSILON / 2.0;
const D: f64 = 0.05;

/// Parameters of the steel reference peg with radial clearance `c` (m),
/// frictionless or not, and the named parameter's value.
fn params(clearance: f64, mu: f64) -> SVector<f64, 24> {
    let spec = CompliantSpec::steel_cylinder(D, clearance / D, 0.1, mu);
    let p = CompliantParams::try_new(spec).expect("valid reference peg");
    p.vector(&Load {
        axial: 10.0,
        radial: 1.0,
        torque: 0.0,
    })
}

fn get(p: &SVector<f64, 24>, name: &str) -> f64 {
    p[lean::P_NAMES
        .iter()
        .position(|&n| n == name)
        .expect("parameter")]
}

/// The state touching the left edge with approach `delta` at θ = 0: there
/// δ = r − D/2 − x exactly, so x = r − D/2 − δ.
fn touching(p: &SVector<f64, 24>, delta: f64, velocity: [f64; 3]) -> SVector<f64, 8> {
    let x = get(p, "r") - 0.5 * get(p, "D") - delta;
    SVector::from([
        x,
        0.01,
        0.0,
        velocity[0],
        velocity[1],
        velocity[2],
        0.0,
        0.0,
    ])
}

fn to_dd<const N: usize>(v: &SVector<f64, N>) -> SVector<Dd, N> {
    v.map(Dd::from)
}

fn rel(v: f64, r: Dd) -> f64 {
    ((Dd::from(v) - r).hi() / r.hi()).abs()
}

/// Clearance D − 2r from 50 µm down to 1 nm at D = 50 mm, peg on the left
/// edge with δ = 1e-9 m at θ = 0: the generated penetration equals the
/// closed form r − D/2 − x (evaluated in double-double from the same
/// inputs) to 1 ulp in `f64`, and to 1e-30 in double-double. (Without the
/// `cos_near_equal` rewrite and the parameter-first sum order the error is
/// ulp(D/2)/δ ≈ 3.5e-9 relative, 3e7 ulps: `docs/ACCURACY.md`.)
#[test]
fn penetration_small_clearances_50um_to_1nm() {
    for clearance in [50e-6, 1e-6, 1e-7, 1e-8, 1e-9] {
        let p = params(clearance, 0.1);
        let y = touching(&p, 1e-9, [0.0; 3]);
        let exact = Dd::from(get(&p, "r")) - Dd::from(0.5 * get(&p, "D")) - Dd::from(y[0]);
        let delta = lean::contacts(&y, &p).delta;
        let delta_dd = lean::contacts(&to_dd(&y), &to_dd(&p)).delta;
        assert!(
            rel(delta[0], exact) <= U,
            "c={clearance}: δ={} vs {exact}",
            delta[0]
        );
        assert!(((delta_dd[0] - exact).hi() / exact.hi()).abs() < 1e-30);
    }
}

/// Hertz contact of steel (E = 210 GPa) on the edge at δ = 1e-12 … 1e-5 m,
/// 1 nm clearance: the normal force is k δ^{3/2} ((13), with
/// k the generated stiffness of the edge contact); the generated `f64`
/// force is within 4 ulps of k δ^{3/2} computed in double-double from the
/// exact δ, at every approach.
#[test]
fn hertz_steel_normal_force_from_1pm_to_10um() {
    let p = params(1e-9, 0.1);
    let k = Dd::from(get(&p, "k_edge"));
    for delta in [1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5] {
        let y = touching(&p, delta, [0.0; 3]);
        let exact_delta = Dd::from(get(&p, "r")) - Dd::from(0.5 * get(&p, "D")) - Dd::from(y[0]);
        let force = k * exact_delta * exact_delta.sqrt();
        let normal = lean::contacts(&y, &p).normal;
        let err = rel(normal[0], force) / U;
        assert!(
            err <= 4.0,
            "δ={delta}: {} vs {force}: {err} ulps",
            normal[0]
        );
    }
}

/// Zero sliding velocity at the edge contact (the peg at rest, touching):
/// the regularized Coulomb law gives exactly zero friction, and every
/// output of the right-hand side is finite; with θ̇ = 1e-12 rad/s instead
/// of 0 the slip is ~r θ̇ ≈ 2.5e-14 m/s, the friction opposes it with
/// μN·v/√(v² + v_s²) (v_s = 1e-5 m/s), and the right-hand side changes by
/// less than 1e-8 relative (no jump, no NaN: the law is continuous
/// through zero slip).
#[test]
fn zero_and_tiny_sliding_velocity() {
    let p = params(1e-6, 0.3);
    let at_rest = touching(&p, 1e-7, [0.0; 3]);
    let lean::ContactsOut { friction, slip, .. } = lean::contacts(&at_rest, &p);
    assert_eq!(slip[0], 0.0);
    assert_eq!(friction[0], 0.0);
    let f0 = lean::rhs(&at_rest, &p);
    assert!(f0.iter().all(|v| v.is_finite()), "{f0}");
    let tiny = touching(&p, 1e-7, [0.0, 0.0, 1e-12]);
    let f1 = lean::rhs(&tiny, &p);
    assert!(f1.iter().all(|v| v.is_finite()), "{f1}");
    let lean::ContactsOut {
        normal,
        friction,
        slip,
        ..
    } = lean::contacts(&tiny, &p);
    let expected = -0.3 * normal[0] * slip[0] / (slip[0].hypot(1e-5));
    assert!(slip[0] != 0.0 && (friction[0] - expected).abs() <= 1e-6 * expected.abs());
    for i in 3..6 {
        assert!(
            (f1[i] - f0[i]).abs() <= 1e-8 * f0[i].abs().max(1.0),
            "component {i}: {} vs {}",
            f1[i],
            f0[i]
        );
    }
}

/// The generated right-hand side and Jacobian at f64 against double-double
/// at θ = 0 over the clearance × approach grid: within 64 ulps for every
/// entry whose double-double value is not tiny next to the entry's scale.
/// (At θ ≠ 0 the penetration is a sum of terms of size r·θ that cancel to
/// δ, a cancellation of the inputs no formula avoids:
/// `pegdyn accuracy` reports it.)
#[test]
fn rhs_and_jacobian_at_zero_tilt_match_double_double() {
    for clearance in [50e-6, 1e-9] {
        for delta in [1e-12, 1e-9, 1e-6] {
            let p = params(clearance, 0.1);
            let y = touching(&p, delta, [0.0, 0.01, 0.0]);
            let f = lean::rhs(&y, &p);
            let fd = lean::rhs(&to_dd(&y), &to_dd(&p));
            for (v, r) in f.iter().zip(fd.iter()) {
                let scale = fd.iter().map(|r| r.hi().abs()).fold(0.0, f64::max);
                let err = (Dd::from(*v) - *r).hi().abs();
                assert!(
                    err <= 64.0 * U * r.hi().abs().max(1e-12 * scale),
                    "c={clearance} δ={delta}: {v} vs {r}"
                );
            }
        }
    }
}

/// Eq. (52) near its singular tilt: k3 = (1 − μ²) sin θ + 2μ cos θ
/// vanishes at θ* = −2 atan μ. Away from it (θ = θ*(1 + ε), ε ≥ 1e-9) the
/// contact forces are finite and within their condition bound of the
/// double-double closed form (relative error ≤ 16 u (1 + μ)² / |k3|); at θ*
/// itself `try_sliding_contact_forces` returns the typed
/// `SlidingIndeterminate` instead of ±∞ or a rounding-noise force.
#[test]
fn jamming_k3_to_zero_is_refused_with_a_type() {
    let mu = 0.3;
    let p = PegHole::try_new(0.0125, 0.002, mu).expect("valid peg");
    let theta_star = -2.0 * mu.atan();
    let (fx, fz) = (0.2, 1.0);
    match try_sliding_contact_forces(&p, theta_star, fx, fz) {
        Err(SlidingIndeterminate { theta, k3 }) => {
            assert_eq!(theta, theta_star);
            assert!(k3.abs() < 1e-15);
        }
        Ok(f) => panic!("θ* accepted: {f:?}"),
    }
    for k in 1..=9 {
        let theta = theta_star * (1.0 + 10f64.powi(-k));
        let f = try_sliding_contact_forces(&p, theta, fx, fz).expect("determinate");
        let (s, c) = Dd::from(theta).sin_cos();
        let m = Dd::from(mu);
        let (k1, k2) = (c - m * s, s + m * c);
        let k3 = k2 + m * k1;
        let edge = (Dd::from(fz) + m * Dd::from(fx)) / k3;
        let tip = (k1 * Dd::from(fz) - k2 * Dd::from(fx)) / k3;
        let bound = 16.0 * U * (1.0 + mu).powi(2) / k3.hi().abs();
        assert!(
            rel(f.edge, edge) <= bound,
            "ε=1e-{k}: edge {} vs {edge}",
            f.edge
        );
        assert!(rel(f.tip, tip) <= bound, "ε=1e-{k}: tip {} vs {tip}", f.tip);
        assert!(k_factors(mu, theta).2.is_finite());
    }
}

/// Force ratio on the edge of the jamming parallelogram: the jam/no-jam
/// verdict flips there, so the margin must be zero to rounding on every
/// edge, finite everywhere, and a step of 1e-9 (in ratio units) inwards or
/// outwards must classify as inside or outside — for small and large
/// clearances, both friction levels and shallow to deep insertions, with
/// the exact (finite-angle) and Whitney's parallelograms alike.
#[test]
fn force_ratio_on_the_parallelogram_edge() {
    use pegdyn::jamming::diagram::{exact_parallelogram, whitney_parallelogram};
    for (c, mu) in [(1e-6, 0.1), (0.002, 0.1), (0.01, 0.3)] {
        let peg = PegHole::try_new(0.0125, c, mu).unwrap();
        for l in [0.001, 0.005, 0.05] {
            let mut shapes = vec![whitney_parallelogram(&peg, l).unwrap()];
            shapes.extend(exact_parallelogram(&peg, l).unwrap());
            for g in shapes {
                let centre = g
                    .corners
                    .iter()
                    .fold([0.0, 0.0], |s, q| [s[0] + 0.25 * q[0], s[1] + 0.25 * q[1]]);
                for (a, b) in g.edges() {
                    let scale = a[0].abs().max(a[1].abs()).max(b[0].abs()).max(b[1].abs());
                    for s in [0.0, 0.25, 0.5, 1.0] {
                        let on = [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])];
                        let m = g.margin(on);
                        assert!(
                            m.is_finite() && m.abs() <= 1e-14 * scale,
                            "c = {c}, mu = {mu}, l = {l}: margin {m:e} on an edge"
                        );
                        let (dx, dy) = (centre[0] - on[0], centre[1] - on[1]);
                        let n = dx.hypot(dy);
                        let step = |k: f64| [on[0] + k * 1e-9 * dx / n, on[1] + k * 1e-9 * dy / n];
                        if s > 0.0 && s < 1.0 {
                            assert!(g.avoids_jamming(step(1.0)), "inward step must be inside");
                        }
                        assert!(
                            !g.avoids_jamming(step(-1.0)),
                            "outward step must be outside"
                        );
                    }
                }
            }
        }
    }
}
