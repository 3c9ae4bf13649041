//! The data model of a plot, independent of the drawing backend: a
//! [`Figure`] is a column of [`Panel`]s; each panel has a title, axis labels
//! (put the unit in the label, e.g. `"t [s]"`), linear or logarithmic axes
//! ([`Scale`]) and several [`Series`]. Non-finite points (and non-positive
//! ones on a log axis) break a series into separate segments, so a series
//! with gaps is drawn by putting NaN in the gaps;
//! [`Series::split_feasible`] draws the stretches of one curve flagged
//! infeasible dashed, in the same colour. Rendering is in [`super::svg`].

/// Axis scaling.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Scale {
    /// Linear axis.
    #[default]
    Linear,
    /// Base-10 logarithmic axis; non-positive values are left out.
    Log,
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Style {
    /// A solid line.
    #[default]
    Solid,
    /// A dashed line (e.g. infeasible or extrapolated stretches).
    Dashed,
    /// Markers only, no line (e.g. work-precision points).
    Markers,
    /// A solid line with markers on the points.
    LineMarkers,
}

/// One curve of a panel.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; an empty name adds no legend entry.
    pub name: String,
    /// Points `(x, y)`; non-finite points break the line.
    pub points: Vec<(f64, f64)>,
    /// Line style.
    pub style: Style,
    /// Colour index into a fixed palette; `None` = the series' position.
    pub color: Option<usize>,
    /// A shade of the grey ramp instead, `(step, steps)`: step 0 light,
    /// step `steps − 1` black. For ordered bands of one quantity (e.g. a
    /// force's quartiles), so that they never share a colour with the
    /// palette's categories (e.g. outcomes) in the same figure.
    pub shade: Option<(usize, usize)>,
}

impl Series {
    /// A solid line.
    pub fn line(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            name: name.into(),
            points,
            style: Style::Solid,
            color: None,
            shade: None,
        }
    }

    /// The same series with another style.
    pub fn styled(mut self, style: Style) -> Self {
        self.style = style;
        self
    }

    /// The same series with a fixed palette colour.
    pub fn colored(mut self, color: usize) -> Self {
        self.color = Some(color);
        self
    }

    /// The same series in shade `step` of `steps` of the grey ramp (light
    /// to black; see [`Series::shade`]).
    pub fn shaded(mut self, step: usize, steps: usize) -> Self {
        self.shade = Some((step, steps));
        self
    }

    /// Splits one curve into a solid series over the stretches where
    /// `feasible[i]` holds and a dashed series (named `"<name> (infeasible)"`)
    /// over the others, both in palette colour `color`. Neighbouring points
    /// are shared at each switch so the curve stays connected.
    pub fn split_feasible(
        name: &str,
        points: &[(f64, f64)],
        feasible: &[bool],
        color: usize,
    ) -> [Series; 2] {
        let gap = (f64::NAN, f64::NAN);
        let ok = |i: usize| feasible.get(i).copied().unwrap_or(false);
        let solid = (0..points.len())
            .map(|i| if ok(i) { points[i] } else { gap })
            .collect();
        // Infeasible points plus their feasible neighbours, so that the
        // dashed stretch joins the solid ones.
        let near_bad =
            |i: usize| !ok(i) || (i > 0 && !ok(i - 1)) || (i + 1 < points.len() && !ok(i + 1));
        let dashed = (0..points.len())
            .map(|i| if near_bad(i) { points[i] } else { gap })
            .collect();
        [
            Series::line(name, solid).colored(color),
            Series::line(format!("{name} (infeasible)"), dashed)
                .styled(Style::Dashed)
                .colored(color),
        ]
    }
}

/// One chart: title, axis labels with units, legend, series.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Panel {
    /// Title above the chart.
    pub title: String,
    /// Horizontal axis label, with unit.
    pub x_label: String,
    /// Vertical axis label, with unit.
    pub y_label: String,
    /// Horizontal scaling.
    pub x_scale: Scale,
    /// Vertical scaling.
    pub y_scale: Scale,
    /// The curves.
    pub series: Vec<Series>,
}

impl Panel {
    /// An empty panel with linear axes.
    pub fn new(title: &str, x_label: &str, y_label: &str) -> Self {
        Panel {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            ..Panel::default()
        }
    }

    /// Adds a series.
    pub fn with(mut self, s: Series) -> Self {
        self.series.push(s);
        self
    }

    /// Sets the axis scales.
    pub fn scales(mut self, x: Scale, y: Scale) -> Self {
        self.x_scale = x;
        self.y_scale = y;
        self
    }
}

/// A column of panels rendered into one SVG.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Panels from top to bottom.
    pub panels: Vec<Panel>,
    /// Width in pixels.
    pub width: u32,
    /// Height of each panel in pixels.
    pub panel_height: u32,
}

impl Default for Figure {
    fn default() -> Self {
        Figure::new()
    }
}

impl Figure {
    /// An empty 800-pixel-wide figure, 360 pixels per panel.
    pub fn new() -> Self {
        Figure {
            panels: Vec::new(),
            width: 800,
            panel_height: 360,
        }
    }
}
