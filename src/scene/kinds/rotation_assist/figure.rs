//! The figure of a `rotation_assist` run: per rotation pair, the outcome
//! and the peak contact force over the error grid.

use super::{Row, rate_pairs};
use crate::output::plot::{Figure, Panel, Series, Style};

/// Per rotation pair: the outcome over the error grid (one marker series
/// per outcome, in the outcome's palette colour) and the peak contact
/// force (one marker series per force quartile of the whole sweep, in a
/// grey shade from light to black): a colour means one thing in every
/// panel, and no force band shares a colour with an outcome.
pub fn heat_maps(rows: &[Row]) -> Figure {
    let mut fig = Figure::new();
    let mut forces: Vec<f64> = rows.iter().map(|r| r.peak_contact).collect();
    forces.sort_by(f64::total_cmp);
    let q = |f: f64| forces[((forces.len() - 1) as f64 * f).round() as usize];
    let bands = [q(0.25), q(0.5), q(0.75)];
    for (pr, sr) in rate_pairs(rows) {
        let sel: Vec<&Row> = rows
            .iter()
            .filter(|r| r.point.precession == pr && r.point.spin == sr)
            .collect();
        let title = format!("ψ̇ = {pr} rad/s, φ̇ = {sr} rad/s");
        let mut a = Panel::new(
            &format!("Outcome, {title}"),
            "lateral error [mm]",
            "angular error [deg]",
        );
        for (code, name) in crate::compliant_peg_3d::outcome::CODE_LEGEND {
            let pts: Vec<(f64, f64)> = sel
                .iter()
                .filter(|r| r.code == code)
                .map(|r| (r.point.lateral * 1e3, r.point.angular_deg))
                .collect();
            if !pts.is_empty() {
                a = a.with(
                    Series::line(name, pts)
                        .styled(Style::Markers)
                        .colored(code as usize),
                );
            }
        }
        fig.panels.push(a);
        let mut b = Panel::new(
            &format!("Peak contact force, {title}"),
            "lateral error [mm]",
            "angular error [deg]",
        );
        for band in 0..4 {
            let lo = if band == 0 {
                f64::NEG_INFINITY
            } else {
                bands[band - 1]
            };
            let hi = if band == 3 {
                f64::INFINITY
            } else {
                bands[band]
            };
            let pts: Vec<(f64, f64)> = sel
                .iter()
                .filter(|r| r.peak_contact > lo && r.peak_contact <= hi)
                .map(|r| (r.point.lateral * 1e3, r.point.angular_deg))
                .collect();
            if !pts.is_empty() {
                let name = match band {
                    0 => format!("≤ {:.3} N", bands[0]),
                    3 => format!("> {:.3} N", bands[2]),
                    k => format!("{:.3}–{:.3} N", bands[k - 1], bands[k]),
                };
                b = b.with(
                    Series::line(name, pts)
                        .styled(Style::Markers)
                        .shaded(band, 4),
                );
            }
        }
        fig.panels.push(b);
    }
    fig
}
