//! The compliant 3-D peg against the quasi-static two-point analysis of
//! jamming (`pegdyn::jamming`): confined to the plane (the setup of
//! `tests/compliant_peg_3d/limits_planar.rs`: loads fixed in the peg's
//! frame applied through the wrench input, no gravity, one fixed Hertz
//! stiffness), its contact forces while sliding in two-point contact under
//! loads on the two-point sliding line approach the quasi-static solution
//! (paper Eq. 52), and its jam/insert outcomes on a coarse grid of load
//! ratios agree with the exact parallelogram.

use crate::common::peg3d;

use nalgebra::{SVector, UnitQuaternion, Vector3};
use peg3d::{Follower, pair_forces};
use pegdyn::compliant_peg::{Load, PegState};
use pegdyn::compliant_peg_3d::{HertzMode, Peg3d, Peg3dParams, pose_state};
use pegdyn::integrate::{Direction, Event, Method, Options, OutputMode, Solver, StopReason, solve};
use pegdyn::jamming::dynamic::{SweepSetup, SweepSpec};
use pegdyn::jamming::forces::{Wrench, to_paper_frame};
use pegdyn::jamming::quasi_static::{PaperPeg, PegAcc, PegLoad};

/// The planar state as a 3-D state (see the planar limit test).
fn to_3d(s: &PegState) -> SVector<f64, 15> {
    pose_state(
        Vector3::new(s.x, 0.0, -s.z),
        UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -s.theta),
        Vector3::new(s.xdot, 0.0, -s.zdot),
        Vector3::new(0.0, -s.thetadot, 0.0),
    )
}

/// The jamming scene's sweep peg: r = 12.5 mm, c = 0.01, μ = 0.3, two-point
/// contact at depth l = 10 mm, steel, L = 0.1 m.
fn setup() -> SweepSetup {
    SweepSetup::new(SweepSpec {
        t_max: 0.05,
        integrator: Method::Dopri5,
        ..SweepSpec::reference()
    })
    .unwrap()
}

/// The 3-D peg of `setup` under `load`, with friction velocity scale `v_s`
/// and Hunt–Crossley damping `alpha`.
fn follower(s: &SweepSetup, load: Load, v_s: f64, alpha: f64) -> Follower {
    let spec = &s.params.spec;
    let g = &spec.geometry;
    let mut prm = Peg3dParams::steel(
        2.0 * g.peg_radius,
        s.spec.peg_length,
        g.hole_diameter,
        g.peg_fillet,
        g.hole_fillet,
        0.2,
    );
    prm.gravity = 0.0;
    prm.friction = spec.friction;
    prm.slip_scale = v_s;
    prm.damping = alpha;
    prm.hertz = HertzMode::Fixed(s.params.pair.edge.stiffness());
    Follower {
        peg: Peg3d::new(prm),
        load,
    }
}

#[test]
fn statics_two_point_sliding_forces_approach_the_quasi_static_solution() {
    let s = setup();
    let spec = &s.params.spec;
    let paper = PaperPeg {
        theta: s.theta,
        mu: spec.friction,
        r: spec.geometry.peg_radius,
        l: s.depth,
        l_c: spec.com_height,
        m: spec.mass,
        j: spec.inertia,
    };
    for f2 in [0.0, 2.0] {
        let u = PegLoad { f1: 20.0, f2 };
        let qs = paper.two_point(u, PegAcc::default());
        let load = Load {
            axial: u.f1,
            radial: u.f2,
            torque: qs.m,
        };
        let sys = follower(&s, load, 1e-5, 20.0);
        // Preloaded: both contacts at the penetration of the mean
        // quasi-static force.
        let k = s.params.pair.edge.stiffness();
        let delta = (0.5 * (qs.f_a + qs.f_b) / k).powf(2.0 / 3.0);
        let start = PegState::two_point(&s.params, s.theta, delta).unwrap();
        let t_end = 0.01;
        let times: Vec<f64> = (0..=10).map(|i| t_end * i as f64 / 10.0).collect();
        let mut opts = Options::with_tolerances(1e-9, 1e-14);
        opts.output = OutputMode::AtTimes(times);
        let sol = solve(&sys, Method::Dopri5, (0.0, to_3d(&start)), t_end, &opts).unwrap();
        assert!(sol.stop.is_success());
        let speed = |y: &SVector<f64, 15>| Vector3::new(y[7], y[8], y[9]).norm();
        let (mid, last) = (&sol.x[5], &sol.x[10]);
        let drift = (speed(last) - speed(mid)).abs() / speed(last);
        let mut worst: f64 = 0.0;
        for (t, y) in sol.t.iter().zip(&sol.x) {
            let (edge, wall) = pair_forces(&sys.peg, y);
            // The regularized law's friction ratio |F_t|/Q at the sliding
            // speed, averaged over the two contacts.
            let forces = sys.peg.forces(y).unwrap();
            let mu_eff = forces
                .iter()
                .map(|f| f.friction.norm() / f.normal_force)
                .sum::<f64>()
                / forces.len() as f64;
            let eff = PaperPeg {
                mu: mu_eff,
                ..paper
            }
            .two_point(u, PegAcc::default());
            eprintln!(
                "f2 = {f2}: t {t:.4} edge {edge:.5} (μ: {:.5}, μ_eff: {:.5}) wall {wall:.5} (μ: {:.5}, μ_eff: {:.5}) μ_eff {mu_eff:.5} v {:.2e} m/s",
                qs.f_a,
                eff.f_a,
                qs.f_b,
                eff.f_b,
                Vector3::new(y[7], y[8], y[9]).norm(),
            );
            if *t >= 0.005 {
                worst = worst
                    .max((edge - eff.f_a).abs() / eff.f_a)
                    .max((wall - eff.f_b).abs() / eff.f_b);
            }
        }
        eprintln!(
            "f2 = {f2}: steady sliding at {:.2e} m/s (speed drift {drift:.1e} over 5 ms), forces within {worst:.1e} of Eq. 52 at the friction ratio of the sliding speed",
            speed(last)
        );
        // Quasi-static: steady sliding (no acceleration), faster than v_s
        // so friction is near its limit, and the contact forces those of
        // the two-point solution with that friction ratio.
        assert!(drift < 0.01, "not steady: {drift}");
        assert!(speed(last) > 3.0 * 1e-5, "creeping at {}", speed(last));
        assert!(worst < 3e-4, "forces differ by {worst} relative");
    }
}

/// Outcome of one 3-D run under the Whitney load ratio `q` for the lean of
/// the start state (`mirror`: the point-reflected load, the other lean's
/// problem): inserted when the bottom face advances 1 mm within 50 ms.
fn inserted(s: &SweepSetup, q: [f64; 2], mirror: bool) -> bool {
    let sign = if mirror { -1.0 } else { 1.0 };
    let fz = s.spec.fz;
    let w = Wrench {
        fx: sign * q[0] * fz,
        fz,
        m: sign * q[1] * s.spec.peg.r() * fz,
    };
    let (f1, f2, m_c) = to_paper_frame(&w, s.theta, s.params.spec.com_height);
    let sys = follower(
        s,
        Load {
            axial: f1,
            radial: f2,
            torque: m_c,
        },
        1e-3,
        20.0,
    );
    let half_l = 0.5 * s.spec.peg_length;
    let depth = move |y: &SVector<f64, 15>| {
        let a_z = 1.0 - 2.0 * (y[4] * y[4] + y[5] * y[5]) / y.fixed_rows::<4>(3).norm_squared();
        -y[2] + half_l * a_z
    };
    let y0 = to_3d(&s.start);
    let target = depth(&y0) + s.spec.advance;
    let mut opts = Options::with_tolerances(1e-6, 1e-12);
    opts.store = false;
    let mut solver = Solver::new(Method::Dopri5, opts).with_event(
        Event::new(move |_, y: &SVector<f64, 15>| depth(y) - target)
            .direction(Direction::Rising)
            .terminal(),
    );
    let sol = solver.solve(&sys, 0.0, y0, s.spec.t_max).unwrap();
    match sol.stop {
        StopReason::Event { .. } => true,
        StopReason::ReachedEnd => false,
        other => panic!("q = {q:?}: {other:?}"),
    }
}

#[test]
fn statics_jam_or_insert_agrees_with_the_exact_parallelogram_on_a_coarse_grid() {
    let s = setup();
    let (mut agree, mut total, mut inserts) = (0, 0, 0);
    for qx in [-1.0, 0.0, 1.0] {
        for qy in [-3.0, 0.0, 3.0] {
            let q = [qx, qy];
            let margin = s.diagram.margin(q);
            let t0 = std::time::Instant::now();
            let three_d = inserted(&s, q, false) && inserted(&s, q, true);
            let expect = s.diagram.avoids_jamming(q);
            eprintln!(
                "q = {q:?}: margin {margin:.3}, parallelogram {}, 3-D {} ({:?})",
                if expect { "inserts" } else { "jams" },
                if three_d { "inserts" } else { "jams" },
                t0.elapsed()
            );
            total += 1;
            agree += usize::from(three_d == expect);
            inserts += usize::from(three_d);
        }
    }
    assert_eq!(agree, total);
    assert_eq!(inserts, 3);
}
