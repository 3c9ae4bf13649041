//! The exact Jacobian of the compliant 3-D peg (generated partial
//! derivatives and the chain rule through the contact wrench) against
//! central finite differences of the right-hand side, at contact states of
//! every pair, with damping, friction, spin and a subtracted col.

use crate::common::peg3d;

use nalgebra::{SMatrix, SVector, UnitQuaternion, Vector3};
use peg3d::orientation;
use pegdyn::compliant_peg_3d::{HertzMode, Pair, Peg3d, Peg3dParams, pose_state};
use pegdyn::integrate::{Method, Options, solve};
use pegdyn::system::OdeSystem;

fn fig9() -> Peg3dParams {
    let mut p = peg3d::fig9();
    p.hertz = HertzMode::Fixed(2e10);
    p
}

/// Central differences of the right-hand side, steps 1e-8 in the pose
/// (m, quaternion components) and 1e-7 in the velocities and energies.
fn central(sys: &Peg3d, y: &SVector<f64, 15>) -> SMatrix<f64, 15, 15> {
    let mut j = SMatrix::<f64, 15, 15>::zeros();
    for c in 0..15 {
        let h = if c < 7 { 1e-8 } else { 1e-7 };
        let (mut a, mut b) = (*y, *y);
        a[c] += h;
        b[c] -= h;
        let col = (sys.rhs(0.0, &a) - sys.rhs(0.0, &b)) / (2.0 * h);
        j.set_column(c, &col);
    }
    j
}

/// Compares column by column: the difference is below 1e-5 of the
/// column's size plus 1e-7 of the largest column (the contact search
/// converges the angle to round-off, and its noise divided by the step
/// is the floor of the differences).
fn check(sys: &Peg3d, y: &SVector<f64, 15>, what: &str) -> f64 {
    let exact = sys.jacobian(0.0, y);
    let fd = central(sys, y);
    let big = (0..15).map(|c| exact.column(c).norm()).fold(0.0, f64::max);
    let errs: Vec<f64> = (0..15)
        .map(|c| {
            let (e, f) = (exact.column(c), fd.column(c));
            (e - f).norm() / (e.norm() + 1e-2 * big)
        })
        .collect();
    let worst = errs.iter().cloned().fold(0.0, f64::max);
    assert!(worst < 1e-5, "{what}: relative column errors {errs:?}");
    worst
}

#[test]
fn exact_jacobian_matches_central_differences_at_contact_states() {
    let mut prm = fig9();
    prm.friction = 0.3;
    prm.damping = 0.4;
    prm.slip_scale = 1e-3;
    prm.force = Vector3::new(0.5, 0.0, -2.0);
    prm.moment = Vector3::new(0.0, 0.01, 0.0);
    let sys = Peg3d::new(prm);
    let moving = |p: Vector3<f64>, q: UnitQuaternion<f64>| {
        pose_state(
            p,
            q,
            Vector3::new(0.01, -0.02, -0.05),
            Vector3::new(1.0, -2.0, 15.0),
        )
    };
    let mut states = Vec::new();
    // Two-point contact: the axis tilted by 2 mrad towards +x through the
    // bore's centre 20 mm below the top face, the mouth edge on the side at
    // +x (about 13 µm) and the rim on the wall at −x (about 43 µm).
    states.push((
        "edge_side + rim_wall",
        moving(Vector3::new(0.0, 0.0, -0.02), orientation(2e-3, 0.0, 0.3)),
    ));
    // Tilted rim 10 µm into the top face.
    let q = orientation(0.3, 0.7, 1.1);
    let rr = prm.peg_radius() - prm.rim_fillet;
    let (ex, ey, a) = (q * Vector3::x(), q * Vector3::y(), q * Vector3::z());
    let lowest = (prm.rim_fillet - 0.5 * prm.length) * a.z - rr * ex.z.hypot(ey.z);
    states.push((
        "rim_top",
        moving(
            Vector3::new(0.08, -0.01, prm.rim_fillet - 10e-6 - lowest),
            q,
        ),
    ));
    // Rim on the mouth fillet, two points sharing a col.
    let (rho_p, rho_h) = (prm.rim_fillet, prm.mouth_fillet);
    let dist = rho_p + rho_h - 10e-6;
    let centre = Vector3::new(
        prm.bore_radius() + rho_h - dist * 0.5_f64.sin(),
        0.0,
        -rho_h + dist * 0.5_f64.cos(),
    );
    for gamma in [0.02, 0.03] {
        let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -gamma);
        let p = centre - q * Vector3::new(rr, 0.0, rho_p - 0.5 * prm.length);
        states.push(("rim_edge", moving(p, q)));
    }
    let mut seen = std::collections::HashSet::new();
    let mut cols = 0;
    for (what, y) in &states {
        let f = sys.forces(y).unwrap();
        assert!(!f.is_empty(), "{what}: no contact");
        for c in &f {
            seen.insert(c.contact.pair);
            cols += usize::from(c.contact.saddle.is_some());
        }
        let worst = check(&sys, y, what);
        eprintln!(
            "{what}: {} contacts, worst column error {worst:.2e}",
            f.len()
        );
    }
    for pair in [Pair::EdgeSide, Pair::RimWall, Pair::RimTop, Pair::RimEdge] {
        assert!(seen.contains(&pair), "{pair:?} not met");
    }
    assert!(cols > 0, "no subtracted col");
}

#[test]
fn rodas4_with_the_exact_jacobian_lands_like_dopri5() {
    // The frictionless landing on the top face integrated by RODAS4 (which
    // uses the exact Jacobian) and by Dormand–Prince 5(4): the end states
    // agree to the tolerance.
    let prm = fig9();
    let sys = Peg3d::new(prm);
    let q = orientation(0.2, 0.3, 0.0);
    let rr = prm.peg_radius() - prm.rim_fillet;
    let (ex, ey, a) = (q * Vector3::x(), q * Vector3::y(), q * Vector3::z());
    let lowest = (prm.rim_fillet - 0.5 * prm.length) * a.z - rr * ex.z.hypot(ey.z);
    let y0 = pose_state(
        Vector3::new(0.07, 0.01, 1e-5 + prm.rim_fillet - lowest),
        q,
        Vector3::new(0.01, 0.0, -0.1),
        Vector3::new(0.0, 0.0, 5.0),
    );
    let opts = Options::with_tolerances(1e-8, 1e-11);
    let end = 2e-3;
    let r4 = solve(&sys, Method::Rodas4, (0.0, y0), end, &opts).unwrap();
    let dp = solve(&sys, Method::Dopri5, (0.0, y0), end, &opts).unwrap();
    assert!(r4.stop.is_success() && dp.stop.is_success());
    let (a, b) = (r4.x.last().unwrap(), dp.x.last().unwrap());
    eprintln!(
        "RODAS4 {} steps, DOPRI5 {} steps, end-state difference {:.2e}",
        r4.x.len(),
        dp.x.len(),
        (a - b).norm()
    );
    assert!((a - b).norm() < 1e-6, "{a} vs {b}");
    assert!(
        r4.x.iter().any(|y| !sys.contacts(y).is_empty()),
        "never touched"
    );
}

#[test]
fn the_prescribed_peg_s_jacobian_and_time_derivative_match_central_differences() {
    // The Fig. 9 motion preloaded with the rigid reactions (three points:
    // K on the side, B1 and B2 on the mouth), aligning and precessing.
    use crate::common::prescribed_rigid::{GAMMADOT, params, preloaded_state};
    use pegdyn::compliant_peg_3d::prescribed::{Motion, PrescribedPeg};
    use pegdyn::rigid_peg::prescribed::reactions;
    use pegdyn::rigid_peg::{Loads, PegParams};
    let rigid = PegParams::fig9();
    let k = 2.4e10;
    let motion = Motion {
        gamma: 0.2,
        gammadot: GAMMADOT,
        psi: 0.3,
        psidot: 10.0,
    };
    let sys = PrescribedPeg::try_new(params(&rigid, k), motion).unwrap();
    let normal = reactions(
        &rigid,
        &Loads::default(),
        nalgebra::Vector2::new(motion.gamma, motion.psi),
        nalgebra::Vector2::new(GAMMADOT, motion.psidot),
        nalgebra::Vector2::zeros(),
    )
    .unwrap()
    .normal;
    let y = preloaded_state(&sys, &rigid, normal, k);
    let t = 0.0;
    assert_eq!(sys.forces(t, &y).unwrap().len(), 3, "three contacts");
    let _ = sys.rhs(t, &y);
    let exact = sys.jacobian(t, &y);
    let big = (0..7).map(|c| exact.column(c).norm()).fold(0.0, f64::max);
    for c in 0..7 {
        let h = if c < 3 { 1e-10 } else { 1e-7 };
        let (mut a, mut b) = (y, y);
        a[c] += h;
        b[c] -= h;
        let fd = (sys.rhs(t, &a) - sys.rhs(t, &b)) / (2.0 * h);
        let err = (fd - exact.column(c)).norm() / (exact.column(c).norm() + 1e-2 * big);
        assert!(
            err < 1e-5,
            "column {c}: {err:.2e}\n{}\n{fd}",
            exact.column(c)
        );
    }
    let dt = 1e-8;
    let fd = (sys.rhs(t + dt, &y) - sys.rhs(t - dt, &y)) / (2.0 * dt);
    let exact = sys.time_derivative(t, &y);
    let err = (fd - exact).norm() / exact.norm();
    assert!(err < 1e-5, "time derivative: {err:.2e}\n{exact}\n{fd}");
}
