//! SVG rendering of [`Figure`]s through plotters' SVG backend (no system
//! fonts needed): title, axis labels, legend, linear or log axes, solid,
//! dashed or marker series, gaps at non-finite points.
//!
//! ```
//! use pegdyn::output::plot::{Figure, Panel, Series};
//! let pts: Vec<(f64, f64)> = (0..50).map(|i| (i as f64 * 0.1, (i as f64 * 0.1).sin())).collect();
//! let mut fig = Figure::new();
//! fig.panels.push(Panel::new("sine", "t [s]", "x [m]").with(Series::line("x", pts)));
//! let svg = fig.render().unwrap();
//! assert!(svg.starts_with("<svg") && svg.contains("sine"));
//! ```

use std::path::Path;

use plotters::coord::Shift;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;

use crate::error::OutputError;
use crate::output::plot::{Figure, Panel, Scale, Style};

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

impl Figure {
    /// Renders to an SVG string.
    pub fn render(&self) -> Result<String, OutputError> {
        self.render_for(Path::new("<memory>"))
    }

    /// Renders and writes to `path`.
    ///
    /// A path in a [`super::memory::Capture`] directory is not drawn: only
    /// the check that every panel has a drawable point is made.
    pub fn save(&self, path: &Path) -> Result<(), OutputError> {
        if super::memory::is_memory(path) {
            return self.check_drawable(path);
        }
        let svg = self.render_for(path)?;
        super::atomic::write(path, svg.as_bytes())
    }

    /// Refuses a panel without a drawable point, as drawing does.
    fn check_drawable(&self, path: &Path) -> Result<(), OutputError> {
        for panel in &self.panels {
            let x = bounds(panel, panel.x_scale, |p| p.0);
            let y = bounds(panel, panel.y_scale, |p| p.1);
            if x.is_none() || y.is_none() {
                return Err(OutputError::EmptyPlot {
                    path: path.to_path_buf(),
                    panel: panel.title.clone(),
                });
            }
        }
        Ok(())
    }

    fn render_for(&self, path: &Path) -> Result<String, OutputError> {
        let plot_err = |message: String| OutputError::Plot {
            path: path.to_path_buf(),
            message,
        };
        let mut svg = String::new();
        let height = self.panel_height * self.panels.len().max(1) as u32;
        {
            let root = SVGBackend::with_string(&mut svg, (self.width, height)).into_drawing_area();
            root.fill(&WHITE).map_err(|e| plot_err(e.to_string()))?;
            let areas = root.split_evenly((self.panels.len().max(1), 1));
            for (panel, area) in self.panels.iter().zip(&areas) {
                let (Some(x), Some(y)) = (
                    bounds(panel, panel.x_scale, |p| p.0),
                    bounds(panel, panel.y_scale, |p| p.1),
                ) else {
                    return Err(OutputError::EmptyPlot {
                        path: path.to_path_buf(),
                        panel: panel.title.clone(),
                    });
                };
                let (xs, ys) = (x.1 - x.0, y.1 - y.0);
                let (xl, yl) = ((x.0..x.1).log_scale(), (y.0..y.1).log_scale());
                let (xr, yr) = (x.0..x.1, y.0..y.1);
                let r = match (panel.x_scale, panel.y_scale) {
                    (Scale::Linear, Scale::Linear) => draw(area, panel, (xr, xs), (yr, ys)),
                    (Scale::Linear, Scale::Log) => draw(area, panel, (xr, xs), (yl, 0.0)),
                    (Scale::Log, Scale::Linear) => draw(area, panel, (xl, 0.0), (yr, ys)),
                    (Scale::Log, Scale::Log) => draw(area, panel, (xl, 0.0), (yl, 0.0)),
                };
                r.map_err(plot_err)?;
            }
            root.present().map_err(|e| plot_err(e.to_string()))?;
        }
        Ok(svg)
    }
}

/// Whether point coordinate `v` can be drawn on an axis of scale `s`.
fn drawable(v: f64, s: Scale) -> bool {
    v.is_finite() && (s == Scale::Linear || v > 0.0)
}

/// Axis range over the drawable points of the panel, padded by 5 % on a
/// linear axis and to whole decades' fractions on a log axis.
fn bounds(panel: &Panel, s: Scale, pick: impl Fn(&(f64, f64)) -> f64) -> Option<(f64, f64)> {
    let (xs, ys) = (panel.x_scale, panel.y_scale);
    let vals = panel
        .series
        .iter()
        .flat_map(|se| se.points.iter())
        .filter(|p| drawable(p.0, xs) && drawable(p.1, ys))
        .map(pick);
    let (lo, hi) = vals.fold(None, |acc: Option<(f64, f64)>, v| {
        Some(acc.map_or((v, v), |(l, h)| (l.min(v), h.max(v))))
    })?;
    Some(match s {
        Scale::Linear => {
            let pad = if hi > lo {
                0.05 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            (lo - pad, hi + pad)
        }
        Scale::Log if hi > lo => (lo / 1.2, hi * 1.2),
        Scale::Log => (lo / 2.0, hi * 2.0),
    })
}

/// A short tick label: `0` when `|v|` is below `1e-9 * span` (rounding
/// noise on a linear axis of width `span`), up to four decimals in
/// `[1e-3, 1e5)`, otherwise three significant digits in scientific
/// notation; trailing zeros dropped.
fn tick(v: f64, span: f64) -> String {
    let a = v.abs();
    if a <= 1e-9 * span {
        return "0".into();
    }
    if (1e-3..1e5).contains(&a) {
        let s = format!("{v:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" { "0".into() } else { s.into() }
    } else {
        let s = format!("{v:.2e}");
        match s.split_once('e') {
            Some((m, e)) => {
                let m = if m.contains('.') {
                    m.trim_end_matches('0').trim_end_matches('.')
                } else {
                    m
                };
                format!("{m}e{e}")
            }
            None => s,
        }
    }
}

/// Splits points into runs of drawable points.
fn segments(points: &[(f64, f64)], xs: Scale, ys: Scale) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for &p in points {
        if drawable(p.0, xs) && drawable(p.1, ys) {
            if let Some(s) = out.last_mut() {
                s.push(p);
            }
        } else if out.last().is_some_and(|s| !s.is_empty()) {
            out.push(Vec::new());
        }
    }
    out.retain(|s| !s.is_empty());
    out
}

fn draw<X, Y>(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    panel: &Panel,
    (x, x_span): (X, f64),
    (y, y_span): (Y, f64),
) -> Result<(), String>
where
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let mut chart = ChartBuilder::on(area)
        .caption(&panel.title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_label_formatter(&|v: &f64| tick(*v, x_span))
        .y_label_formatter(&|v: &f64| tick(*v, y_span))
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(|e| e.to_string())?;
    for (i, s) in panel.series.iter().enumerate() {
        let color = PALETTE[s.color.unwrap_or(i) % PALETTE.len()];
        let line = ShapeStyle::from(color).stroke_width(2);
        let mut labelled = s.name.is_empty();
        for seg in segments(&s.points, panel.x_scale, panel.y_scale) {
            let anno = match s.style {
                Style::Solid => chart.draw_series(LineSeries::new(seg, line)),
                Style::Dashed => chart.draw_series(DashedLineSeries::new(seg, 8, 5, line)),
                Style::Markers => {
                    chart.draw_series(seg.into_iter().map(|p| Circle::new(p, 3, color.filled())))
                }
                Style::LineMarkers => {
                    chart
                        .draw_series(seg.iter().map(|&p| Circle::new(p, 3, color.filled())))
                        .map_err(|e| e.to_string())?;
                    chart.draw_series(LineSeries::new(seg, line))
                }
            }
            .map_err(|e| e.to_string())?;
            if !labelled {
                labelled = true;
                let style = s.style;
                // Both arms build the same element type: a dashed legend is
                // two short strokes, a solid one a full stroke and an empty one.
                let (a, b) = if style == Style::Dashed {
                    (7, 13)
                } else {
                    (20, 20)
                };
                anno.label(s.name.as_str()).legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (a, 0)], line)
                        + PathElement::new(vec![(b, 0), (20, 0)], line)
                });
            }
        }
    }
    if panel.series.iter().any(|s| !s.name.is_empty()) {
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::Series;

    fn count(svg: &str, what: &str) -> usize {
        svg.matches(what).count()
    }

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(tick(1e-11 * (1.0 - f64::EPSILON), 0.0), "1e-11");
        assert_eq!(tick(-1e-17, 2.0), "0");
        assert_eq!(tick(-1e-17, 1e-15), "-1e-17");
        assert_eq!(tick(0.25, 1.0), "0.25");
        assert_eq!(tick(2.0, 1.0), "2");
        assert_eq!(tick(123456.0, 1.0), "1.23e5");
    }

    #[test]
    fn gaps_split_a_series_into_segments() {
        let pts = vec![
            (0.0, 1.0),
            (1.0, 2.0),
            (2.0, f64::NAN),
            (3.0, 1.0),
            (4.0, 0.5),
        ];
        assert_eq!(segments(&pts, Scale::Linear, Scale::Linear).len(), 2);
        // On a log axis the non-positive point is a gap too.
        let pts = vec![(1.0, 1.0), (2.0, -1.0), (3.0, 1.0), (4.0, 2.0)];
        assert_eq!(segments(&pts, Scale::Log, Scale::Log).len(), 2);
    }

    #[test]
    fn renders_title_labels_legend_and_log_axes() {
        let pts: Vec<(f64, f64)> = (1..30).map(|i| (i as f64, (i as f64).powi(-4))).collect();
        let fig = Figure {
            panels: vec![
                Panel::new("work-precision", "error [-]", "time [s]")
                    .scales(Scale::Log, Scale::Log)
                    .with(Series::line("dopri5", pts.clone()).styled(Style::LineMarkers))
                    .with(Series::line("rk4", pts).styled(Style::Dashed)),
                Panel::new("second", "t [s]", "x [m]")
                    .with(Series::line("", vec![(0.0, 0.0), (1.0, 1.0)])),
            ],
            ..Figure::new()
        };
        let svg = fig.render().unwrap();
        for text in [
            "work-precision",
            "error [-]",
            "time [s]",
            "dopri5",
            "rk4",
            "second",
            "x [m]",
        ] {
            assert!(svg.contains(text), "{text} missing");
        }
        assert!(count(&svg, "<circle") >= 29);
    }

    #[test]
    fn empty_panel_is_an_error() {
        let fig = Figure {
            panels: vec![
                Panel::new("nothing", "x", "y").with(Series::line("a", vec![(f64::NAN, 1.0)])),
            ],
            ..Figure::new()
        };
        assert!(matches!(fig.render(), Err(OutputError::EmptyPlot { .. })));
    }
}
