//! The compliant 3-D peg's energy balance over a run with many contact
//! changes: a tilted, spinning peg released inside the bore with a lateral
//! velocity rattles between the mouth edge (pair `edge_side`) and the bore
//! wall (`rim_wall`) on alternating sides while it sinks under gravity and
//! constant applied loads. (`tests/compliant_peg_3d.rs` checks the balance
//! for a landing on the top face, one contact.)

use nalgebra::{SVector, UnitQuaternion, Vector3};
use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, PegState};
use pegdyn::compliant_peg_3d::{HertzMode, Pair, Peg3d, Peg3dParams, pose_state};
use pegdyn::integrate::{Method, Options, solve};

/// The Fig. 9 peg (D = 50 mm, d = 49.95 mm, L = 70 mm), 1 mm fillets,
/// fixed stiffness (the contact potential is then exact), applied force and
/// moment.
fn params(friction: f64, damping: f64) -> Peg3dParams {
    let mut prm = Peg3dParams::steel(0.04995, 0.070, 0.050, 1e-3, 1e-3, 0.1);
    prm.hertz = HertzMode::Fixed(2e9);
    prm.force = Vector3::new(0.3, -0.2, -2.0);
    prm.moment = Vector3::new(0.002, 0.001, 0.0);
    prm.friction = friction;
    prm.damping = damping;
    prm
}

/// The Fig. 9 peg in the compliant planar peg's two-point lean at tilt
/// 0.01 rad (left mouth edge on the peg's side, right bore wall on its rim,
/// both just touching; bottom face about 5 mm deep), then kicked: away from
/// the wall at 1 cm/s, out of the plane at 2 mm/s, down at 2 cm/s, spinning
/// about its axis at 20 1/s.
fn start(prm: &Peg3dParams) -> SVector<f64, 15> {
    let mut spec = CompliantSpec::steel_cylinder(
        prm.hole_diameter,
        1.0 - prm.peg_diameter / prm.hole_diameter,
        prm.length,
        0.0,
    );
    spec.geometry.peg_fillet = prm.rim_fillet;
    spec.geometry.hole_fillet = prm.mouth_fillet;
    let planar = CompliantParams::try_new(spec).unwrap();
    let s = PegState::two_point(&planar, 0.01, 0.0).unwrap();
    // Planar (x, z into the hole, θ) to 3-D: p = (x, 0, −z), tilt −θ about e_y.
    pose_state(
        Vector3::new(s.x, 0.0, -s.z),
        UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -s.theta),
        Vector3::new(-0.01, 0.002, -0.02),
        Vector3::new(0.0, 0.0, 20.0),
    )
}

/// The run over 20 ms at rtol 1e-11: every step's balance minus the
/// initial one (largest |·|), the number of changes of the set of touching
/// pairs, the pairs seen, the dissipation at every step, the steps.
fn rattle(prm: Peg3dParams) -> (f64, usize, Vec<Pair>, Vec<f64>, usize) {
    let sys = Peg3d::new(prm);
    let y0 = start(&prm);
    let e0 = sys.energy_balance(&y0).unwrap();
    let sol = solve(
        &sys,
        Method::Dopri5,
        (0.0, y0),
        0.02,
        &Options::with_tolerances(1e-11, 1e-13),
    )
    .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    let mut worst: f64 = 0.0;
    let mut changes = 0;
    let mut last: Vec<(Pair, bool)> = Vec::new();
    let mut seen = Vec::new();
    let mut dissipation = Vec::new();
    for y in &sol.x {
        let e = sys.energy_balance(y).unwrap();
        worst = worst.max((e - e0).abs());
        // The touching pairs and on which side of the bore (sign of the
        // contact point along the initial lateral velocity).
        let mut now: Vec<(Pair, bool)> = sys
            .contacts(y)
            .iter()
            .map(|c| (c.pair, c.point.x + 0.5 * c.point.y > 0.0))
            .collect();
        now.sort_by_key(|(p, s)| (p.name(), *s));
        now.dedup();
        if now != last {
            changes += 1;
        }
        for (p, _) in &now {
            if !seen.contains(p) {
                seen.push(*p);
            }
        }
        last = now;
        dissipation.push(y[14]);
    }
    (worst, changes, seen, dissipation, sol.stats.steps)
}

#[test]
fn energy_frictionless_undamped_rattle_keeps_the_balance_over_many_contact_changes() {
    let (worst, changes, seen, _, steps) = rattle(params(0.0, 0.0));
    eprintln!(
        "frictionless rattle: {changes} contact changes ({seen:?}), {steps} steps, balance drift {worst:.2e} J"
    );
    assert!(changes >= 10, "only {changes} contact changes");
    assert!(seen.contains(&Pair::EdgeSide) && seen.contains(&Pair::RimWall));
    // Kinetic energy ≈ 0.07 J (mostly the spin); measured drift 1.1e-13 J.
    assert!(worst < 1e-10, "energy balance drifts by {worst} J");
}

#[test]
fn energy_rattle_with_friction_and_damping_closes_with_non_negative_dissipation() {
    let (worst, changes, _, s, steps) = rattle(params(0.2, 0.5));
    let total = *s.last().unwrap();
    eprintln!(
        "dissipative rattle: {changes} contact changes, {steps} steps, dissipated {total:.3e} J, balance drift {worst:.2e} J"
    );
    assert!(changes >= 10, "only {changes} contact changes");
    for w in s.windows(2) {
        assert!(
            w[1] >= w[0] - 1e-15,
            "dissipation decreased: {} -> {}",
            w[0],
            w[1]
        );
    }
    assert!(total > 1e-2, "dissipated only {total} J");
    assert!(worst < 1e-10, "energy balance drifts by {worst} J");
}
