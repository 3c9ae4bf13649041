//! The quasi-static limit of a robot insertion: in two-point contact (the
//! mouth edge on the peg's side, the rim on the bore wall) a slow descent's
//! contact forces satisfy the static sliding equilibrium of the jamming
//! analysis (`pegdyn::jamming::forces::sliding_contact_forces`, exact in
//! the tilt) under the wrist's force and gravity, at every depth, to a
//! tolerance that shrinks as the descent slows.

use crate::common::rcc;
use nalgebra::Vector3;
use pegdyn::compliant_peg_3d::Pair;
use pegdyn::jamming::forces::sliding_contact_forces;
use pegdyn::jamming::params::PegHole;

/// Largest relative deviation of the simulated edge and tip forces from
/// the static ones over the two-point samples, and their number.
fn deviation(speed: f64) -> (f64, usize) {
    let text = include_str!("../../scenes/insert_rcc.toml")
        // The cases assume the tip starting 2 mm in the bore.
        .replace("start_height = 1e-3 ", "start_height = -2e-3 ")
        .replace("speed = 0.01 ", &format!("speed = {speed} "))
        .replace("t_end = 1.2 ", "t_end = 10.0 ")
        // Friction's regularization scale well below both speeds, so that
        // what remains is the dynamic error.
        .replace("slip_velocity = 1e-3 ", "slip_velocity = 1e-4 ")
        .replace(
            "output_interval = 1e-3 ",
            &format!("output_interval = {} ", 2e-5 / speed),
        );
    let (scene, built, run) = rcc::run(&text);
    assert_eq!(run.outcome.name(), "seated");
    let prm = built.params;
    let hole = PegHole::try_new(prm.peg_radius(), scene.peg.clearance_ratio, prm.friction).unwrap();
    let (mut worst, mut n) = (0.0_f64, 0);
    for (&t, y) in run.solution.t.iter().zip(&run.solution.x) {
        let s = run.system.sample(t, y).unwrap();
        let edge = s
            .forces
            .iter()
            .filter(|f| f.contact.pair == Pair::EdgeSide)
            .collect::<Vec<_>>();
        let tip = s
            .forces
            .iter()
            .filter(|f| f.contact.pair == Pair::RimWall)
            .collect::<Vec<_>>();
        if edge.len() != 1 || tip.len() != 1 || s.depth < 0.0055 {
            continue;
        }
        let (e, k) = (edge[0], tip[0]);
        let mut h = e.contact.point - k.contact.point;
        h.z = 0.0;
        let h = h.normalize();
        let w = s.wrist.unwrap();
        let applied = w.force - Vector3::z() * (prm.mass * prm.gravity);
        let f = sliding_contact_forces(&hole, s.tilt, applied.dot(&h), -applied.z);
        let scale = f.edge.abs().max(f.tip.abs());
        let dev = ((e.normal_force - f.edge).abs()).max((k.normal_force - f.tip).abs()) / scale;
        worst = worst.max(dev);
        n += 1;
    }
    (worst, n)
}

#[test]
fn slow_two_point_descent_meets_the_static_sliding_equilibrium() {
    let (fast, n_fast) = deviation(0.02);
    let (slow, n_slow) = deviation(0.005);
    assert!(n_fast > 20 && n_slow > 20, "{n_fast} {n_slow}");
    assert!(slow < 1e-3, "slow {slow}");
    assert!(slow < 0.5 * fast, "slow {slow} fast {fast}");
}

#[test]
fn one_point_contact_deflects_the_wrist_by_the_error_less_the_clearance() {
    // The shipped insertion rides the bore wall on its rim between 2 and
    // 4.9 mm. The rim's outermost point towards the wall lies
    // x_reach = (r − ρ_p) cos θ − ρ_p sin θ + ρ_p from the tip's centre
    // (tilt θ away from the wall), so the tip sits at R − x_reach + δ and the
    // wrist (compliance centre at the tip, robot at lateral error e) is
    // deflected by d_x = R − x_reach + δ − e, δ = (Q/k)^(2/3).
    let text = include_str!("../../scenes/insert_rcc.toml")
        // The cases assume the tip starting 2 mm in the bore.
        .replace("start_height = 1e-3 ", "start_height = -2e-3 ")
        .replace("seat_depth = 0.008 ", "seat_depth = 0.0045 ");
    let (scene, built, run) = rcc::run(&text);
    let prm = built.params;
    let k = scene.peg.contact_stiffness.unwrap();
    let e = scene.robot.lateral_error;
    let (r, rho) = (prm.peg_radius(), prm.rim_fillet);
    let mut n = 0;
    for (&t, y) in run.solution.t.iter().zip(&run.solution.x) {
        let s = run.system.sample(t, y).unwrap();
        if s.depth < 0.003 || s.forces.len() != 1 || s.forces[0].contact.pair != Pair::RimWall {
            continue;
        }
        let q = s.forces[0].normal_force;
        let th = s.tilt;
        let reach = (r - rho) * th.cos() - rho * th.sin() + rho;
        let predicted = prm.bore_radius() - reach + (q / k).powf(2.0 / 3.0) - e;
        let dx = s.wrist.unwrap().deflection.x;
        assert!(
            (dx - predicted).abs() < 2e-3 * predicted.abs(),
            "{dx} vs {predicted} at {t}"
        );
        n += 1;
    }
    assert!(n > 50, "{n} one-point samples");
}
