//! The work-precision diagram: error against wall time, log-log, one line
//! per method; points the reference cannot judge as extra markers; the
//! reference's error estimate as a dashed horizontal line.

use pegdyn::output::plot::{Figure, Panel, Scale, Series, Style};

use crate::measure::Point;

const METHODS: [&str; 4] = ["rk4", "dopri5", "rodas3", "rodas4"];

fn panel(title: &str, unit: &str, points: &[Point], err: fn(&Point) -> f64, ref_err: f64) -> Panel {
    let mut panel = Panel::new(title, "wall time per run [s]", &format!("error [{unit}]"))
        .scales(Scale::Log, Scale::Log);
    let (mut t_lo, mut t_hi) = (f64::INFINITY, 0.0_f64);
    for (color, method) in METHODS.iter().enumerate() {
        let mut pts: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.method == *method && err(p).is_finite())
            .map(|p| (p.wall_s, err(p)))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        for &(t, _) in &pts {
            (t_lo, t_hi) = (t_lo.min(t), t_hi.max(t));
        }
        panel = panel.with(
            Series::line(*method, pts)
                .styled(Style::LineMarkers)
                .colored(color),
        );
    }
    let flagged: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| !p.resolved && err(p).is_finite())
        .map(|p| (p.wall_s, err(p)))
        .collect();
    if !flagged.is_empty() {
        panel = panel.with(
            Series::line("below 2x the reference error (not judged)", flagged)
                .styled(Style::Markers)
                .colored(7),
        );
    }
    if ref_err > 0.0 && t_hi > 0.0 {
        panel = panel.with(
            Series::line(
                "reference error estimate",
                vec![(t_lo, ref_err), (t_hi, ref_err)],
            )
            .styled(Style::Dashed)
            .colored(7),
        );
    }
    panel
}

/// Two panels: error at the end time, largest error over the trajectory.
pub fn figure(name: &str, unit: &str, points: &[Point], reference_error: (f64, f64)) -> Figure {
    let mut fig = Figure::new();
    fig.panels.push(panel(
        &format!("{name}: error at t_end vs time"),
        unit,
        points,
        |p| p.err_end,
        reference_error.0,
    ));
    fig.panels.push(panel(
        &format!("{name}: max error over the trajectory vs time"),
        unit,
        points,
        |p| p.err_max,
        reference_error.1,
    ));
    fig
}
