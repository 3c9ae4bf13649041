//! Energy and passivity of the compliant planar peg ((55)–(64)):
//! without friction `T + P − W` is constant to the integrator tolerance;
//! with friction the dissipated energy `S` never decreases and
//! `T + P − W + S` is constant, also with Hunt–Crossley contact damping.
//! `W` (work of the applied loads) and `S` are
//! integrated as extra states of the generated model.

use nalgebra::SVector;
use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, CompliantSystem, Load, PegState};
use pegdyn::integrate::{Method, Options, Solver};

struct Trace {
    balance_drift: f64,
    scale: f64,
    max_force: f64,
    min_dissipation_step: f64,
    dissipation: f64,
}

fn run(mu: f64, rtol: f64, atol: f64) -> Trace {
    run_damped(mu, 0.0, rtol, atol)
}

fn run_damped(mu: f64, damping: f64, rtol: f64, atol: f64) -> Trace {
    let mut spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, mu);
    spec.damping = damping;
    let p = CompliantParams::try_new(spec).unwrap();
    // Tilted two-point start; the torque rocks the peg against both contacts.
    let load = Load {
        axial: 20.0,
        radial: 2.0,
        torque: -0.3,
    };
    let sys = CompliantSystem::new(&p, &load);
    let y0 = PegState::two_point(&p, 0.01, 0.0).unwrap().to_vector();
    let h0 = sys.sample(&y0).balance();
    let mut tr = Trace {
        balance_drift: 0.0,
        scale: 0.0,
        max_force: 0.0,
        min_dissipation_step: 0.0,
        dissipation: 0.0,
    };
    let mut last_s = 0.0;
    let mut options = Options::with_tolerances(rtol, atol);
    options.store = false;
    let sol = Solver::new(Method::Dopri5, options)
        .with_observer(|_t, y: &SVector<f64, 8>| {
            let s = sys.sample(y);
            tr.balance_drift = tr.balance_drift.max((s.balance() - h0).abs());
            tr.scale = tr.scale.max(s.work.abs()).max(s.kinetic);
            tr.max_force = tr.max_force.max(s.f_edge).max(s.f_wall);
            tr.min_dissipation_step = tr.min_dissipation_step.min(s.dissipation - last_s);
            last_s = s.dissipation;
        })
        .solve(&sys, 0.0, y0, 0.03)
        .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    tr.dissipation = last_s;
    tr
}

#[test]
fn frictionless_energy_is_conserved_to_the_tolerance() {
    let loose = run(0.0, 1e-6, 1e-12);
    let tight = run(0.0, 1e-10, 1e-15);
    assert!(
        tight.max_force > 1.0,
        "the contacts must be loaded: {}",
        tight.max_force
    );
    assert_eq!(tight.dissipation, 0.0);
    let (rel_loose, rel_tight) = (
        loose.balance_drift / loose.scale,
        tight.balance_drift / tight.scale,
    );
    assert!(rel_tight < 1e-7, "drift {rel_tight} of {}", tight.scale);
    assert!(
        rel_tight < 0.1 * rel_loose,
        "drift shrinks with the tolerance: {rel_loose} -> {rel_tight}"
    );
}

#[test]
fn friction_dissipates_and_the_balance_closes() {
    let tr = run(0.1, 1e-10, 1e-15);
    assert!(tr.max_force > 1.0);
    assert!(
        tr.dissipation > 1e-4 * tr.scale,
        "dissipated {} of {}",
        tr.dissipation,
        tr.scale
    );
    assert!(
        tr.min_dissipation_step >= 0.0,
        "dissipation decreased by {}",
        -tr.min_dissipation_step
    );
    assert!(
        tr.balance_drift / tr.scale < 1e-7,
        "balance drift {} of {}",
        tr.balance_drift,
        tr.scale
    );
}

/// Hunt–Crossley contact damping (α = 0.5 s/m, no friction) dissipates
/// energy and the balance, with its dissipation in `S`, still closes.
#[test]
fn contact_damping_dissipates_and_the_balance_closes() {
    let tr = run_damped(0.0, 0.5, 1e-10, 1e-15);
    assert!(tr.max_force > 1.0);
    assert!(
        tr.dissipation > 1e-4 * tr.scale,
        "dissipated {} of {}",
        tr.dissipation,
        tr.scale
    );
    assert!(
        tr.min_dissipation_step >= 0.0,
        "dissipation decreased by {}",
        -tr.min_dissipation_step
    );
    assert!(
        tr.balance_drift / tr.scale < 1e-7,
        "balance drift {} of {}",
        tr.balance_drift,
        tr.scale
    );
}
