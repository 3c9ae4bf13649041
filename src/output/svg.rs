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
use crate::output::axes::{bounds, drawable, tick};
use crate::output::legend;
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

/// Shade `step` of `steps` of the grey ramp: from light grey (170) at
/// step 0 to black at the last step.
fn shade(step: usize, steps: usize) -> RGBColor {
    let last = steps.saturating_sub(1).max(1) as f64;
    let level = (170.0 * (1.0 - (step as f64 / last).min(1.0))).round() as u8;
    RGBColor(level, level, level)
}

impl Figure {
    /// Renders to an SVG string.
    pub fn render(&self) -> Result<String, OutputError> {
        self.render_for(Path::new("<memory>"))
    }

    /// Renders and writes to `path` (whole or not at all, [`super::atomic`]).
    /// A scene draws its figures through its run context
    /// ([`super::sink::Sink::figure`]) instead.
    pub fn save(&self, path: &Path) -> Result<(), OutputError> {
        let svg = self.render_for(path)?;
        super::atomic::write(path, svg.as_bytes())
    }

    /// Refuses a panel without a drawable point, as drawing does, naming
    /// `path` (the figure is not drawn).
    pub(crate) fn check_drawable(&self, path: &Path) -> Result<(), OutputError> {
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

    /// Renders to an SVG string, naming `path` in errors.
    pub(crate) fn render_for(&self, path: &Path) -> Result<String, OutputError> {
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
                let plan = legend::plan(panel, plotting_area(area.dim_in_pixel(), panel), x, y);
                let (y, legend) = (plan.y, plan.position);
                let (xs, ys) = (x.1 - x.0, y.1 - y.0);
                let (xl, yl) = ((x.0..x.1).log_scale(), (y.0..y.1).log_scale());
                let (xr, yr) = (x.0..x.1, y.0..y.1);
                let clip = (x, y);
                let (area, l) = ((area, panel), legend);
                let r = match (panel.x_scale, panel.y_scale) {
                    (Scale::Linear, Scale::Linear) => draw(area, clip, (xr, xs), (yr, ys), l),
                    (Scale::Linear, Scale::Log) => draw(area, clip, (xr, xs), (yl, 0.0), l),
                    (Scale::Log, Scale::Linear) => draw(area, clip, (xl, 0.0), (yr, ys), l),
                    (Scale::Log, Scale::Log) => draw(area, clip, (xl, 0.0), (yl, 0.0), l),
                };
                r.map_err(plot_err)?;
            }
            root.present().map_err(|e| plot_err(e.to_string()))?;
        }
        Ok(svg)
    }
}

/// The chart layout of every panel: title, margins, axis label areas.
fn chart<'a, 'b, DB: DrawingBackend + 'a>(
    area: &'a DrawingArea<DB, Shift>,
    title: &'b str,
) -> ChartBuilder<'a, 'b, DB> {
    let mut b = ChartBuilder::on(area);
    b.caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70);
    b
}

/// The size in pixels of the plotting area of `panel` in an area of
/// `dims` pixels (the layout of [`chart`], measured on a scratch drawing).
fn plotting_area(dims: (u32, u32), panel: &Panel) -> (f64, f64) {
    let mut scratch = String::new();
    let root = SVGBackend::with_string(&mut scratch, dims).into_drawing_area();
    chart(&root, &panel.title)
        .build_cartesian_2d(0.0..1.0, 0.0..1.0)
        .map(|c| {
            let (w, h) = c.plotting_area().dim_in_pixel();
            (f64::from(w), f64::from(h))
        })
        .unwrap_or((f64::from(dims.0), f64::from(dims.1)))
}

/// Splits points into runs of drawable points.
#[doc(hidden)]
pub fn segments(points: &[(f64, f64)], xs: Scale, ys: Scale) -> Vec<Vec<(f64, f64)>> {
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
    (area, panel): (&DrawingArea<SVGBackend<'_>, Shift>, &Panel),
    clip: ((f64, f64), (f64, f64)),
    (x, x_span): (X, f64),
    (y, y_span): (Y, f64),
    legend: legend::Place,
) -> Result<(), String>
where
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let mut chart = chart(area, &panel.title)
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
        let color = match s.shade {
            Some((step, steps)) => shade(step, steps),
            None => PALETTE[s.color.unwrap_or(i) % PALETTE.len()],
        };
        let line = ShapeStyle::from(color).stroke_width(2);
        let mut labelled = s.name.is_empty();
        for seg in segments(&s.points, panel.x_scale, panel.y_scale) {
            // Points beyond a bounded axis (|v| > AXIS_LIMIT) are drawn at
            // its edge: plotters' pixel arithmetic overflows far outside.
            let ((x0, x1), (y0, y1)) = clip;
            let seg: Vec<(f64, f64)> = seg
                .into_iter()
                .map(|(x, y)| (x.clamp(x0, x1), y.clamp(y0, y1)))
                .collect();
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
                // One element type for every style: a dashed legend is two
                // short strokes, a solid one a full stroke and an empty one,
                // a marker series its marker (a ring) and an empty stroke.
                let (a, b) = if style == Style::Dashed {
                    (7, 13)
                } else {
                    (20, 20)
                };
                let first: Vec<(i32, i32)> = if style == Style::Markers {
                    // A small closed ring about the symbol's middle: the
                    // marker, drawn with the line's 2-pixel stroke.
                    vec![(12, 0), (11, 2), (9, 2), (8, 0), (9, -2), (11, -2), (12, 0)]
                } else {
                    vec![(0, 0), (a, 0)]
                };
                anno.label(s.name.as_str()).legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(first.clone(), line)
                        + PathElement::new(vec![(b, 0), (20, 0)], line)
                });
            }
        }
    }
    if panel.series.iter().any(|s| !s.name.is_empty()) {
        chart
            .configure_series_labels()
            .position(legend.position())
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}
