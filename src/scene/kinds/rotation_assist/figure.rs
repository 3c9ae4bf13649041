//! The figure of a `rotation_assist` run: per rotation pair, the outcome
//! and the peak contact force over the error grid.

use super::{Row, rate_pairs};
use crate::output::plot::{Figure, Panel, Series, Style};

/// Per rotation pair: the outcome over the error grid (one marker series
/// per outcome, in the outcome's palette colour) and the peak contact
/// force (one marker series per force quartile of the whole sweep, in a
/// grey shade from light to black): a colour means one thing in every
/// panel, and no force band shares a colour with an outcome.
pub(super) fn heat_maps(rows: &[Row]) -> Figure {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::kinds::rotation_assist::Point;

    fn row(lateral: f64, angular_deg: f64, spin: f64, code: f64, peak: f64) -> Row {
        Row {
            point: Point {
                lateral,
                angular_deg,
                precession: 0.0,
                spin,
            },
            outcome: String::new(),
            code,
            end: 0.5,
            seated: code == 0.0,
            peak_contact: peak,
            peak_pressure: 0.0,
            peak_moment: 0.0,
            peak_wrist: 0.0,
        }
    }

    #[test]
    fn a_colour_means_one_thing_in_every_panel() {
        // Two rotation pairs, outcomes 0 to 3 and forces in every quartile.
        let mut rows = Vec::new();
        for (k, spin) in [0.0, 20.0].into_iter().enumerate() {
            for i in 0..4 {
                for j in 0..2 {
                    let code = ((i + j + k) % 4) as f64;
                    let peak = 10.0 * (1 + i + 4 * j + 8 * k) as f64;
                    rows.push(row(1e-4 * i as f64, 0.5 + j as f64, spin, code, peak));
                }
            }
        }
        let fig = heat_maps(&rows);
        assert_eq!(fig.panels.len(), 4);
        // name -> (palette colour, shade) over every panel.
        type Colour = (Option<usize>, Option<(usize, usize)>);
        let mut meaning: Vec<(String, Colour)> = Vec::new();
        for s in fig.panels.iter().flat_map(|p| &p.series) {
            assert!(s.color.is_some() || s.shade.is_some(), "{}", s.name);
            match meaning.iter().find(|m| m.0 == s.name) {
                Some(m) => assert_eq!(m.1, (s.color, s.shade), "{}", s.name),
                None => meaning.push((s.name.clone(), (s.color, s.shade))),
            }
        }
        // ... and a colour names one thing.
        for (i, a) in meaning.iter().enumerate() {
            for b in &meaning[i + 1..] {
                assert!(a.1 != b.1, "{} and {} share a colour", a.0, b.0);
            }
        }
        // Every outcome is in the palette, every force band a shade.
        let outcomes: Vec<&str> = crate::compliant_peg_3d::outcome::CODE_LEGEND
            .iter()
            .map(|(_, n)| *n)
            .collect();
        for (name, (colour, shade)) in &meaning {
            if outcomes.contains(&name.as_str()) {
                assert!(colour.is_some() && shade.is_none(), "{name}");
            } else {
                assert!(shade.is_some(), "{name}");
            }
        }
    }
}
