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
pub fn comparison(
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
