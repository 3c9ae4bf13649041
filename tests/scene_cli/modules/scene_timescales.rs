//! The items of `src/scene/timescales.rs`.

use pegdyn::scene::timescales::*;

fn scales(period: f64) -> TimeScales {
    TimeScales {
        scales: vec![
            TimeScale::new("slow", "a = 1", 1.0),
            TimeScale::new("the contact's natural period", "peg.k = 1e15", period),
            TimeScale::new("not a scale", "b = 0", f64::NAN),
        ],
        span: (0.0, 0.05),
        atol: 1e-10,
        rtol: 1e-6,
    }
}

#[test]
fn a_slow_run_names_the_tolerances_or_the_scale_that_set_its_steps() {
    let mut t = scales(1e-5);
    t.rtol = 1e-13;
    t.atol = 1e-20;
    // Steps of 1e-10 s: 1/100000 of the fastest scale.
    let s = t.slow_cause(1e-10);
    assert!(
        s.starts_with("the tolerance")
            && s.contains("1/100000 of the fastest time scale")
            && s.contains("integrator.rtol = 1e-13 and integrator.atol = 1e-20"),
        "{s}"
    );
    // Steps of a tenth of the scale: the scale sets them.
    let s = t.slow_cause(1e-6);
    assert!(
        s.starts_with("the fastest time scale of the scene, the contact's natural period")
            && s.contains("change peg.k = 1e15")
            && !s.contains("rtol"),
        "{s}"
    );
    // No scale known: both tolerances are named.
    t.scales.clear();
    let s = t.slow_cause(1e-6);
    assert!(
        s.contains("integrator.rtol = 1e-13 and integrator.atol = 1e-20"),
        "{s}"
    );
}

#[test]
fn a_scale_below_f64_resolution_is_named_with_its_fields() {
    // 16 eps 0.05 = 1.8e-16 s: a 2e-15 s scale is 11 steps long.
    let s = scales(2e-15).step_failure_cause(0.0, 1.7e-16);
    assert!(
        s.contains("the contact's natural period = 2e-15 s (peg.k = 1e15)")
            && s.contains("too short to follow")
            && s.contains("change peg.k = 1e15"),
        "{s}"
    );
}

#[test]
fn a_step_far_below_every_scale_points_at_the_tolerance() {
    let mut t = scales(1e-5);
    t.atol = 1e-300;
    let s = t.step_failure_cause(0.0, 2.2e-15);
    assert!(
        s.starts_with("the tolerance") && s.contains("integrator.atol = 1e-300"),
        "{s}"
    );
    // A step near the fastest scale names that scale.
    let s = t.step_failure_cause(0.0, 1e-8);
    assert!(
        s.starts_with("the contact's natural period = 1e-5 s"),
        "{s}"
    );
}

#[test]
fn periods_follow_their_formulas() {
    assert!((TimeScale::period_of(1.0, 4.0 * std::f64::consts::PI.powi(2)) - 1.0).abs() < 1e-15);
    // F = k δ^1.5 at δ = 1e-6, k = 1e10: F = 10 N, dF/dδ = 1.5 k δ^0.5 = 1.5e7.
    let k = TimeScale::hertz_stiffness(1e10, 10.0);
    assert!((k / 1.5e7 - 1.0).abs() < 1e-12, "{k}");
}

#[test]
fn a_step_budget_names_the_tolerance_or_the_scale_that_set_the_steps() {
    let mut t = scales(3e-5);
    t.atol = 1e-300;
    // 1e6 steps to 4.5e-7 s: 4.5e-13 s each, 1/6.7e7 of the scale.
    let s = t.budget_cause(4.5e-7, 4.5e-13);
    assert!(
        s.starts_with("the tolerance") && s.contains("integrator.atol = 1e-300"),
        "{s}"
    );
    // Steps of a tenth of the scale over 0.05 s: 16667 of them.
    let s = t.budget_cause(0.01, 3e-6);
    assert!(
        s.starts_with("the contact's natural period = 3e-5 s")
            && s.contains("about 16667 of them")
            && s.contains("raise integrator.max_steps, or change peg.k = 1e15"),
        "{s}"
    );
}
