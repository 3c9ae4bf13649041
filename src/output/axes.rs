//! The axes of a panel: the range over its drawable points, padded and
//! bounded so that plotters can draw it ([`bounds`], [`drawable_range`]),
//! and short tick labels ([`tick`]).

use crate::output::plot::{Panel, Scale};

/// Whether point coordinate `v` can be drawn on an axis of scale `s`.
pub(crate) fn drawable(v: f64, s: Scale) -> bool {
    v.is_finite() && (s == Scale::Linear || v > 0.0)
}

/// Largest magnitude an axis end may take: the axis width `hi − lo` must
/// stay finite (plotters' tick search divides by it and loops without end
/// on an infinite or NaN width). Points beyond are drawn off the chart.
const AXIS_LIMIT: f64 = 1e300;

/// Largest and inverse smallest end of a log axis: the ratio of the ends
/// must stay finite (plotters counts decades as `ln(end/start)` and loops
/// without end when it is infinite).
const LOG_AXIS_LIMIT: f64 = 1e150;

/// Smallest axis width relative to the largest magnitude on the axis:
/// below, ticks are closer than f64 resolves and plotters' tick search
/// never finds a spacing (it kept dividing the spacing by ten).
const MIN_RELATIVE_WIDTH: f64 = 1e-9;

/// Axis range over the drawable points of the panel, padded by 5 % on a
/// linear axis and to whole decades' fractions on a log axis, then made
/// safe to draw (`drawable_range`).
pub fn bounds(panel: &Panel, s: Scale, pick: impl Fn(&(f64, f64)) -> f64) -> Option<(f64, f64)> {
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
    Some(drawable_range(lo, hi, s))
}

/// The axis `[lo, hi]` (data extremes, `lo <= hi`) padded and bounded so
/// that its ends are within `±AXIS_LIMIT` (log: `[1/LOG_AXIS_LIMIT,
/// LOG_AXIS_LIMIT]`) and its width is at least `MIN_RELATIVE_WIDTH` of its
/// largest magnitude (log: a ratio of at least 4).
pub(crate) fn drawable_range(lo: f64, hi: f64, s: Scale) -> (f64, f64) {
    match s {
        Scale::Linear => {
            let (lo, hi) = (
                lo.clamp(-AXIS_LIMIT, AXIS_LIMIT),
                hi.clamp(-AXIS_LIMIT, AXIS_LIMIT),
            );
            let pad = if hi > lo {
                0.05 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            let (lo, hi) = (
                (lo - pad).max(-1.1 * AXIS_LIMIT),
                (hi + pad).min(1.1 * AXIS_LIMIT),
            );
            let magnitude = lo.abs().max(hi.abs());
            let half = 0.5 * MIN_RELATIVE_WIDTH * magnitude;
            if hi - lo >= 2.0 * half {
                (lo, hi)
            } else {
                let mid = 0.5 * lo + 0.5 * hi;
                (mid - half, mid + half)
            }
        }
        Scale::Log => {
            let (lo, hi) = (
                lo.clamp(1.0 / LOG_AXIS_LIMIT, LOG_AXIS_LIMIT),
                hi.clamp(1.0 / LOG_AXIS_LIMIT, LOG_AXIS_LIMIT),
            );
            if hi > 4.0 * lo {
                (lo / 1.2, hi * 1.2)
            } else {
                (lo / 2.0, hi * 2.0)
            }
        }
    }
}

/// A short tick label: `0` when `|v|` is below `1e-9 * span` (rounding
/// noise on a linear axis of width `span`), up to four decimals in
/// `[1e-3, 1e5)`, otherwise three significant digits in scientific
/// notation; trailing zeros dropped.
pub fn tick(v: f64, span: f64) -> String {
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
