//! The two figures of `design_margins`: the success region over the error
//! grid with the capture rule's boundaries, and Whitney's no-jam region
//! with the nominal run's load ratio.

use super::depth::{Nominal, Row, separation};
use super::design::{Design, GridRun};
use crate::jamming::PegHole;
use crate::jamming::diagram::whitney_parallelogram;
use crate::output::plot::{Figure, Panel, Series, Style};

/// Points along the boundary curves.
const BOUNDARY_POINTS: usize = 81;

/// The success region: the simulated outcome at each grid point (lateral
/// error of the compliance centre in mm, angular error in degrees), the
/// edges of the capture rule's accepted band, and the points where rule
/// and simulation disagree.
pub fn region(d: &Design, rows: &[GridRun]) -> Figure {
    let mm = 1e3;
    let mut panel = Panel::new(
        "Success region: simulated outcome and the chamfer's capture rule",
        "lateral error of the compliance centre [mm]",
        "angular error [deg]",
    );
    for (code, name) in crate::compliant_peg_3d::outcome::CODE_LEGEND {
        let pts: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.outcome.code() == code)
            .map(|r| (r.point.centre_lateral * mm, r.point.angular_deg))
            .collect();
        if !pts.is_empty() {
            panel = panel.with(
                Series::line(format!("simulated: {name}"), pts)
                    .styled(Style::Markers)
                    .colored(code as usize),
            );
        }
    }
    let angles = &d.scene.grid.angular_errors_deg;
    let lo = angles.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = angles.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        (lo - 1.0, hi + 1.0)
    };
    let dir = d.scene.robot.lateral_error_direction_deg.to_radians();
    let az = d.scene.robot.tilt_direction_deg.to_radians();
    // The frictionless rule is left out: on the raised side of a tilted
    // rim any inward lean of the round's normal passes it, so its band
    // reaches almost to the mouth's radius.
    for (frictionless, label, style, color) in [(false, "capture rule", Style::Solid, 7)] {
        let mut lower = Vec::new();
        let mut upper = Vec::new();
        for k in 0..BOUNDARY_POINTS {
            let deg = lo + (hi - lo) * k as f64 / (BOUNDARY_POINTS - 1) as f64;
            if let Some((a, b)) = d.capture.boundary(dir, deg.to_radians(), az, frictionless) {
                lower.push((a * mm, deg));
                upper.push((b * mm, deg));
            }
        }
        for (side, pts) in [("lower", lower), ("upper", upper)] {
            if !pts.is_empty() {
                panel = panel.with(
                    Series::line(format!("{label} ({side} edge)"), pts)
                        .styled(style)
                        .colored(color),
                );
            }
        }
    }
    let off: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| !r.agrees())
        .map(|r| (r.point.centre_lateral * mm, r.point.angular_deg))
        .collect();
    if !off.is_empty() {
        panel = panel.with(
            Series::line("rule and simulation disagree", off)
                .styled(Style::Markers)
                .colored(9),
        );
    }
    let mut fig = Figure::new();
    fig.panels.push(panel);
    fig
}

/// Whitney's no-jam parallelogram at the first, middle and last depth of
/// the table with the nominal run's load ratio; and the ratio's signed
/// distance to the parallelogram against the tip depth, with the wedging
/// and two-point depths.
pub fn nojam(d: &Design, table: &[Row], nominal: &Nominal) -> Figure {
    let prm = &d.nominal.params;
    let mm = 1e3;
    let mut a = Panel::new(
        "Load ratio of the wrist against Whitney's no-jam region",
        "F_x / F_z",
        "M / (r F_z)",
    );
    if !nominal.ratio.is_empty() {
        a = a.with(
            Series::line(
                "nominal run (wrist and gravity at the tip)",
                nominal.ratio.iter().map(|(_, q, _)| (q[0], q[1])).collect(),
            )
            .styled(Style::LineMarkers),
        );
    }
    let hole = PegHole::try_new(
        prm.peg_radius(),
        d.scene.peg.clearance_ratio,
        prm.friction.max(1e-6),
    );
    let picks: Vec<&Row> = match table {
        [] => Vec::new(),
        [one] => vec![one],
        _ => vec![&table[0], &table[table.len() / 2], &table[table.len() - 1]],
    };
    if let Ok(hole) = &hole {
        for (k, r) in picks.iter().enumerate() {
            if let Ok(g) = whitney_parallelogram(hole, r.separation) {
                let mut pts: Vec<(f64, f64)> = g.corners.iter().map(|c| (c[0], c[1])).collect();
                pts.push(pts[0]);
                a = a.with(
                    Series::line(
                        format!("no-jam region at tip depth {:.2} mm", r.tip_depth * mm),
                        pts,
                    )
                    .styled(Style::Dashed)
                    .colored(k + 2),
                );
            }
        }
    }
    let mut b = Panel::new(
        "No-jam margin of the nominal run against depth (positive: inside)",
        "tip depth [mm]",
        "signed distance to the parallelogram",
    );
    let margins: Vec<(f64, f64)> = match &hole {
        Ok(hole) => nominal
            .ratio
            .iter()
            .filter_map(|(_, q, z)| {
                let g = whitney_parallelogram(hole, separation(prm, *z)).ok()?;
                Some((z * mm, g.margin(*q)))
            })
            .collect(),
        Err(_) => Vec::new(),
    };
    let (mut ylo, mut yhi) = margins
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.1), b.max(p.1))
        });
    if !(ylo.is_finite() && yhi.is_finite()) || yhi <= ylo {
        (ylo, yhi) = (-1.0, 1.0);
    }
    if !margins.is_empty() {
        let xs = (margins[0].0, margins[margins.len() - 1].0);
        b = b
            .with(Series::line("simulated", margins).styled(Style::LineMarkers))
            .with(
                Series::line("zero: on the sliding line", vec![(xs.0, 0.0), (xs.1, 0.0)])
                    .styled(Style::Dashed)
                    .colored(7),
            );
    }
    let wedge = prm.friction * prm.peg_diameter + prm.mouth_fillet + prm.rim_fillet;
    b = b.with(
        Series::line(
            "wedging possible shallower than l = mu d",
            vec![(wedge * mm, ylo), (wedge * mm, yhi)],
        )
        .styled(Style::Dashed)
        .colored(3),
    );
    let theta = d.nominal.held.robot.tilt.abs();
    if theta > 0.0 {
        let z2 = prm.mouth_fillet + prm.rim_fillet + (prm.hole_diameter - prm.peg_diameter) / theta;
        b = b.with(
            Series::line(
                "analytic two-point depth at the nominal angular error",
                vec![(z2 * mm, ylo), (z2 * mm, yhi)],
            )
            .styled(Style::Dashed)
            .colored(4),
        );
    }
    let mut fig = Figure::new();
    fig.panels.push(a);
    fig.panels.push(b);
    fig
}
