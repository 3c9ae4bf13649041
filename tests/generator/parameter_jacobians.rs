//! The generated parameter Jacobians against Richardson-extrapolated
//! central differences (in double-double) of the generated functions they
//! differentiate, to 1e-8 relative per parameter column, at random points: the compliant planar peg's `rhs_p` (∂f/∂p of `rhs`) in
//! two-point contact, sliding, and the rigid three-point peg's `forward_p`
//! (∂(b − A u)/∂p of `forward`'s linear system, so that A ∂u/∂p = it).

use nalgebra::{SMatrix, SVector};
use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, Load, PegState};
use pegdyn::generated::{compliant_peg, rigid_peg};
use pegdyn::rigid_peg::PegParams;
use pegdyn::scalar::{Dd, Real};

use crate::common::Rng;
use crate::common::rigid::loads;

/// `∂f/∂p_k` by central differences at steps `h` and `h/2`, extrapolated
/// (error O(h⁴)), evaluated in double-double so that rounding (about 1e-32
/// relative) does not limit the differences.
fn richardson<const R: usize, const Q: usize>(
    f: impl Fn(&SVector<Dd, Q>) -> SVector<Dd, R>,
    p: &SVector<f64, Q>,
    k: usize,
    h: f64,
) -> SVector<f64, R> {
    let central = |h: f64| {
        let hd = Dd::from_f64(h);
        let at = |sign: f64| {
            let mut q: SVector<Dd, Q> = SVector::from_fn(|i, _| Dd::from_f64(p[i]));
            q[k] = q[k] + Dd::from_f64(sign) * hd;
            f(&q)
        };
        let (a, b) = (at(1.0), at(-1.0));
        SVector::<Dd, R>::from_fn(|i, _| (a[i] - b[i]) / (Dd::from_f64(2.0) * hd))
    };
    let (d1, d2) = (central(h), central(0.5 * h));
    SVector::from_fn(|i, _| ((Dd::from_f64(4.0) * d2[i] - d1[i]) / Dd::from_f64(3.0)).to_f64())
}

/// Column by column: `|exact − fd| ≤ 1e-8 · max |column|` (a zero column
/// must be zero by differences too).
fn assert_columns<const R: usize, const Q: usize>(
    exact: &SMatrix<f64, R, Q>,
    fd: impl Fn(usize) -> SVector<f64, R>,
    names: &[&str],
    context: &str,
) {
    for (k, name) in names.iter().enumerate().take(Q) {
        let (e, d) = (exact.column(k), fd(k));
        let scale = e.amax().max(d.amax());
        let err = (e - d).amax();
        assert!(
            err <= 1e-8 * scale || scale == 0.0,
            "{context}: column `{name}`: |exact − fd| = {err:e}, scale {scale:e}\nfd {d:?}"
        );
    }
}

#[test]
fn compliant_rhs_p_matches_differences_of_rhs_in_sliding_two_point_contact() {
    let mut spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.3);
    spec.slip_velocity = 1e-3;
    spec.damping = 0.2;
    let params = CompliantParams::try_new(spec).unwrap();
    let load = Load {
        axial: 20.0,
        radial: 2.0,
        torque: -0.3,
    };
    let p = params.vector(&load);
    let mut rng = Rng(7);
    let mut checked = 0;
    while checked < 12 {
        let theta = rng.uniform(0.002, 0.01);
        let pen = rng.uniform(1.5e-5, 4e-5);
        let mut y = PegState::two_point(&params, theta, pen)
            .unwrap()
            .to_vector();
        // Sliding velocities of either sign, of the order of v_s.
        y[3] = rng.uniform(-2e-3, 2e-3);
        y[4] = rng.uniform(-2e-3, 2e-3);
        y[5] = rng.uniform(-0.1, 0.1);
        // Skip points within reach of a kink (a contact at δ = 0 or the
        // damping factor's max(0, ·)) of the differences' steps.
        let c = compliant_peg::contacts(&y, &p);
        if c.delta.iter().any(|d| d.abs() < 1e-5) {
            continue;
        }
        checked += 1;
        let exact = compliant_peg::rhs_p(&y, &p);
        // Small steps for the dimensions (which move the penetrations, so
        // the steps must stay far inside the contacts' smooth range), larger
        // ones for the rest (against rounding).
        let geometric = ["r", "l_c", "D", "rho_p", "rho_h"];
        let fd = |k: usize| {
            let rel = if geometric.contains(&compliant_peg::P_NAMES[k]) {
                1e-6
            } else {
                1e-3
            };
            let h = rel * p[k].abs().max(1e-3);
            let yd = y.map(Dd::from_f64);
            richardson(|q| compliant_peg::rhs(&yd, q), &p, k, h)
        };
        assert_columns(
            &exact,
            fd,
            &compliant_peg::P_NAMES,
            &format!("point {checked}"),
        );
    }
}

#[test]
fn rigid_forward_p_gives_the_sensitivity_of_accelerations_and_reactions() {
    let peg = PegParams {
        friction: 0.2,
        ..PegParams::fig9()
    };
    let (p, l) = (peg.to_vector(), loads().to_vector());
    let mut rng = Rng(11);
    for point in 0..10 {
        let gamma = peg.gamma0() * (1.0 + rng.uniform(0.05, 0.5));
        let x = SVector::<f64, 4>::new(
            gamma,
            rng.uniform(-1.0, 1.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
        );
        let mut t = rng.vector::<9>(-1.0, 1.0);
        t /= t.norm();
        let sys = rigid_peg::forward(&x, &p, &l, &t);
        let u = sys.a.lu().solve(&sys.b).unwrap();
        let exact = sys
            .a
            .lu()
            .solve(&rigid_peg::forward_p(&x, &u, &p, &l, &t))
            .unwrap();
        // ∂u/∂p = A⁻¹ ∂(b − A u)/∂p: the differences of the residual at the
        // fixed solution u, solved with the same A.
        let (xd, ld, td, ud) = (
            x.map(Dd::from_f64),
            l.map(Dd::from_f64),
            t.map(Dd::from_f64),
            u.map(Dd::from_f64),
        );
        let residual = |q: &SVector<Dd, 7>| {
            let s = rigid_peg::forward(&xd, q, &ld, &td);
            SVector::<Dd, 5>::from_fn(|i, _| {
                (0..5).fold(s.b[i], |acc, j| acc - s.a[(i, j)] * ud[j])
            })
        };
        let fd = |k: usize| {
            let r = richardson(residual, &p, k, 1e-4 * p[k].abs().max(1e-3));
            sys.a.lu().solve(&r).unwrap()
        };
        assert_columns(&exact, fd, &rigid_peg::P_NAMES, &format!("point {point}"));
    }
}
