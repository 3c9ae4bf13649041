//! The `[sweep]`'s comparison with the jamming diagrams as summary
//! metrics.

use crate::jamming::sweep;
use crate::scene::summary::Metric;

/// The sweep's comparison with the diagrams as metrics: the contradictions
/// are counted of the points judged (`(of 108 judged)`); when no point was
/// judged the counts are replaced by a note saying that nothing was
/// compared, never a bare "contradicting = 0", and why: runs the
/// integrator could not finish are counted and named with `tolerances`
/// (the sweep's method and tolerances as written).
pub(super) fn comparison(
    runs: usize,
    exact: &sweep::BoundaryCheck,
    small: &sweep::BoundaryCheck,
    tolerances: &str,
) -> Vec<Metric> {
    let mut metrics = vec![
        Metric::new("sweep runs", runs as f64, ""),
        Metric::new(
            "grid points judged (beyond one cell of the boundary)",
            exact.judged as f64,
            "",
        ),
    ];
    let contradicting = |which: &str, check: &sweep::BoundaryCheck| {
        Metric::new(
            format!(
                "points contradicting {which} diagram (of {} judged)",
                check.judged
            ),
            check.mismatches.len() as f64,
            "",
        )
    };
    if exact.judged > 0 {
        metrics.push(contradicting("the exact", exact));
    }
    if small.judged > 0 {
        metrics.push(contradicting("Whitney's", small));
    }
    if exact.judged == 0 || small.judged == 0 {
        let why = if exact.failed > 0 {
            format!(
                "; {} of them the integrator could not finish (step size underflow, non-finite \
                 values or the step budget) under {tolerances}: a tolerance far from the \
                 state's scale is the likely cause",
                exact.failed
            )
        } else {
            String::new()
        };
        let advice = if exact.failed == exact.other && exact.failed > 0 {
            "change the integrator's settings"
        } else {
            "widen the grid, lengthen sweep.t_max_s or shorten sweep.window_s"
        };
        metrics.push(Metric::note(
            "diagram check",
            format!(
                "NOT MADE for {}: no run ended inserted or stuck farther than one grid cell \
                 from the boundary ({} of {runs} runs neither inserted nor stuck{why}), so the \
                 sweep compared nothing; {advice}",
                match (exact.judged, small.judged) {
                    (0, 0) => "either diagram",
                    (0, _) => "the exact diagram",
                    _ => "Whitney's diagram",
                },
                exact.other
            ),
        ));
    }
    metrics.push(Metric::new(
        "runs neither inserted nor stuck",
        exact.other as f64,
        "",
    ));
    if exact.failed > 0 {
        metrics.push(Metric::new(
            "of them, runs the integrator could not finish (class failed)",
            exact.failed as f64,
            "",
        ));
    }
    metrics
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::jamming::sweep::{BoundaryCheck, RunClass, SweepPoint};

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
        crate::scene::RunSummary {
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
}
