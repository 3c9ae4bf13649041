//! The `design_margins` summary and per-grid-point table.

use super::chamfer::Touch;
use super::design::{Design, GridRun};
use crate::error::RunError;
use crate::output::csv::format_f64;
use crate::output::names::Part;
use crate::scene::context::RunContext;
use crate::scene::numbers::significant;
use crate::scene::shared::compliant_peg_3d::insertion::outcome_text;
use crate::scene::summary::Metric;

/// The analytic margins of `d`'s peg, hole and wrist.
pub fn analytic_metrics(d: &Design) -> Vec<Metric> {
    let c = &d.capture;
    let p = &d.nominal.params;
    let mut m = vec![
        Metric::new(
            "chamfer accepts aligned tip errors below (R - r) + rho_h + rho_p (frictionless)",
            c.frictionless_width() - (c.peg_radius - c.rim_fillet),
            "m",
        ),
        Metric::new(
            "chamfer accepts aligned tip errors below W_mu - (r - rho_p), with friction",
            c.aligned_tip_error(),
            "m",
        ),
        Metric::new(
            "tip error per degree of angular error, L_c sin(1 deg)",
            c.centre_height * 1f64.to_radians().sin(),
            "m",
        ),
        Metric::new(
            "wedging possible for two-point contacts closer than l = mu d",
            p.friction * p.peg_diameter,
            "m",
        ),
    ];
    let theta = d.nominal.held.robot.tilt.abs();
    if theta > 0.0 {
        m.push(Metric::new(
            "two-point depth rho_h + rho_p + (D - d)/theta0 at the nominal angular error",
            p.mouth_fillet + p.rim_fillet + (p.hole_diameter - p.peg_diameter) / theta,
            "m",
        ));
    }
    m
}

/// The grid's counts and every disagreement, named.
pub fn grid_metrics(rows: &[GridRun]) -> Vec<Metric> {
    let seated = rows.iter().filter(|r| r.seated()).count();
    let accepted = rows.iter().filter(|r| r.verdict.accepts()).count();
    let agree = rows.iter().filter(|r| r.agrees()).count();
    let mut m = vec![
        Metric::new("grid runs", rows.len() as f64, ""),
        Metric::new("grid runs seated", seated as f64, ""),
        Metric::new("grid points the capture rule accepts", accepted as f64, ""),
        Metric::new(
            format!(
                "grid points the capture rule classifies as the simulation (of {})",
                rows.len()
            ),
            agree as f64,
            "",
        ),
    ];
    for r in rows.iter().filter(|r| !r.agrees()) {
        m.push(Metric::new(
            format!(
                "disagreement at e_c = {} m, {} deg: rule {}, simulated {} (rule margin, m)",
                significant(r.point.centre_lateral),
                significant(r.point.angular_deg),
                if r.verdict.accepts() {
                    "accepts"
                } else {
                    "rejects"
                },
                r.outcome.name()
            ),
            r.verdict.margin,
            "m",
        ));
    }
    m
}

/// Writes `<name>.csv`, one row per grid point.
///
/// # Errors
/// An output error.
pub fn write_grid(ctx: &RunContext, rows: &[GridRun]) -> Result<(), RunError> {
    let mut csv = ctx.table(
        Part::Main,
        &[
            "centre_lateral_error_m",
            "angular_error_deg",
            "tip_error_x_m",
            "tip_error_y_m",
            "rule_margin_m",
            "rule_frictionless_margin_m",
            "rule_accepts",
            "rule_first_touch",
            "rule_touch_angle_deg",
            "outcome",
            "outcome_code",
            "seated",
            "agrees",
            "end_time_s",
            "insertion_time_s",
            "end_depth_m",
            "end_contacts",
            "peak_contact_N",
            "peak_wrist_force_N",
        ],
    )?;
    let flag = |b: bool| if b { "1" } else { "0" };
    for r in rows {
        csv.row_cells(&[
            &format_f64(r.point.centre_lateral),
            &format_f64(r.point.angular_deg),
            &format_f64(r.verdict.tip[0]),
            &format_f64(r.verdict.tip[1]),
            &format_f64(r.verdict.margin),
            &format_f64(r.verdict.frictionless_margin),
            flag(r.verdict.accepts()),
            match r.verdict.touch {
                Touch::Round { .. } => "round",
                Touch::TopFace { .. } => "top_face",
                Touch::None => "none",
            },
            &match r.verdict.touch {
                Touch::Round { alpha, .. } => format_f64(alpha.to_degrees()),
                _ => String::new(),
            },
            &outcome_text(&r.outcome),
            &format_f64(r.outcome.code()),
            flag(r.seated()),
            flag(r.agrees()),
            &format_f64(r.end),
            &if r.seated() {
                format_f64(r.end)
            } else {
                String::new()
            },
            &format_f64(r.end_depth),
            &r.end_contacts,
            &format_f64(r.peak_contact),
            &format_f64(r.peak_wrist),
        ])?;
    }
    Ok(csv.finish()?)
}
