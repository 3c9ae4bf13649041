//! The no-jam margins against depth: Whitney's parallelogram at each
//! contact separation, the wedging depth and the nominal insertion's load
//! ratio (`docs/insertion.md`, "Quasi-static theory of two-point contact").
//!
//! In two-point contact the mouth's innermost circle (`ρ_h` below the top
//! face) touches the peg's side and the rim's outermost circle (`ρ_p` above
//! the tip) the wall, so the contacts lie `l = z_tip − ρ_h − ρ_p` apart
//! along the axis (`z_tip` the tip's depth, m). At separation `l` the
//! no-jam region of the load ratio `q = (F_x/F_z, M/(r F_z))` (moment about
//! the tip) is Whitney's parallelogram with corners `(±1/μ, ±(1 + 2λ))`,
//! `(±1/μ, ±1)`, `λ = l/(2 r μ)`, and its two-point sliding lines
//! `M/(r F_z) = ±λ + μ (1 + λ) F_x/F_z`. Two-point contact exists from
//! `l = √(D² − d²)` (the peg across the bore) and can wedge while
//! `l < μ d`.

use crate::compliant_peg_3d::Peg3dParams;
use crate::compliant_peg_3d::outcome::{Outcome, two_point};
use crate::error::RunError;
use crate::jamming::PegHole;
use crate::jamming::diagram::whitney_parallelogram;
use crate::jamming::geometry::two_point_tilt;
use crate::output::csv::format_f64;
use crate::output::names::Part;
use crate::scene::context::RunContext;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::progress::Progress;
use crate::scene::shared::compliant_peg_3d::insertion::{Built, Run, outcome_text, run_one};
use crate::scene::shared::compliant_peg_3d::margins::ratio;
use crate::scene::shared::compliant_peg_3d::output::samples;
use crate::scene::summary::Metric;

/// Rows of the depth table.
pub const ROWS: usize = 64;

/// The nominal insertion's result.
#[derive(Debug, Clone)]
pub struct Nominal {
    /// How it ended.
    pub outcome: Outcome,
    /// End time (s).
    pub end: f64,
    /// `(t, q, tip depth)` of each output sample in two-point contact in
    /// the bore, pushed in.
    pub ratio: Vec<(f64, [f64; 2], f64)>,
    /// Tip depth of the first output sample in two-point contact (m).
    pub two_point_from: Option<f64>,
}

/// Integrates the nominal insertion and extracts its load ratio; with
/// `track`, the contact transitions are located too (for the replay page:
/// the same trajectory, the transitions only observe it) and the run is
/// handed back.
///
/// # Errors
/// The integrator's refusal or a Hertz setup error.
pub fn nominal(
    b: &Built,
    spec: &IntegratorSpec,
    track: bool,
) -> Result<(Nominal, Option<Run>), RunError> {
    let run = run_one(b, spec, track, &mut Progress::silent())?;
    let s = samples(&run.system, &run.solution)?;
    let two_point_from = s
        .rows
        .iter()
        .find(|(_, _, smp)| {
            two_point(smp.forces.iter().map(|f| f.contact.pair))
                && smp.depth > b.params.mouth_fillet
        })
        .map(|(_, _, smp)| smp.depth);
    let nominal = Nominal {
        outcome: run.outcome.clone(),
        end: run.solution.t_final,
        ratio: ratio(&b.params, &s),
        two_point_from,
    };
    Ok((nominal, track.then_some(run)))
}

impl Nominal {
    /// The nominal run's metrics.
    pub fn metrics(&self, prm: &Peg3dParams, clearance_ratio: f64) -> Vec<Metric> {
        let mut m = vec![
            Metric::coded(
                "nominal run outcome",
                self.outcome.code(),
                outcome_text(&self.outcome),
            ),
            Metric::new("nominal run end time", self.end, "s"),
        ];
        if let Some(d) = self.two_point_from {
            m.push(Metric::new(
                "nominal run: simulated two-point contact from depth",
                d,
                "m",
            ));
        }
        let hole = PegHole::try_new(prm.peg_radius(), clearance_ratio, prm.friction.max(1e-6));
        if let Ok(hole) = hole {
            let worst = self
                .ratio
                .iter()
                .filter_map(|(_, q, z)| {
                    let g = whitney_parallelogram(&hole, separation(prm, *z)).ok()?;
                    Some(g.margin(*q))
                })
                .fold(f64::INFINITY, f64::min);
            if worst.is_finite() {
                m.push(Metric::new(
                    "nominal run: smallest no-jam margin in two-point contact (negative: outside)",
                    worst,
                    "",
                ));
            }
        }
        m
    }
}

/// The contact separation `l = z_tip − ρ_h − ρ_p` at tip depth `z` (m).
pub fn separation(prm: &Peg3dParams, z: f64) -> f64 {
    z - prm.mouth_fillet - prm.rim_fillet
}

/// One row of the depth table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// Tip depth (m).
    pub tip_depth: f64,
    /// Contact separation `l` (m).
    pub separation: f64,
    /// The exact two-point tilt at `l` (rad).
    pub tilt: Option<f64>,
    /// `λ = l/(2 r μ)`.
    pub lambda: f64,
    /// `l < μ d`.
    pub wedging_possible: bool,
    /// `μ` of the parallelogram (the scene's, at least 1e-6).
    pub friction: f64,
    /// The nominal run's load ratio at the nearest sample within half a
    /// row spacing, and its signed distance to the parallelogram's edges.
    pub simulated: Option<([f64; 2], f64)>,
}

/// The depth table from the first depth of two-point contact,
/// `ρ_h + ρ_p + √(D² − d²)`, to `seat` (m), `ROWS` rows; `path` is the
/// nominal run's load ratio. Empty when two-point contact cannot occur
/// above the seat.
pub fn table(
    prm: &Peg3dParams,
    clearance_ratio: f64,
    seat: f64,
    path: &[(f64, [f64; 2], f64)],
) -> Vec<Row> {
    let Ok(hole) = PegHole::try_new(prm.peg_radius(), clearance_ratio, prm.friction.max(1e-6))
    else {
        return Vec::new();
    };
    let (big, small) = (prm.hole_diameter, prm.peg_diameter);
    let start = prm.mouth_fillet + prm.rim_fillet + (big * big - small * small).sqrt();
    if start >= seat {
        return Vec::new();
    }
    let step = (seat - start) / (ROWS - 1) as f64;
    (0..ROWS)
        .map(|i| {
            let z = start + step * i as f64;
            let l = separation(prm, z);
            let simulated = path
                .iter()
                .filter(|(_, _, d)| (d - z).abs() <= 0.5 * step)
                .min_by(|a, b| (a.2 - z).abs().total_cmp(&(b.2 - z).abs()))
                .and_then(|(_, q, d)| {
                    let g = whitney_parallelogram(&hole, separation(prm, *d)).ok()?;
                    Some((*q, g.margin(*q)))
                });
            Row {
                tip_depth: z,
                separation: l,
                tilt: two_point_tilt(&hole, l).ok().flatten(),
                lambda: hole.lambda(l),
                wedging_possible: l < prm.friction * small,
                friction: hole.mu(),
                simulated,
            }
        })
        .collect()
}

/// Writes `<name>.depth.csv`.
///
/// # Errors
/// An output error.
pub fn write(ctx: &RunContext, rows: &[Row]) -> Result<(), RunError> {
    let mut csv = ctx.table(
        Part::Sub("depth"),
        &[
            "tip_depth_m",
            "separation_m",
            "two_point_tilt_rad",
            "lambda",
            "wedging_possible",
            "no_jam_edge_fx_over_fz",
            "sliding_line_intercept",
            "sliding_line_slope",
            "simulated_fx_over_fz",
            "simulated_m_over_rfz",
            "simulated_no_jam_margin",
        ],
    )?;
    let opt = |v: Option<f64>| v.map(format_f64).unwrap_or_default();
    for r in rows {
        csv.row_cells(&[
            &format_f64(r.tip_depth),
            &format_f64(r.separation),
            &opt(r.tilt),
            &format_f64(r.lambda),
            if r.wedging_possible { "1" } else { "0" },
            &format_f64(1.0 / r.friction),
            &format_f64(r.lambda),
            &format_f64(r.friction * (1.0 + r.lambda)),
            &opt(r.simulated.map(|s| s.0[0])),
            &opt(r.simulated.map(|s| s.0[1])),
            &opt(r.simulated.map(|s| s.1)),
        ])?;
    }
    Ok(csv.finish()?)
}
