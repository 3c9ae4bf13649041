//! `Options::error_components`: the step control over the first `n`
//! components only, as a sensitivity run uses it.

use nalgebra::{Vector1, Vector2};
use pegdyn::integrate::{IntegrateError, Method, Options, Solver, StopReason};
use pegdyn::system::FnSystem;

/// `y′ = −y` alone.
fn decay() -> FnSystem<impl Fn(f64, &Vector1<f64>) -> Vector1<f64>> {
    FnSystem(|_t: f64, x: &Vector1<f64>| -x)
}

#[test]
fn the_first_component_alone_sets_the_steps() {
    // y′ = −y beside a fast oscillation z′ = cos(2000 t): controlling y
    // only, the steps are those of y′ = −y by itself and y is the same
    // number; controlling both, the oscillation takes many more steps.
    let both = FnSystem(|t: f64, x: &Vector2<f64>| Vector2::new(-x[0], (2000.0 * t).cos()));
    // One starting step for all (its estimate reads every component).
    let options = Options {
        h0: Some(1e-4),
        ..Options::with_tolerances(1e-8, 1e-10)
    };
    let alone = Solver::new(Method::Dopri5, options.clone())
        .solve(&decay(), 0.0, Vector1::new(1.0), 2.0)
        .expect("solves");
    let first = Options {
        error_components: Some(1),
        ..options.clone()
    };
    let controlled_first = Solver::new(Method::Dopri5, first)
        .solve(&both, 0.0, Vector2::new(1.0, 0.0), 2.0)
        .expect("solves");
    let controlled_all = Solver::new(Method::Dopri5, options)
        .solve(&both, 0.0, Vector2::new(1.0, 0.0), 2.0)
        .expect("solves");
    assert_eq!(controlled_first.stats.steps, alone.stats.steps);
    assert_eq!(controlled_first.stats.rejected, alone.stats.rejected);
    assert_eq!(controlled_first.x_final[0], alone.x_final[0]);
    assert!(
        controlled_all.stats.steps > 10 * alone.stats.steps,
        "{} against {}",
        controlled_all.stats.steps,
        alone.stats.steps
    );
    // n beyond the state's size means every component.
    let beyond = Options {
        error_components: Some(5),
        h0: Some(1e-4),
        ..Options::with_tolerances(1e-8, 1e-10)
    };
    let sol = Solver::new(Method::Dopri5, beyond)
        .solve(&both, 0.0, Vector2::new(1.0, 0.0), 2.0)
        .expect("solves");
    assert_eq!(sol.stats.steps, controlled_all.stats.steps);
}

#[test]
fn a_component_outside_the_norm_that_is_not_finite_still_stops_the_run() {
    // z′ turns NaN at t = 0.5: never a silent NaN in the uncontrolled part.
    let bad = FnSystem(|t: f64, x: &Vector2<f64>| {
        Vector2::new(-x[0], if t > 0.5 { f64::NAN } else { 1.0 })
    });
    let options = Options {
        error_components: Some(1),
        ..Options::with_tolerances(1e-8, 1e-10)
    };
    let sol = Solver::new(Method::Dopri5, options)
        .solve(&bad, 0.0, Vector2::new(1.0, 0.0), 2.0)
        .expect("solves");
    match sol.stop {
        StopReason::NonFinite { t } => assert!((0.4..=0.5).contains(&t), "{t}"),
        other => panic!("{other:?}"),
    }
    assert!(sol.x_final.iter().all(|v| v.is_finite()));
}

/// `y′ = 1` beside `z′ = 1/√|t − t_s|`, an integrable singularity at
/// `t_s = 0.37` (a sensitivity's rate at a contact that splits in two).
fn singular() -> FnSystem<impl Fn(f64, &Vector2<f64>) -> Vector2<f64>> {
    FnSystem(|t: f64, _: &Vector2<f64>| Vector2::new(1.0, 1.0 / (t - 0.37).abs().sqrt()))
}

#[test]
fn the_fallback_passes_an_integrable_singularity_of_the_extension() {
    // Every component controlled, z's error estimate stays above the
    // tolerance however short the step across t_s: the run stops at the
    // round-off floor there. With the first component judging the steps
    // shorter than FALLBACK_FLOOR round-off floors, it passes, says how
    // many steps it so judged (4), and z(1) = 2√t_s + 2√(1 − t_s) is
    // within 1.1e-6 relative (about √h of a step there, h ≈ 3.6e-11).
    let options = Options::with_tolerances(1e-10, 1e-12);
    let stopped = Solver::new(Method::Dopri5, options.clone())
        .solve(&singular(), 0.0, Vector2::zeros(), 1.0)
        .expect("solves");
    match stopped.stop {
        StopReason::StepSizeTooSmall { t, .. } => assert!((t - 0.37).abs() < 1e-9, "{t}"),
        other => panic!("{other:?}"),
    }
    assert_eq!(stopped.stats.fallback_steps, 0);
    let fallback = Options {
        fallback_components: Some(1),
        ..options
    };
    let sol = Solver::new(Method::Dopri5, fallback)
        .solve(&singular(), 0.0, Vector2::zeros(), 1.0)
        .expect("solves");
    assert_eq!(sol.stop, StopReason::ReachedEnd);
    let n = sol.stats.fallback_steps;
    assert!(
        (1..=100).contains(&n),
        "{n} steps judged by the first component"
    );
    let exact = 2.0 * 0.37_f64.sqrt() + 2.0 * 0.63_f64.sqrt();
    let err = (sol.x_final[1] - exact).abs();
    eprintln!(
        "z(1) error {err:e}, {n} fallback steps, {} steps",
        sol.stats.steps
    );
    assert!(
        err < 1e-5 * exact,
        "z(1) = {} against {exact}",
        sol.x_final[1]
    );
    assert!((sol.x_final[0] - 1.0).abs() < 1e-12);
}

#[test]
fn no_component_is_refused_naming_the_option() {
    let none_controlled = Options {
        error_components: Some(0),
        ..Options::default()
    };
    let none_fall_back = Options {
        fallback_components: Some(0),
        ..Options::default()
    };
    for (options, option) in [
        (none_controlled, "error_components"),
        (none_fall_back, "fallback_components"),
    ] {
        let err = Solver::new(Method::Dopri5, options)
            .solve(&decay(), 0.0, Vector1::new(1.0), 1.0)
            .expect_err("refused");
        match err {
            IntegrateError::InvalidOption { name, .. } => assert_eq!(name, option),
            other => panic!("{other:?}"),
        }
    }
}
