//! The items of `src/scene/kinds/jamming/comparison.rs`.

use pegdyn::internals::jamming::*;
use pegdyn::jamming::sweep::{BoundaryCheck, RunClass, SweepPoint};
use pegdyn::scene::Metric;

fn check(judged: usize, mismatches: usize, other: usize) -> BoundaryCheck {
    failing(judged, mismatches, other, 0)
}

fn failing(judged: usize, mismatches: usize, other: usize, failed: usize) -> BoundaryCheck {
    let p = SweepPoint {
        ratio: [0.0, 0.0],
        class: RunClass::Jammed,
    };
    BoundaryCheck {
        mismatches: vec![p; mismatches],
        judged,
        other,
        failed,
        tolerance: 0.1,
    }
}

const TOL: &str = "sweep.method = rodas4, sweep.rtol = 1e-4, sweep.atol = 1e-8";

fn text(metrics: Vec<Metric>) -> String {
    pegdyn::scene::RunSummary {
        metrics,
        ..Default::default()
    }
    .to_string()
}

#[test]
fn contradictions_are_counted_of_the_points_judged() {
    let t = text(comparison(169, &check(108, 0, 0), &check(108, 2, 0), TOL));
    assert!(
        t.contains("points contradicting the exact diagram (of 108 judged) = 0\n"),
        "{t}"
    );
    assert!(
        t.contains("points contradicting Whitney's diagram (of 108 judged) = 2\n"),
        "{t}"
    );
    assert!(!t.contains("NOT MADE"), "{t}");
}

#[test]
fn a_sweep_that_judges_nothing_says_so_and_counts_no_contradiction() {
    for (runs, other) in [(169, 169), (9, 3), (0, 0)] {
        let t = text(comparison(
            runs,
            &check(0, 0, other),
            &check(0, 0, other),
            TOL,
        ));
        assert!(!t.contains("contradicting"), "{t}");
        assert!(
            t.contains("diagram check: NOT MADE for either diagram")
                && t.contains(&format!("({other} of {runs} runs neither")),
            "{t}"
        );
    }
    let t = text(comparison(169, &check(12, 0, 150), &check(0, 0, 150), TOL));
    assert!(t.contains("the exact diagram (of 12 judged) = 0"), "{t}");
    assert!(t.contains("NOT MADE for Whitney's diagram"), "{t}");
}

#[test]
fn runs_the_integrator_could_not_finish_are_counted_and_named() {
    for (runs, failed) in [(25, 25), (169, 169)] {
        let c = failing(0, 0, failed, failed);
        let t = text(comparison(runs, &c, &c, TOL));
        assert!(!t.contains("contradicting"), "{t}");
        assert!(
            t.contains(&format!(
                "({failed} of {runs} runs neither inserted nor stuck; {failed} of them the \
                 integrator could not finish"
            )) && t.contains(TOL)
                && t.contains("change the integrator's settings")
                && !t.contains("widen the grid"),
            "{t}"
        );
        assert!(
            t.contains(&format!(
                "of them, runs the integrator could not finish (class failed) = {failed}\n"
            )),
            "{t}"
        );
    }
    // Some failed, some unfinished: both causes are offered.
    let c = failing(0, 0, 9, 4);
    let t = text(comparison(9, &c, &c, TOL));
    assert!(
        t.contains("4 of them") && t.contains("widen the grid"),
        "{t}"
    );
    // None failed: no such line.
    let t = text(comparison(169, &check(108, 0, 3), &check(108, 0, 3), TOL));
    assert!(!t.contains("could not finish"), "{t}");
}
