//! Where a panel's legend goes: in a corner (or an edge's middle) of the
//! plotting area that no data point or line passes through, computed from
//! the data in pixels; when every place is taken, the vertical axis is
//! extended upwards so that a band above the data holds the legend. The
//! legend never covers data.
//!
//! The legend's size is plotters' own estimate (its default 12-pixel
//! label font, 30-pixel symbol area and 10-pixel margins), its places
//! plotters' [`SeriesLabelPosition`]s, 5 pixels from the area's edges.

use plotters::element::MultiLineText;
use plotters::prelude::*;

use crate::output::plot::{Panel, Scale, Style};

/// Pixels kept free around the legend box (a marker's radius and a line's
/// width beyond the point).
const CLEARANCE: f64 = 5.0;

/// A place of the legend in the plotting area (plotters'
/// [`SeriesLabelPosition`] without its coordinates variant).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// The upper left corner.
    UpperLeft,
    /// The middle of the upper edge.
    UpperMiddle,
    /// The upper right corner.
    UpperRight,
    /// The middle of the left edge.
    MiddleLeft,
    /// The middle of the right edge.
    MiddleRight,
    /// The lower left corner.
    LowerLeft,
    /// The middle of the lower edge.
    LowerMiddle,
    /// The lower right corner.
    LowerRight,
}

impl Place {
    /// Plotters' name of the place.
    pub fn position(self) -> SeriesLabelPosition {
        match self {
            Place::UpperLeft => SeriesLabelPosition::UpperLeft,
            Place::UpperMiddle => SeriesLabelPosition::UpperMiddle,
            Place::UpperRight => SeriesLabelPosition::UpperRight,
            Place::MiddleLeft => SeriesLabelPosition::MiddleLeft,
            Place::MiddleRight => SeriesLabelPosition::MiddleRight,
            Place::LowerLeft => SeriesLabelPosition::LowerLeft,
            Place::LowerMiddle => SeriesLabelPosition::LowerMiddle,
            Place::LowerRight => SeriesLabelPosition::LowerRight,
        }
    }
}

/// Where a panel's legend is drawn and the vertical axis it needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plan {
    /// The legend's place in the plotting area.
    pub position: Place,
    /// The vertical axis range (the data's, or extended upwards).
    pub y: (f64, f64),
}

/// The places tried, in order: upper right first (where plotters puts a
/// legend by default, so a panel whose upper right is free is drawn as
/// before).
const PLACES: [Place; 8] = [
    Place::UpperRight,
    Place::UpperLeft,
    Place::LowerRight,
    Place::LowerLeft,
    Place::UpperMiddle,
    Place::LowerMiddle,
    Place::MiddleRight,
    Place::MiddleLeft,
];

/// A point of a panel in pixels of its plotting area, `(0, 0)` top left.
pub struct Mapping {
    /// The plotting area in pixels, width and height.
    pub size: (f64, f64),
    /// The horizontal axis: its range and scale.
    pub x: (f64, f64, Scale),
    /// The vertical axis: its range and scale.
    pub y: (f64, f64, Scale),
}

impl Mapping {
    fn axis(v: f64, (lo, hi, s): (f64, f64, Scale)) -> f64 {
        match s {
            Scale::Linear => (v - lo) / (hi - lo),
            Scale::Log => (v.ln() - lo.ln()) / (hi.ln() - lo.ln()),
        }
    }

    fn pixel(&self, p: (f64, f64)) -> (f64, f64) {
        let (w, h) = self.size;
        (
            w * Self::axis(p.0, self.x),
            h * (1.0 - Self::axis(p.1, self.y)),
        )
    }
}

/// The legend box's size in pixels for the labels `names`, as plotters
/// computes it.
pub fn legend_size(names: &[&str]) -> (f64, f64) {
    let font: TextStyle = ("sans-serif", 12).into_font().into();
    let mut text = MultiLineText::<_, &str>::new((0, 0), &font);
    for n in names {
        text.push_line(*n);
    }
    let (w, h) = text.estimate_dimension().unwrap_or((8 * 12, 16));
    (f64::from(w + 30 + 20), f64::from(h + 20))
}

/// The box of place `p` for a legend of `size` in an area of `area`
/// pixels: `(x0, y0, x1, y1)`, as plotters lays it out.
pub fn place(p: Place, size: (f64, f64), area: (f64, f64)) -> (f64, f64, f64, f64) {
    use Place::*;
    let (w, h) = size;
    let x = match p {
        UpperLeft | MiddleLeft | LowerLeft => 5.0,
        UpperMiddle | LowerMiddle => ((area.0 - w) / 2.0).floor(),
        UpperRight | MiddleRight | LowerRight => area.0 - w - 5.0,
    };
    let y = match p {
        UpperLeft | UpperMiddle | UpperRight => 5.0,
        MiddleLeft | MiddleRight => ((area.1 - h) / 2.0).floor(),
        LowerLeft | LowerMiddle | LowerRight => area.1 - h - 5.0,
    };
    (x, y, x + w, y + h)
}

/// Whether segment `a`–`b` meets the box `r` (Liang–Barsky clipping).
pub fn crosses(a: (f64, f64), b: (f64, f64), r: (f64, f64, f64, f64)) -> bool {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.0 - r.0),
        (dx, r.2 - a.0),
        (-dy, a.1 - r.1),
        (dy, r.3 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

/// Whether any drawn point or line of `panel` passes through box `r`
/// (grown by `CLEARANCE`).
pub fn covers(panel: &Panel, m: &Mapping, r: (f64, f64, f64, f64)) -> bool {
    let r = (
        r.0 - CLEARANCE,
        r.1 - CLEARANCE,
        r.2 + CLEARANCE,
        r.3 + CLEARANCE,
    );
    let drawable = |v: f64, s: Scale| v.is_finite() && (s == Scale::Linear || v > 0.0);
    panel.series.iter().any(|s| {
        let pixels: Vec<Option<(f64, f64)>> = s
            .points
            .iter()
            .map(|&(x, y)| {
                (drawable(x, panel.x_scale) && drawable(y, panel.y_scale)).then(|| {
                    let x = x.clamp(m.x.0, m.x.1);
                    let y = y.clamp(m.y.0, m.y.1);
                    m.pixel((x, y))
                })
            })
            .collect();
        match s.style {
            Style::Markers => pixels.iter().flatten().any(|&p| crosses(p, p, r)),
            _ => {
                pixels.iter().flatten().any(|&p| crosses(p, p, r))
                    || pixels.windows(2).any(|w| match (w[0], w[1]) {
                        (Some(a), Some(b)) => crosses(a, b, r),
                        _ => false,
                    })
            }
        }
    })
}

/// Where the legend of `panel` goes in a plotting area of `area` pixels
/// whose axes span `x` and `y`: the first place of `PLACES` free of
/// data, else the upper right with the vertical axis extended so that the
/// data stay below the legend. Panels without a legend keep their axes.
pub fn plan(panel: &Panel, area: (f64, f64), x: (f64, f64), y: (f64, f64)) -> Plan {
    // The series plotters labels: named, with a drawable point.
    let drawable = |v: f64, s: Scale| v.is_finite() && (s == Scale::Linear || v > 0.0);
    let names: Vec<&str> = panel
        .series
        .iter()
        .filter(|s| !s.name.is_empty())
        .filter(|s| {
            s.points
                .iter()
                .any(|&(x, y)| drawable(x, panel.x_scale) && drawable(y, panel.y_scale))
        })
        .map(|s| s.name.as_str())
        .collect();
    let upper_right = Plan {
        position: Place::UpperRight,
        y,
    };
    if names.is_empty() {
        return upper_right;
    }
    let size = legend_size(&names);
    let m = Mapping {
        size: area,
        x: (x.0, x.1, panel.x_scale),
        y: (y.0, y.1, panel.y_scale),
    };
    if let Some(position) = PLACES
        .into_iter()
        .find(|p| !covers(panel, &m, place(*p, size, area)))
    {
        return Plan { position, y };
    }
    // A band above the data: the old top maps below the legend's box.
    let band = size.1 + 2.0 * CLEARANCE + 5.0;
    if band > 0.6 * area.1 {
        // Taller than the band a plot can give up: where it was.
        return upper_right;
    }
    let keep = area.1 / (area.1 - band);
    let top = match panel.y_scale {
        Scale::Linear => y.0 + (y.1 - y.0) * keep,
        Scale::Log => y.0 * (y.1 / y.0).powf(keep),
    };
    Plan {
        position: Place::UpperRight,
        y: (y.0, top),
    }
}
