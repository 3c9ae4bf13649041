//! A run that cannot step names its likely cause: a tolerance far below
//! the state's scale (`integrator.atol` from `1e-300` to `1e-40`), whether
//! the step becomes too small at the first step or the step budget runs
//! out, and the scene's fastest time scale with its fields when the sizes
//! are at their smallest. Several values per kind, each run in-process.

use crate::common::scene_text::{shipped, with};

use crate::common::cli::{fresh_dir, run_scene};

/// The stop of `text` run as `name`, which must have failed.
fn failed_stop(text: &str, name: &str, tag: &str) -> String {
    let s = run_scene(text, name, &fresh_dir("step-causes", tag));
    let i = s.integration.expect("an integration");
    assert!(!i.success, "{tag}: {}", i.stop);
    i.stop
}

#[test]
fn a_tolerance_far_below_the_state_is_named_as_the_cause() {
    for (kind, values) in [
        ("insert_rcc", ["1e-300", "1e-100", "1e-40"]),
        ("insert_compliant", ["1e-300", "1e-100", "1e-40"]),
    ] {
        // insert_rcc with the explicit DOPRI5 at rtol 1e-6, whose steps a
        // tolerance far below the state shrinks (the scene's own RODAS4 at
        // rtol 1e-4 with atol 1e-40 steps on to the budget, and the
        // summary names the wrist's angular damping time instead).
        let base = if kind == "insert_rcc" {
            with(
                &with(&shipped(kind), "method", "\"dopri5\""),
                "rtol",
                "1e-6",
            )
        } else {
            shipped(kind)
        };
        for atol in values {
            // A small step budget: the runs that do not fail at once stop
            // on it, and name the same cause.
            let text = with(&base, "atol", &format!("{atol}\nmax_steps = 20000"));
            let stop = failed_stop(&text, kind, &format!("{kind}-{atol}"));
            assert!(
                stop.contains("; likely cause: the tolerance")
                    && stop.contains(&format!("integrator.atol = {atol} is likely far below")),
                "{kind} atol {atol}: {stop}"
            );
        }
    }
}

#[test]
fn a_step_budget_too_small_for_the_scene_names_the_scale_that_sets_the_steps() {
    for steps in ["20", "50"] {
        let text = with(
            &shipped("insert_rcc"),
            "atol",
            &format!("1e-10\nmax_steps = {steps}"),
        );
        let stop = failed_stop(&text, "rcc", &format!("budget-{steps}"));
        assert!(
            stop.contains(&format!("step budget of {steps} steps"))
                && stop.contains("which sets the steps")
                && stop.contains("raise integrator.max_steps, or change wrist."),
            "{steps}: {stop}"
        );
    }
}

#[test]
fn drop_3d_at_its_smallest_sizes_names_the_fields_that_set_the_step() {
    let mut tiny = shipped("drop_3d");
    for (k, v) in [
        ("hole_diameter", "1e-6"),
        ("length", "1e-6"),
        ("rim_fillet", "1e-7"),
        ("mouth_fillet", "1e-7"),
        ("bore_depth", "1e-6"),
    ] {
        tiny = with(&tiny, k, v);
    }
    for (slip, shown, tag) in [("1e-3", "0.001", "shipped"), ("1.0", "1", "largest")] {
        let text = with(&tiny, "slip_velocity", slip);
        let stop = failed_stop(&text, "tiny", &format!("tiny-{tag}"));
        assert!(
            stop.contains("at t = 0 s; likely cause: ")
                && stop.contains("is too short to follow")
                && stop.contains(&format!("change peg.slip_velocity = {shown} m/s"))
                && stop.contains("drop.aligning_moment"),
            "slip {slip}: {stop}"
        );
    }
}
