//! One insertion of the compliant 3-D peg held by a robot through a
//! compliant wrist (remote centre compliance), shared by the kinds that run
//! it (`insert_rcc` once, `rotation_assist` and `design_margins` over
//! grids): the `insert_rcc` tables as written ([`RccScene`]), validated
//! ([`Built`]), integrated and classified ([`run_one`]), and the outcome in
//! words ([`outcome_text`]).

use serde::Deserialize;

use nalgebra::SVector;

use super::start;
use super::tables::{CriteriaTable, PegTable, RobotTable, WristTable, held};
use crate::compliant_peg_3d::Peg3dParams;
use crate::compliant_peg_3d::forces::ContactForce;
use crate::compliant_peg_3d::insertion::{Held, Insertion, N_STATE, Sample, peg_state};
use crate::compliant_peg_3d::outcome::{
    CountCache, Criteria, LimitStop, Outcome, TERMINAL_NAMES, classify, terminal_events,
    transition_events,
};
use crate::compliant_peg_3d::robot::Descent;
use crate::compliant_peg_3d::wrist::WristLoad;
use crate::error::{RunError, SceneError, SceneErrors};
use crate::hertz::HertzError;
use crate::integrate::{Solution, StopReason};
use crate::scene::integrator::IntegratorSpec;
use crate::scene::numbers::significant;
use crate::scene::progress::Progress;
use crate::scene::shared::replay::ReplayTable;
use crate::scene::shared::sensitivities::SensitivitiesTable;
use crate::scene::simulate::{describe_stop, integrate_watching};
use crate::scene::validate::Checker;
use crate::system::ModelError;

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
    /// `[replay]` (optional).
    #[serde(default)]
    pub replay: ReplayTable,
    /// `[sensitivities]` (optional; `insert_rcc`'s, or a `rotation_assist`
    /// grid's for each of its points): derivatives of the run's metrics in
    /// design fields.
    #[serde(default)]
    pub sensitivities: Option<SensitivitiesTable>,
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
        let built = Built {
            params,
            held,
            criteria,
            start_depth: (self.robot.start_height < 0.0).then_some(-self.robot.start_height),
        };
        let sys = Insertion::new(built.params, Some(built.held), 0.0);
        let y0 = built.start_state(&sys);
        if let Some(o) = start::overlap(&sys, &y0) {
            return Err(SceneErrors::from(self.start_refusal(&built, &o)));
        }
        // A limit the start already passes is never crossed (the limit's
        // event fires on a rise through it) and the summary would report a
        // stop at a later, smaller force.
        let at_start = sys
            .sample(0.0, &y0)
            .ok()
            .and_then(|s| s.wrist)
            .map_or(0.0, |w| w.force.norm());
        if at_start >= built.criteria.wrist_force_limit {
            return Err(SceneErrors::from(SceneError::invalid(
                "criteria.wrist_force_limit",
                self.criteria.wrist_force_limit,
                format!(
                    "the wrist already carries {} N at the start ({}), so the limit would be \
                     passed before the run begins and never detected; it must exceed that force",
                    significant(at_start),
                    built.start_load()
                ),
            )));
        }
        Ok(built)
    }

    /// Why the start pose is refused, on the field that places the peg
    /// there: `wrist.axial_stiffness` when the wrist's static sag under
    /// the peg's weight is what sinks it, else `robot.start_height`, the
    /// errors named in the reason with the start height that clears.
    fn start_refusal(&self, b: &Built, o: &start::Overlap) -> SceneError {
        let r = &self.robot;
        let h = r.start_height;
        let clears = h + o.lift;
        let sag = b.sag();
        if b.start_depth.is_some() {
            return SceneError::invalid(
                "robot.start_height",
                h,
                format!(
                    "{}: the peg starts in the bore, centred and aligned, at that depth",
                    o.describe()
                ),
            );
        }
        if sag > 0.0 && sag >= 0.5 * o.lift {
            return SceneError::invalid(
                "wrist.axial_stiffness",
                self.wrist.axial_stiffness,
                format!(
                    "{}: the wrist's static sag m g / K_z = {} m under the peg's weight puts the \
                     peg that far below robot.start_height = {} m; a stiffer wrist, or \
                     robot.start_height of at least {} m, clears the block",
                    o.describe(),
                    significant(sag),
                    significant(h),
                    significant(clears)
                ),
            );
        }
        SceneError::invalid(
            "robot.start_height",
            h,
            format!(
                "{}: with robot.angular_error_deg = {}, robot.lateral_error = {} m{} the tip \
                 starts too low; robot.start_height of at least {} m (or smaller errors) clears \
                 the block",
                o.describe(),
                significant(r.angular_error_deg),
                significant(r.lateral_error),
                if sag > 0.0 {
                    format!(
                        " and the wrist's static sag m g / K_z = {} m",
                        significant(sag)
                    )
                } else {
                    String::new()
                },
                significant(clears)
            ),
        )
    }
}

impl Built {
    /// The start state of the run: in the bore (`robot.start_height < 0`)
    /// or held above it.
    pub fn start_state(&self, sys: &Insertion) -> SVector<f64, N_STATE> {
        match self.start_depth {
            Some(d) => sys.centred_start(d),
            None => sys.held_start(),
        }
        .unwrap_or_default()
    }

    /// What loads the wrist at the start, in words (for a refusal of a
    /// force limit the start already passes).
    fn start_load(&self) -> &'static str {
        if self.start_depth.is_some() {
            "the peg starts centred and upright in the bore, so the wrist is deflected by \
             robot.lateral_error and robot.angular_error_deg and carries the peg's weight"
        } else if matches!(self.held.robot.descent, Descent::Force { .. }) {
            "the robot's axial push and the peg's weight"
        } else {
            "the peg's weight m g, held by the wrist's static sag"
        }
    }

    /// The wrist's static axial sag `m g / K_z` at a speed-controlled start
    /// held above the bore (m; 0 under an axial force or in the bore).
    pub fn sag(&self) -> f64 {
        let forced = matches!(self.held.robot.descent, Descent::Force { .. });
        if forced || self.start_depth.is_some() || self.held.wrist.axial <= 0.0 {
            0.0
        } else {
            self.params.mass * self.params.gravity / self.held.wrist.axial
        }
    }
}

/// The errors of grid point `point` (its entries, e.g.
/// `("grid.lateral_errors[1]", 2e-4)`) with the robot fields the grid
/// replaces renamed as the grid's entries (`renames`: robot field, grid
/// entry, the grid value), and a start-pose refusal (on
/// `robot.start_height`) named on the last entry with the point in its
/// reason; identical errors (one per point of
/// a field every point shares) are kept once by [`Checker::push_once`].
pub fn at_grid_point(
    errors: SceneErrors,
    point: &[(String, f64)],
    renames: &[(&str, &str, f64)],
    c: &mut Checker,
) {
    let at = point
        .iter()
        .map(|(f, v)| format!("{f} = {}", significant(*v)))
        .collect::<Vec<_>>()
        .join(", ");
    for e in errors.errors {
        let error = match e.error {
            SceneError::Invalid {
                field,
                value,
                reason,
            } => {
                if let Some((_, grid, v)) = renames.iter().find(|(robot, ..)| *robot == field) {
                    SceneError::invalid(*grid, v, format!("at the grid point ({at}): {reason}"))
                } else if field == "robot.start_height"
                    && reason.starts_with(start::OVERLAP)
                    && let Some((last, v)) = point.last()
                {
                    SceneError::invalid(
                        last.clone(),
                        v,
                        format!(
                            "at the grid point ({at}), from robot.start_height = {value}: {reason}"
                        ),
                    )
                } else {
                    SceneError::Invalid {
                        field,
                        value,
                        reason,
                    }
                }
            }
            other => other,
        };
        c.push_once(error);
    }
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
    /// The peaks over the ends of every accepted step.
    pub steps: RunPeaks,
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
    progress: &mut Progress,
) -> Result<Run, RunError> {
    let sys = Insertion::new(b.params, Some(b.held), 0.0);
    let y0 = b.start_state(&sys);
    let mut steps = RunPeaks::default();
    let (solution, what) = {
        // The counts share the run's search: at a step's end they take
        // the contacts its last right-hand side found there.
        let cache = CountCache::new(&sys);
        let mut events = terminal_events(&sys, b.criteria);
        let mut what = Vec::new();
        if track {
            let (ev, w) = transition_events(&cache);
            events.extend(ev);
            what = w;
        }
        let on_step = |t, y: &SVector<f64, N_STATE>| steps.include(&sys, t, y);
        (
            integrate_watching(&sys, y0, spec, events, progress, on_step)?,
            what,
        )
    };
    if let Some(ModelError::Hertz(e)) = solution.model_error.clone() {
        return Err(start::hertz_refusal(&b.params, solution.t_final, e));
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
        steps,
    })
}

/// The largest values along one insertion: over the ends of its accepted
/// steps, its stored samples (which end with the final state) and its
/// located events.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RunPeaks {
    /// Largest contact normal force (N).
    pub contact: f64,
    /// Largest Hertz pressure `p₀` (Pa).
    pub pressure: f64,
    /// Largest wrist lateral moment about the compliance centre (N·m).
    pub wrist_moment: f64,
    /// Largest wrist force (N).
    pub wrist_force: f64,
}

impl RunPeaks {
    /// Takes the state `y` at `t` of `sys` into the peaks: its contact
    /// forces and the wrist's load only (not a whole sample), the pressure
    /// screened against the peak so far; a state whose contacts cannot be
    /// set up adds nothing (the run reports that error itself).
    pub fn include(&mut self, sys: &Insertion, t: f64, y: &SVector<f64, N_STATE>) {
        let _ = self.try_include(sys, t, y);
    }

    /// [`RunPeaks::include`], with the Hertz setup error of a state whose
    /// contacts cannot be set up.
    fn try_include(
        &mut self,
        sys: &Insertion,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> Result<(), HertzError> {
        let ys = peg_state(y);
        let forces = sys.peg.forces(&ys)?;
        let wrist = sys.wrist_load(t, &ys).map(|(_, l)| l);
        self.take(sys, y, &forces, wrist.as_ref());
        Ok(())
    }

    /// Takes the forces of sample `s` at state `y` into the peaks.
    pub fn include_sample(&mut self, sys: &Insertion, y: &SVector<f64, N_STATE>, s: &Sample) {
        self.take(sys, y, &s.forces, s.wrist.as_ref());
    }

    /// Takes contact `forces` at state `y`, their largest Hertz pressure
    /// (Pa, screened against the peak so far) and the wrist's load into
    /// the peaks.
    fn take(
        &mut self,
        sys: &Insertion,
        y: &SVector<f64, N_STATE>,
        forces: &[ContactForce],
        wrist: Option<&WristLoad>,
    ) {
        let pressure = sys.peak_pressure_above(y, forces, self.pressure);
        let normal = forces.iter().map(|f| f.normal_force).fold(0.0, f64::max);
        self.contact = self.contact.max(normal);
        self.pressure = self.pressure.max(pressure);
        if let Some(w) = wrist {
            self.wrist_moment = self.wrist_moment.max(w.moment_robot.xy().norm());
            self.wrist_force = self.wrist_force.max(w.force.norm());
        }
    }
}

impl Run {
    /// The peaks of the run over the end of every accepted step, every
    /// stored sample and every event state (a peak between two output
    /// times, an impact, is at a step's end or an event, not at a sample).
    ///
    /// # Errors
    /// A Hertz setup error at a sample or an event state.
    pub fn peaks(&self) -> Result<RunPeaks, RunError> {
        let sol = &self.solution;
        let samples = sol.t.iter().copied().zip(sol.x.iter());
        let events = sol.events.iter().map(|e| (e.t, &e.x));
        let mut p = self.steps;
        for (t, y) in samples.chain(events) {
            p.try_include(&self.system, t, y)?;
        }
        Ok(p)
    }
}

/// The force limit that stopped a jammed or wedged run, in words (empty
/// when the run ended without progress instead).
fn stopped_by(limit: &Option<LimitStop>) -> String {
    limit.map_or_else(String::new, |l| {
        format!(
            " (the run stopped at the {} force limit, {} N)",
            l.which,
            significant(l.force)
        )
    })
}

/// The outcome in words.
pub fn outcome_text(o: &Outcome) -> String {
    match o {
        Outcome::Jammed { contacts, limit } => format!("jammed on {contacts}{}", stopped_by(limit)),
        Outcome::Wedged { contacts, limit } => format!("wedged on {contacts}{}", stopped_by(limit)),
        Outcome::ForceLimit { which, force } => {
            format!("{which} force limit ({} N)", significant(*force))
        }
        Outcome::Stopped { reason } => format!("stopped: {reason}"),
        Outcome::ContactJump { before, since } => format!(
            "contact force jumped to the limit from {} N at t = {} s (a contact the model's \
             pairs miss)",
            significant(*before),
            significant(*since)
        ),
        other => other.name().to_string(),
    }
}
