//! Scene kind `insert_rcc`: a robot inserts the compliant 3-D peg through
//! a compliant wrist (remote centre compliance) from a start pose with
//! lateral and angular errors, descending at a speed or under a constant
//! axial force, optionally precessing, spinning or searching on a spiral.
//! The run ends with an [`Outcome`] (seated, jammed, wedged, missed, force
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
//! Writes `<name>.csv` (time series), `<name>_events.csv` (contact
//! transitions), `<name>.svg` (Whitney's plot: insertion force and the
//! wrist's lateral force and moment against depth; contact forces and the
//! contact-state timeline against time) and `<name>_views.svg`.

use serde::Deserialize;

use super::output;
use super::tables::{CriteriaTable, PegTable, RobotTable, WristTable, held};
use crate::compliant_peg_3d::Peg3dParams;
use crate::compliant_peg_3d::insertion::{Held, Insertion, N_STATE};
use crate::compliant_peg_3d::outcome::{
    CountCache, Criteria, Outcome, TERMINAL_NAMES, classify, terminal_events, transition_events,
};
use crate::error::{RunError, SceneErrors};
use crate::integrate::{Solution, StopReason};
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series};
use crate::scene::integrator::DefaultMethod;
use crate::scene::simulate::{describe_stop, integrate, integration_summary};
use crate::scene::validate::Checker;
use crate::scene::{Document, IntegratorSpec, Kind, Metric, RunContext, RunSummary, Scene};

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "insert_rcc",
    about: "compliant 3-D peg inserted by a robot through a compliant wrist (RCC)",
    parse,
};

/// An `insert_rcc` scene as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RccScene {
    /// `[peg]`.
    pub peg: PegTable,
    /// `[wrist]`.
    pub wrist: WristTable,
    /// `[robot]`.
    pub robot: RobotTable,
    /// `[criteria]`.
    pub criteria: CriteriaTable,
    /// `[integrator]`.
    pub integrator: IntegratorSpec,
}

/// A validated held peg, ready to run.
#[derive(Debug, Clone, Copy)]
pub struct Built {
    /// The peg.
    pub params: Peg3dParams,
    /// Wrist and robot.
    pub held: Held,
    /// When the run ends.
    pub criteria: Criteria,
    /// Tip depth of a start in the bore (m), if `robot.start_height < 0`.
    pub start_depth: Option<f64>,
}

impl RccScene {
    /// Validates every table.
    ///
    /// # Errors
    /// Every invalid field, named.
    pub fn build(&self) -> Result<Built, SceneErrors> {
        let mut c = Checker::default();
        let (params, held, criteria) =
            held(&self.peg, &self.wrist, &self.robot, &self.criteria, &mut c);
        c.extend(self.integrator.check("integrator"));
        c.finish()?;
        Ok(Built {
            params,
            held,
            criteria,
            start_depth: (self.robot.start_height < 0.0).then_some(-self.robot.start_height),
        })
    }
}

#[derive(Debug)]
struct Ready {
    scene: RccScene,
    built: Built,
    integrator: IntegratorSpec,
    method_reason: &'static str,
}

fn parse(doc: &Document<'_>) -> Result<Box<dyn Scene>, SceneErrors> {
    let s: RccScene = doc.body()?;
    let built = s.build()?;
    let (integrator, method_reason) = s.integrator.resolved(DefaultMethod::NON_STIFF);
    Ok(Box::new(Ready {
        scene: s,
        built,
        integrator,
        method_reason,
    }))
}

/// One insertion's result.
pub struct Run {
    /// The system.
    pub system: Insertion,
    /// The integration.
    pub solution: Solution<N_STATE>,
    /// How it ended.
    pub outcome: Outcome,
    /// The transition events' meaning.
    pub transitions: Vec<crate::compliant_peg_3d::outcome::Transition>,
}

/// Integrates one insertion with its terminal and (if `track`) contact
/// transition events, and classifies the end.
///
/// # Errors
/// The integrator's refusal or a Hertz setup error.
pub fn run_one(
    b: &Built,
    spec: &IntegratorSpec,
    track: bool,
    progress: &mut crate::scene::Progress,
) -> Result<Run, RunError> {
    let sys = Insertion::new(b.params, Some(b.held), 0.0);
    let counter = Insertion::new(b.params, None, 0.0);
    let y0 = match b.start_depth {
        Some(d) => sys.centred_start(d),
        None => sys.held_start(),
    }
    .unwrap_or_default();
    let (solution, what) = {
        let cache = CountCache::new(&counter);
        let mut events = terminal_events(&sys, b.criteria);
        let mut what = Vec::new();
        if track {
            let (ev, w) = transition_events(&cache);
            events.extend(ev);
            what = w;
        }
        (integrate(&sys, y0, spec, events, progress)?, what)
    };
    if let Some(e) = sys.error() {
        return Err(RunError::Hertz(e));
    }
    let terminal = match solution.stop {
        StopReason::Event { index, .. } if index < TERMINAL_NAMES.len() => Some(index),
        _ => None,
    };
    let reason = describe_stop(&solution.stop, &TERMINAL_NAMES);
    let outcome = classify(
        &sys,
        b.criteria,
        solution.t_final,
        &solution.x_final,
        terminal,
        &reason,
    );
    // A contact force limit reached by a jump between two samples is a
    // contact the model's pairs missed, not a robot stop.
    let outcome = match outcome {
        Outcome::ForceLimit {
            which: "contact", ..
        } => {
            let prev = solution
                .t
                .iter()
                .zip(&solution.x)
                .rev()
                .find(|(t, _)| **t < solution.t_final);
            match prev {
                Some((&t, y)) => {
                    let before = sys.sample(t, y)?.peak_normal();
                    if before < 0.1 * b.criteria.contact_force_limit {
                        Outcome::ContactJump { before, since: t }
                    } else {
                        outcome
                    }
                }
                None => outcome,
            }
        }
        other => other,
    };
    // Transition events are indexed after the terminal ones.
    let mut solution = solution;
    for e in &mut solution.events {
        e.index = e.index.wrapping_sub(TERMINAL_NAMES.len());
    }
    Ok(Run {
        system: sys,
        solution,
        outcome,
        transitions: what,
    })
}

impl Scene for Ready {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        self.scene.integrator.work("integrator")
    }

    fn describe(&self) -> String {
        let r = &self.scene.robot;
        let w = &self.built.held.wrist;
        format!(
            "robot insertion through a compliant wrist: D = {} m, c = {}, mu = {}, L_c = {} m, \
             K_x = {} N/m, K_theta = {} N m/rad, lateral error {} m, angular error {} deg, \
             speed {} m/s; {} ({})",
            crate::scene::significant(self.built.params.hole_diameter),
            crate::scene::significant(self.scene.peg.clearance_ratio),
            crate::scene::significant(self.built.params.friction),
            crate::scene::significant(w.centre_height),
            crate::scene::significant(w.lateral[0]),
            crate::scene::significant(w.angular),
            crate::scene::significant(r.lateral_error),
            crate::scene::significant(r.angular_error_deg),
            crate::scene::significant(r.speed),
            self.integrator.describe(),
            self.method_reason
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let run = run_one(&self.built, &self.integrator, true, &mut ctx.progress)?;
        let sys = &run.system;
        let sol = &run.solution;
        let mut names: Vec<String> = TERMINAL_NAMES.iter().map(|s| s.to_string()).collect();
        names.extend(
            run.transitions
                .iter()
                .map(|(i, k)| format!("{} {k}", crate::compliant_peg_3d::Pair::ALL[*i].name())),
        );
        let name_refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let mut integ = integration_summary(&self.integrator, sol, &name_refs);
        if let StopReason::Event { index, t } = sol.stop {
            integ.stop = describe_stop(&StopReason::Event { index, t }, &TERMINAL_NAMES);
        }
        let mut out = RunSummary {
            integration: Some(integ),
            ..RunSummary::default()
        };
        let samples = output::samples(sys, sol)?;
        let peaks = output::write_series(ctx, &samples)?;
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
        let (margin_metrics, margin_panel) = super::margins::margins(
            &self.built.params,
            self.scene.peg.clearance_ratio,
            self.built.held.robot.tilt.abs(),
            &samples,
        );
        if !margin_panel.series.is_empty() {
            fig.panels.push(margin_panel);
        }
        ctx.figure(Part::Main, &fig)?;
        output::write_views(
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
        out.metrics.push(Metric::new(
            format!("outcome: {}", outcome_text(&run.outcome)),
            run.outcome.code(),
            "",
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
        Ok(out)
    }
}

/// The outcome in words.
pub fn outcome_text(o: &Outcome) -> String {
    match o {
        Outcome::Jammed { contacts } => format!("jammed on {contacts}"),
        Outcome::Wedged { contacts } => format!("wedged on {contacts}"),
        Outcome::ForceLimit { which, force } => {
            format!(
                "{which} force limit ({} N)",
                crate::scene::significant(*force)
            )
        }
        Outcome::Stopped { reason } => format!("stopped: {reason}"),
        Outcome::ContactJump { before, since } => format!(
            "contact force jumped to the limit from {} N at t = {} s (a contact the model's \
             pairs miss)",
            crate::scene::significant(*before),
            crate::scene::significant(*since)
        ),
        other => other.name().to_string(),
    }
}
