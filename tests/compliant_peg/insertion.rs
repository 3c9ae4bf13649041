//! Insertion runs of the compliant peg (`simulate_insertion`): a centred,
//! upright peg pushed axially slides in without any contact force; a peg
//! pressed sideways against the wall with an axial force inside the friction
//! cone jams, and the creep of the regularized friction law shrinks in
//! proportion to its velocity scale `v_s`.

use nalgebra::SVector;
use pegdyn::compliant_peg::{
    CompliantParams, CompliantSpec, CompliantSystem, InsertionOptions, InsertionOutcome, Load,
    PegState, simulate_insertion,
};
use pegdyn::integrate::{Method, Options, OutputMode, Solver};

fn params(mu: f64, v_s: f64) -> CompliantParams {
    let mut spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, mu);
    spec.slip_velocity = v_s;
    CompliantParams::try_new(spec).unwrap()
}

#[test]
fn pure_axial_push_inserts_a_centred_peg_without_contact_force() {
    let p = params(0.1, 1e-5);
    let load = Load {
        axial: 10.0,
        radial: 0.0,
        torque: 0.0,
    };
    let start = PegState::centred(&p, 0.005);
    let opts = InsertionOptions {
        target_depth: 0.015,
        ..InsertionOptions::default()
    };
    let run = simulate_insertion(&p, &load, &start, &opts).unwrap();
    // Free flight: Δ = ½ (f₁/m) t².
    let t_free = (2.0 * 0.010 * p.spec.mass / 10.0).sqrt();
    let InsertionOutcome::Inserted { t } = run.outcome else {
        panic!("{:?}", run.outcome)
    };
    assert!(
        (t - t_free).abs() < 1e-6 * t_free,
        "t = {t}, free flight {t_free}"
    );
    // No contact force at any output point.
    let sys = CompliantSystem::new(&p, &load);
    let mut max_force = 0.0_f64;
    Solver::new(Method::Dopri5, Options::default())
        .with_observer(|_t, y: &SVector<f64, 8>| {
            let s = sys.sample(y);
            max_force = max_force.max(s.f_edge).max(s.f_wall);
        })
        .solve(&sys, 0.0, start.to_vector(), t)
        .unwrap();
    assert_eq!(max_force, 0.0);
}

/// Upright peg pushed sideways by `f₂ = 50 N` at its centre of mass
/// (above the hole) with an axial push `f₁ = 2 N`: it tips into a two-point
/// contact (right edge, left wall) and Coulomb friction holds it. Returns
/// the outcome and the creep of the depth between 30 and 50 ms, after the
/// impacts have settled; the regularized law creeps at a speed `∝ v_s`.
fn creep(v_s: f64) -> (InsertionOutcome, f64) {
    let p = params(0.1, v_s);
    let load = Load {
        axial: 2.0,
        radial: 50.0,
        torque: 0.0,
    };
    let r = p.spec.geometry.peg_radius;
    let mut start = PegState::centred(&p, 0.02);
    start.x = 0.025 - r + 2e-7; // both right contacts slightly loaded
    let opts = InsertionOptions {
        target_depth: 0.03,
        t_max: 0.1,
        window: 0.02,
        ..InsertionOptions::default()
    };
    let outcome = simulate_insertion(&p, &load, &start, &opts)
        .unwrap()
        .outcome;
    let sys = CompliantSystem::new(&p, &load);
    let mut options = Options::with_tolerances(1e-8, 1e-13);
    options.output = OutputMode::AtTimes(vec![0.03, 0.05]);
    let sol = Solver::new(Method::Dopri5, options)
        .solve(&sys, 0.0, start.to_vector(), 0.05)
        .unwrap();
    let depth = |y: &SVector<f64, 8>| sys.sample(y).depth;
    (outcome, depth(&sol.x[1]) - depth(&sol.x[0]))
}

#[test]
fn side_pushed_peg_jams_and_regularization_creep_shrinks_with_the_scale() {
    let (o1, c1) = creep(1e-4);
    let (o2, c2) = creep(1e-5);
    let (o3, c3) = creep(1e-6);
    for o in [o1, o2, o3] {
        assert!(matches!(o, InsertionOutcome::Jammed { .. }), "{o:?}");
    }
    assert!(c1 > 0.0, "creep {c1}");
    assert!(
        c2.abs() < 0.2 * c1 && c3.abs() < 0.2 * c2.abs(),
        "creep must shrink ~ v_s: {c1} {c2} {c3}"
    );
}

#[test]
fn no_axial_force_leaves_a_free_peg_stalled() {
    let p = params(0.1, 1e-5);
    let run = simulate_insertion(
        &p,
        &Load::default(),
        &PegState::centred(&p, 0.005),
        &InsertionOptions::default(),
    )
    .unwrap();
    assert!(
        matches!(run.outcome, InsertionOutcome::Stalled { .. }),
        "{:?}",
        run.outcome
    );
}
