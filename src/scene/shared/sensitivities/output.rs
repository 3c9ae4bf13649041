//! The outputs of a `[sensitivities]` table: `<scene>.sensitivities.csv`
//! (one row per metric and field: `metric, parameter, value, derivative,
//! elasticity, flag`; a flagged derivative and elasticity are empty cells),
//! the tornado plot `<scene>.sensitivities.svg` (per metric, the fields'
//! elasticities as bars, largest magnitude on top; flagged fields are left
//! out) and the ranking `pegdyn run` prints (the fields by |elasticity|
//! for each metric).

use super::Row;
use crate::error::RunError;
use crate::output::csv::format_f64;
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series};
use crate::scene::context::RunContext;
use crate::scene::summary::Metric;

/// The CSV's header.
pub const HEADER: [&str; 6] = [
    "metric",
    "parameter",
    "value",
    "derivative",
    "elasticity",
    "flag",
];

/// The fields shown per metric in the printed ranking.
const RANKED: usize = 5;

/// Elasticities below this are left out of the ranking and the plot
/// (e.g. the final depth of a seated run, the target depth by definition,
/// moves with no other field).
const NEGLIGIBLE: f64 = 1e-9;

/// Half the height of a tornado bar (the bars sit on integer rows).
const BAR: f64 = 0.35;

/// The cells of a row in the order of [`HEADER`] (an empty cell for a
/// missing number).
pub fn cells(r: &Row) -> [String; 6] {
    let cell = |v: Option<f64>| v.map(format_f64).unwrap_or_default();
    [
        r.metric.to_owned(),
        r.parameter.to_owned(),
        cell(r.value),
        cell(r.derivative),
        cell(r.elasticity),
        r.flag.clone(),
    ]
}

/// Writes the CSV and the tornado plot of `rows` (metrics in the order of
/// `metrics`), and returns the ranking as notes; the plot and the ranking
/// name each field without `prefix` (`"insert_compliant."`: `friction`).
///
/// # Errors
/// The files cannot be written.
pub fn write(
    ctx: &RunContext,
    rows: &[Row],
    metrics: &[&str],
    prefix: &str,
) -> Result<Vec<Metric>, RunError> {
    let short = |parameter: &'static str| parameter.strip_prefix(prefix).unwrap_or(parameter);
    let part = Part::Sub("sensitivities");
    let mut csv = ctx.table(part, &HEADER)?;
    for r in rows {
        csv.row_cells(&cells(r).each_ref().map(String::as_str))?;
    }
    csv.finish()?;
    let mut fig = Figure::new();
    let mut notes = Vec::new();
    for &metric in metrics {
        let mut ranked: Vec<(&str, f64)> = rows
            .iter()
            .filter(|r| r.metric == metric && r.flag.is_empty())
            .filter_map(|r| r.elasticity.map(|e| (short(r.parameter), e)))
            .filter(|(_, e)| e.abs() > NEGLIGIBLE)
            .collect();
        ranked.sort_by(|a, b| b.1.abs().total_cmp(&a.1.abs()));
        let flagged = rows
            .iter()
            .filter(|r| r.metric == metric && !r.flag.is_empty() && r.derivative.is_none())
            .count();
        if ranked.is_empty() {
            if flagged > 0 {
                notes.push(Metric::note(
                    format!("sensitivities of {metric}"),
                    "every derivative flagged (see the flag column of the CSV)",
                ));
            }
            continue;
        }
        let text = ranked
            .iter()
            .take(RANKED)
            .map(|(p, e)| format!("{p} {e:+.3}"))
            .collect::<Vec<_>>()
            .join(", ");
        let more = if flagged > 0 {
            format!("; {flagged} flagged")
        } else {
            String::new()
        };
        notes.push(Metric::note(
            format!("elasticities of {metric}"),
            format!("{text}{more}"),
        ));
        let mut panel = Panel::new(
            &format!("Elasticities of {metric}"),
            "q/m dm/dq",
            "rank (largest on top)",
        );
        let n = ranked.len();
        for (i, (p, e)) in ranked.iter().enumerate() {
            let y = (n - 1 - i) as f64;
            let bar = vec![
                (0.0, y - BAR),
                (*e, y - BAR),
                (*e, y + BAR),
                (0.0, y + BAR),
                (0.0, y - BAR),
            ];
            panel = panel.with(Series::line(format!("{p} {e:+.3}"), bar).colored(i % 8));
        }
        fig.panels.push(panel);
    }
    if !fig.panels.is_empty() {
        ctx.figure(part, &fig)?;
    }
    Ok(notes)
}
