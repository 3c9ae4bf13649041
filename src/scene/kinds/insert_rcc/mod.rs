//! Scene kind `insert_rcc`: a robot inserts the compliant 3-D peg through
//! a compliant wrist (remote centre compliance) from a start pose with
//! lateral and angular errors, descending at a speed or under a constant
//! axial force, optionally precessing, spinning or searching on a spiral.
//! The run ends with an [`Outcome`](crate::compliant_peg_3d::outcome::Outcome) (seated, jammed, wedged, missed, force
//! limit, or an integrator stop).
//!
//! ```toml
//! kind = "insert_rcc"
//! [peg]
//! hole_diameter = 0.025
//! clearance_ratio = 0.003
//! length = 0.05
//! rim_fillet = 0.0003
//! mouth_fillet = 0.0005          # the 0.5 mm "chamfer", rounded
//! bore_depth = 0.03
//! density = 7850.0
//! friction = 0.2
//! [wrist]
//! centre_height = 0.0            # compliance centre at the tip
//! lateral_stiffness = 2.0e4      # N/m
//! axial_stiffness = 2.0e5        # N/m
//! angular_stiffness = 20.0       # N m/rad
//! torsional_stiffness = 20.0     # N m/rad
//! lateral_damping = 20.0         # N s/m
//! axial_damping = 200.0          # N s/m
//! angular_damping = 0.02         # N m s/rad
//! [robot]
//! lateral_error = 3e-4           # m
//! angular_error_deg = 1.0
//! start_height = 5e-4            # tip above the top face, m
//! speed = 0.01                   # m/s
//! [criteria]
//! seat_depth = 0.01              # m
//! wrist_force_limit = 200.0      # N
//! contact_force_limit = 2000.0   # N
//! [integrator]
//! method = "dopri5"
//! t_end = 2.0
//! output_interval = 1e-3
//! ```
//!
//! Writes `<name>.csv` (time series), `<name>.events.csv` (contact
//! transitions), `<name>.svg` (Whitney's plot: insertion force and the
//! wrist's lateral force and moment against depth; contact forces and the
//! contact-state timeline against time), `<name>.views.svg` and the replay
//! page `<name>.html` (`docs/replay.md`; `[replay] page = false` or
//! `pegdyn run --no-replay` turns it off). An optional `[sensitivities]`
//! table adds the derivatives of the insertion's metrics in design fields
//! ([`sensitivities`]): `<name>.sensitivities.csv`, a tornado plot and a
//! ranking in the summary.

pub mod sensitivities;

use crate::compliant_peg_3d::outcome::TERMINAL_NAMES;
use crate::error::{RunError, SceneErrors};
use crate::integrate::StopReason;
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series};
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::integrator::{DefaultMethod, IntegratorSpec};
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::limits::WorkItem;
use crate::scene::numbers::significant;
use crate::scene::shared::compliant_peg_3d::insertion::{Built, RccScene, outcome_text, run_one};
use crate::scene::shared::compliant_peg_3d::replay::insertion;
use crate::scene::shared::compliant_peg_3d::{margins, output, ranges, timescales};
use crate::scene::shared::replay;
use crate::scene::simulate::{describe_stop, integration_summary};
use crate::scene::summary::{Metric, RunSummary};

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "insert_rcc",
    about: "compliant 3-D peg inserted by a robot through a compliant wrist (RCC)",
    parse,
    ranges: &[ranges::PEG, ranges::WRIST, ranges::ROBOT, ranges::CRITERIA],
};

#[derive(Debug)]
struct Ready {
    scene: RccScene,
    built: Built,
    integrator: IntegratorSpec,
    method_reason: &'static str,
    /// The fields of the `[sensitivities]` table (slots of
    /// [`crate::scene::shared::compliant_peg_3d::design::FIELDS`]), empty
    /// without one.
    sensitivities: Vec<usize>,
}

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: RccScene = doc.body()?;
    let built = s.build()?;
    let (integrator, method_reason) = s.integrator.resolved(DefaultMethod::STIFF_CONTACT);
    let chosen = s
        .sensitivities
        .as_ref()
        .map(|t| sensitivities::check(t, &built));
    Ok(Box::new(Ready {
        sensitivities: chosen.transpose()?.unwrap_or_default(),
        scene: s,
        built,
        integrator,
        method_reason,
    }))
}

impl Written for Ready {
    fn work(&self) -> Vec<WorkItem> {
        let mut work = self.scene.integrator.work("integrator");
        if !self.sensitivities.is_empty() {
            work.extend(sensitivities::work(
                &self.integrator,
                self.sensitivities.len(),
            ));
        }
        work
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        Ok(self)
    }
}

impl Scene for Ready {
    fn time_scales(&self) -> Option<crate::scene::TimeScales> {
        let scales = timescales::held(&self.built.params, &self.built.held);
        Some(crate::scene::TimeScales::new(&self.integrator, scales))
    }

    fn describe(&self) -> String {
        let r = &self.scene.robot;
        let w = &self.built.held.wrist;
        format!(
            "robot insertion through a compliant wrist: D = {} m, c = {}, mu = {}, L_c = {} m, \
             K_x = {} N/m, K_theta = {} N m/rad, lateral error {} m, angular error {} deg, \
             speed {} m/s; {} ({})",
            significant(self.built.params.hole_diameter),
            significant(self.scene.peg.clearance_ratio),
            significant(self.built.params.friction),
            significant(w.centre_height),
            significant(w.lateral[0]),
            significant(w.angular),
            significant(r.lateral_error),
            significant(r.angular_error_deg),
            significant(r.speed),
            self.integrator.describe(),
            self.method_reason
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let run = run_one(&self.built, &self.integrator, true, &mut ctx.progress)?;
        let sys = &run.system;
        let sol = &run.solution;
        let mut integ = integration_summary(&self.integrator, sol, &TERMINAL_NAMES);
        if let StopReason::Event { index, t } = sol.stop {
            integ.stop = describe_stop(&StopReason::Event { index, t }, &TERMINAL_NAMES);
        }
        // `run_one` numbers the transition events from 0 and the terminal
        // ones below 0 (wrapping), in the order of `TERMINAL_NAMES`: each
        // record is named, and the stop marked, by that numbering.
        for (record, hit) in integ.events.iter_mut().zip(&sol.events) {
            let terminal = hit.index.wrapping_add(TERMINAL_NAMES.len());
            if let Some(name) = TERMINAL_NAMES.get(terminal) {
                record.name = (*name).to_string();
                record.terminal = matches!(
                    sol.stop,
                    StopReason::Event { index, t } if index == terminal && t == hit.t
                );
            } else if let Some((i, k)) = run.transitions.get(hit.index) {
                record.name = format!("{} {k}", crate::compliant_peg_3d::Pair::ALL[*i].name());
            }
        }
        let mut out = RunSummary {
            integration: Some(integ),
            ..RunSummary::default()
        };
        let samples = output::samples(sys, sol)?;
        let peaks = output::write_series(ctx, sys, &samples, &sol.events, &run.steps)?;
        let rows = output::transitions(sys, sol, &run.transitions);
        output::write_events(ctx, sys, &rows)?;
        let mm = 1e3;
        let series = |f: &dyn Fn(&crate::compliant_peg_3d::wrist::WristLoad) -> f64| {
            samples
                .rows
                .iter()
                .filter_map(|(_, _, s)| s.wrist.as_ref().map(|w| (s.depth * mm, f(w))))
                .collect::<Vec<_>>()
        };
        let mut fig = Figure::new();
        fig.panels.push(
            Panel::new(
                "Insertion force against depth (Whitney's plot)",
                "depth [mm]",
                "F_z [N]",
            )
            .with(Series::line(
                "insertion force -F_z",
                series(&|w| -w.force_robot.z),
            )),
        );
        fig.panels.push(
            Panel::new(
                "Wrist lateral force and moment against depth",
                "depth [mm]",
                "F [N], M/L_ref [N]",
            )
            .with(Series::line(
                "lateral force |F_xy|",
                series(&|w| w.force_robot.xy().norm()),
            ))
            .with(Series::line(
                "lateral moment |M_xy| / 10 mm",
                series(&|w| w.moment_robot.xy().norm() / 0.01),
            )),
        );
        fig.panels.push(output::forces_panel(&samples));
        fig.panels.push(output::timeline(&samples));
        let (margin_metrics, margin_panel) = margins::margins(
            &self.built.params,
            self.scene.peg.clearance_ratio,
            self.built.held.robot.tilt.abs(),
            &samples,
        );
        if !margin_panel.series.is_empty() {
            fig.panels.push(margin_panel);
        }
        ctx.figure(Part::Main, &fig)?;
        crate::scene::shared::compliant_peg_3d::views::write_views(
            ctx,
            sys,
            (
                sol.t.first().copied().unwrap_or(0.0),
                sol.x.first().unwrap_or(&sol.x_final),
            ),
            &rows,
            (sol.t_final, &sol.x_final),
            12,
        )?;
        out.metrics = output::metrics(&peaks);
        out.metrics.push(Metric::coded(
            "outcome",
            run.outcome.code(),
            outcome_text(&run.outcome),
        ));
        out.metrics.push(Metric::new("end time", sol.t_final, "s"));
        let (depth, tilt, _) = crate::compliant_peg_3d::insertion::depth_tilt(
            &self.built.params,
            &crate::compliant_peg_3d::insertion::peg_state(&sol.x_final),
        );
        out.metrics.push(Metric::new("end depth", depth, "m"));
        out.metrics.push(Metric::new("end tilt", tilt, "rad"));
        out.metrics
            .push(Metric::new("contact transitions", rows.len() as f64, ""));
        if let Some(r) = rows.iter().find(|r| r.two_point) {
            let (d2, ..) = crate::compliant_peg_3d::insertion::depth_tilt(
                &self.built.params,
                &crate::compliant_peg_3d::insertion::peg_state(&r.y),
            );
            out.metrics.push(Metric::new(
                "simulated two-point contact from depth",
                d2,
                "m",
            ));
        }
        out.metrics.extend(margin_metrics);
        if !self.sensitivities.is_empty() {
            let (scene, built) = (&self.scene, &self.built);
            let chosen = &self.sensitivities;
            out.metrics.extend(sensitivities::run(
                ctx,
                scene,
                built,
                &self.integrator,
                chosen,
            )?);
        }
        if self.scene.replay.wanted(ctx) {
            let what = "compliant 3-D peg held by a compliant wrist";
            replay::write(ctx, &insertion(ctx.name(), what, &run)?)?;
        }
        Ok(out)
    }
}
