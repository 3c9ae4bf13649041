//! Scene kind `design_margins`: for a peg, hole, friction and wrist (the
//! `insert_rcc` description), the margins a designer reads, each analytic
//! prediction drawn over the simulated one (`docs/insertion.md`, "Design
//! margins"):
//!
//! - the chamfer's capture rule ([`chamfer`]) against a sweep of the
//!   insertion over a grid of initial lateral (of the compliance centre) ×
//!   angular errors, in parallel (rayon) with a progress line;
//! - Whitney's no-jam region at each depth, the wedging depth and the
//!   two-point depth ([`depth`]) against the load ratio of the wrist in the
//!   nominal insertion (the `[robot]` table's own errors).
//!
//! The `[peg]`, `[wrist]`, `[robot]`, `[criteria]` and `[integrator]`
//! tables are those of `insert_rcc`; `[grid]`:
//!
//! ```toml
//! [grid]
//! centre_lateral_errors = [-1.2e-3, 0.0, 1.2e-3]  # m, of the compliance centre
//! angular_errors_deg = [-2.0, 0.0, 2.0]           # tilt towards robot.tilt_direction_deg
//! seat_depth = 0.003      # m, optional: the grid runs' seat (default criteria.seat_depth)
//! ```
//!
//! The errors lie along `robot.lateral_error_direction_deg`; the robot
//! places the tip at `e_c − L_c sin θ (cos ψ, sin ψ)`.
//!
//! Writes `<name>.csv` (one row per grid point), `<name>.depth.csv` (the
//! analytic margins against depth with the nominal run's load ratio),
//! `<name>.svg` (the success region: simulated outcome per grid point with
//! the capture rule's boundaries) and `<name>.nojam.svg` (Whitney's no-jam
//! region at several depths with the wrist's load ratio, and the margin
//! against depth) and the replay page `<name>.html` of one run:
//! `replay.run = "nominal"` (default), `"worst"` or a grid index.
//!
//! With a `[sensitivities]` table it also writes the capture widths'
//! derivatives with respect to the named fields ([`sensitivities`]):
//! `<name>.sensitivities.csv`, the tornado plot
//! `<name>.sensitivities.svg` and the ranking in the summary.

pub mod chamfer;
pub mod chamfer_sensitivity;
pub mod depth;
pub mod design;
mod figures;
pub mod ranges;
pub mod report;
pub mod sensitivities;

pub use design::{Checked, Design, DesignScene, GridRun, GridTable, Point};

use crate::error::{RunError, SceneErrors};
use crate::output::names::Part;
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::limits::WorkItem;
use crate::scene::numbers::significant;
use crate::scene::shared::compliant_peg_3d::insertion::Built;
use crate::scene::shared::compliant_peg_3d::ranges as peg_3d;
use crate::scene::shared::compliant_peg_3d::replay;
use crate::scene::shared::replay::RunChoice;
use crate::scene::shared::sensitivities::output;
use crate::scene::summary::RunSummary;

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "design_margins",
    about: "design margins of a compliant-wrist insertion: chamfer capture and no-jam, analytic over simulated",
    parse,
    ranges: &[
        peg_3d::PEG,
        peg_3d::WRIST,
        peg_3d::ROBOT,
        peg_3d::CRITERIA,
        ranges::GRID,
    ],
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: DesignScene = doc.body()?;
    Ok(Box::new(s.checked()?))
}

impl Written for Checked {
    fn work(&self) -> Vec<WorkItem> {
        let mut w = self.scene.integrator.work("integrator");
        // Every point's insertion is built before the runs start, and
        // every run keeps its row; one more run is the nominal insertion.
        let each = std::mem::size_of::<(Point, Built)>() + std::mem::size_of::<GridRun>();
        w.push(WorkItem::new(
            "grid",
            "max_runs",
            self.grid_points() + 1.0,
            each as f64,
        ));
        w
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        Ok(Box::new(Checked::build(*self)?))
    }
}

impl Scene for Design {
    fn describe(&self) -> String {
        let w = &self.nominal.held.wrist;
        format!(
            "design margins: D = {} m, c = {}, mu = {}, L_c = {} m, K_x = {} N/m, K_theta = {} N m/rad; \
             {} insertions ({} centre lateral x {} angular errors) and the nominal one; {} ({})",
            significant(self.nominal.params.hole_diameter),
            significant(self.scene.peg.clearance_ratio),
            significant(self.nominal.params.friction),
            significant(w.centre_height),
            significant(w.lateral[0]),
            significant(w.angular),
            self.points.len(),
            self.scene.grid.centre_lateral_errors.len(),
            self.scene.grid.angular_errors_deg.len(),
            self.integrator.describe(),
            self.method_reason
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let page = self.scene.replay.wanted(ctx);
        let choice = self.scene.replay.run.unwrap_or(RunChoice::Nominal);
        let track = page && choice == RunChoice::Nominal;
        let (nominal, grid) = {
            let progress = &mut ctx.progress;
            rayon::join(
                || depth::nominal(&self.nominal, &self.integrator, track),
                || self.run_grid(progress),
            )
        };
        let (nominal, nominal_run) = nominal?;
        let rows = grid?;
        report::write_grid(ctx, &rows)?;
        let table = depth::table(
            &self.nominal.params,
            self.scene.peg.clearance_ratio,
            self.nominal.criteria.seat_depth,
            &nominal.ratio,
        );
        depth::write(ctx, &table)?;
        ctx.figure(Part::Main, &figures::region(self, &rows))?;
        ctx.figure(Part::Sub("nojam"), &figures::nojam(self, &table, &nominal))?;
        let mut metrics = report::analytic_metrics(self);
        metrics.extend(nominal.metrics(&self.nominal.params, self.scene.peg.clearance_ratio));
        metrics.extend(report::grid_metrics(&rows));
        if let Some(chosen) = &self.sensitivities {
            let fields = sensitivities::CaptureFields {
                hole_diameter: self.nominal.params.hole_diameter,
                clearance_ratio: self.scene.peg.clearance_ratio,
            };
            let rows = sensitivities::rows(&self.capture, fields, chosen);
            metrics.extend(output::write(ctx, &rows, &sensitivities::METRICS, "")?);
        }
        if page {
            let outcomes: Vec<(bool, f64)> = rows.iter().map(|r| (r.seated(), r.end)).collect();
            let describe = |p: &Point| {
                format!(
                    "compliance centre's lateral error {} m, angular error {} deg",
                    p.centre_lateral, p.angular_deg
                )
            };
            replay::write_grid(
                ctx,
                choice,
                &outcomes,
                &self.points,
                describe,
                &self.integrator,
                || Ok(nominal_run),
            )?;
        }
        Ok(RunSummary {
            metrics,
            ..RunSummary::default()
        })
    }
}
