//! The forward simulation driver: integrate the sliding peg until an event,
//! decide stick or slip when it comes to rest, restart, and collect the
//! trajectory with the reactions at each output time.

use nalgebra::{Vector2, Vector4};

use crate::integrate::{IntegrateError, Method, Options, OutputMode, Solver, Stats, StopReason};
use crate::rigid_peg::RigidError;
use crate::rigid_peg::forward::{ForwardModel, FrictionLaw, PegSystem, split};
use crate::rigid_peg::forward_events::{EventKind, events};
use crate::rigid_peg::modes::{Verdict, classify};
use crate::rigid_peg::static_hold::hold_at_rest;
use crate::rigid_peg::stick::{RestOutcome, start_from_rest};
use crate::rigid_peg::stop::{ForwardStop, PainleveCase};

/// Budget of stop/restart cycles of one simulation.
pub const MAX_RESTARTS: usize = 1000;

/// One output point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// Time (s).
    pub t: f64,
    /// State (γ, ψ, γ̇, ψ̇).
    pub x: Vector4<f64>,
    /// `[N_K, N_B1, N_B2]` (N); NaN where undefined.
    pub normal: [f64; 3],
}

/// A peg-at-rest episode during the run: the speed fell to v_stop and the
/// peg restarted sliding along `direction`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Restart {
    /// Time (s).
    pub t: f64,
    /// Direction û of the new motion in (γ, ψ).
    pub direction: Vector2<f64>,
}

/// The result of [`simulate`].
#[derive(Clone, Debug, PartialEq)]
pub struct Trajectory {
    /// Output points of all phases, in time order.
    pub rows: Vec<Row>,
    /// Why it stopped.
    pub stop: ForwardStop,
    /// Restarts from rest, in time order.
    pub restarts: Vec<Restart>,
    /// Integrator work, summed over phases.
    pub stats: Stats,
    /// For a non-finite integrator stop: the first non-finite component
    /// ([`crate::integrate::Solution::non_finite`]).
    pub non_finite: Option<crate::integrate::NonFiniteAt>,
}

/// Invalid input to [`simulate`].
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ForwardError {
    /// Options or time span rejected by the integrator.
    #[error(transparent)]
    Integrate(#[from] IntegrateError),
    /// Initial state outside three-point contact, or bad parameters.
    #[error(transparent)]
    Rigid(#[from] RigidError),
}

fn painleve(t: f64, x: Vector4<f64>, case: PainleveCase) -> ForwardStop {
    ForwardStop::Painleve { t, state: x, case }
}

/// Checks a sliding state before a phase: `None` when the three-point
/// motion can proceed, else the stop to report.
fn check_sliding(model: &ForwardModel, t: f64, x: Vector4<f64>) -> Option<ForwardStop> {
    let a = model.evaluate(&x, None);
    if let Ok(a) = &a
        && a.normal.iter().all(|&n| n >= 0.0)
    {
        return None;
    }
    let (q, qdot) = split(&x);
    match classify(model, q, qdot) {
        Ok(Verdict::ThreePoint) => None,
        Ok(Verdict::LiftOff(m)) => {
            let i = (0..3).find(|&i| !m.in_contact[i]).unwrap_or(0);
            Some(ForwardStop::LiftOff {
                contact: crate::rigid_peg::dynamics::CONTACTS[i],
                t,
                state: x,
            })
        }
        Ok(Verdict::Inconsistent) => Some(painleve(t, x, PainleveCase::Inconsistent)),
        Ok(Verdict::Indeterminate(m)) => Some(painleve(t, x, PainleveCase::Indeterminate(m))),
        Err(_) => Some(painleve(t, x, PainleveCase::Singular)),
    }
}

/// Integrates the peg from `x0 = (γ, ψ, γ̇, ψ̇)` at `t0` to `t_end` with
/// `method` and `options` (tolerances, output times; the output times of
/// each phase are those inside it, and each phase's final state is added).
///
/// # Errors
/// [`ForwardError`] for invalid options, span or initial state (γ outside
/// (γ0, π/2)).
pub fn simulate(
    model: &ForwardModel,
    x0: Vector4<f64>,
    t0: f64,
    t_end: f64,
    method: Method,
    options: &Options,
) -> Result<Trajectory, ForwardError> {
    simulate_with_progress(model, x0, (t0, t_end), method, options, &mut |_| {}, None)
}

/// [`simulate`] calling `progress` with the time after every accepted step,
/// and stopping with [`StopReason::Interrupted`] once `interrupt` (when
/// given) is requested.
///
/// # Errors
/// As [`simulate`].
pub fn simulate_with_progress(
    model: &ForwardModel,
    x0: Vector4<f64>,
    (t0, t_end): (f64, f64),
    method: Method,
    options: &Options,
    progress: &mut dyn FnMut(f64),
    interrupt: Option<&crate::integrate::Interrupt>,
) -> Result<Trajectory, ForwardError> {
    options.validate(t0, t_end)?;
    crate::rigid_peg::kinematics::Geometry::try_new(&model.params, x0[0])?;
    let mut out = Trajectory {
        rows: Vec::new(),
        stop: ForwardStop::ReachedEnd { t: t0 },
        restarts: Vec::new(),
        stats: Stats::default(),
        non_finite: None,
    };
    let (mut t, mut x) = (t0, x0);
    loop {
        // One step budget for the whole trajectory, across restarts and
        // stops: the work of a run stays bounded by `options.max_steps`.
        let used = out.stats.steps + out.stats.rejected;
        if used >= options.max_steps {
            out.stop = ForwardStop::Integrator(StopReason::MaxSteps { t, steps: used });
            return Ok(out);
        }
        let mut start = None;
        if model.friction == FrictionLaw::Coulomb && model.speed(&x) <= model.v_stop {
            x[2] = 0.0;
            x[3] = 0.0;
            let (q, _) = split(&x);
            match start_from_rest(model, q)? {
                RestOutcome::Sticks => {
                    push_row(model, &mut out.rows, t, x, None);
                    out.stop = ForwardStop::Stuck {
                        t,
                        gamma: x[0],
                        psi: x[1],
                    };
                    return Ok(out);
                }
                // A start needs a pulling contact: before reporting the
                // lift-off, check whether static friction holds the peg at
                // rest on its three contacts (without wedging pre-stress).
                RestOutcome::LeavesContact { .. } if hold_at_rest(model, q)?.is_some() => {
                    push_row(model, &mut out.rows, t, x, None);
                    out.stop = ForwardStop::Stuck {
                        t,
                        gamma: x[0],
                        psi: x[1],
                    };
                    return Ok(out);
                }
                RestOutcome::LeavesContact { contact, .. } => {
                    push_row(model, &mut out.rows, t, x, None);
                    out.stop = ForwardStop::LiftOff {
                        contact: crate::rigid_peg::dynamics::CONTACTS[contact],
                        t,
                        state: x,
                    };
                    return Ok(out);
                }
                RestOutcome::Slides { starts } => {
                    let u = starts[0].direction;
                    if out.restarts.len() >= MAX_RESTARTS {
                        out.stop = ForwardStop::RestartLimit {
                            t,
                            restarts: out.restarts.len(),
                        };
                        return Ok(out);
                    }
                    out.restarts.push(Restart { t, direction: u });
                    start = Some(u);
                }
            }
        } else if let Some(stop) = check_sliding(model, t, x) {
            push_row(model, &mut out.rows, t, x, None);
            out.stop = stop;
            return Ok(out);
        }
        let mut opts = options.clone();
        opts.max_steps = options.max_steps - used;
        if let OutputMode::AtTimes(ts) = &options.output {
            opts.output = OutputMode::AtTimes(ts.iter().copied().filter(|&s| s >= t).collect());
        }
        let (evs, kinds) = events(model, start);
        let mut solver = Solver::new(method, opts);
        for e in evs {
            solver = solver.with_event(e);
        }
        if let Some(i) = interrupt {
            solver = solver.with_interrupt(i);
        }
        let mut solver = solver.with_progress(&mut *progress);
        let system = PegSystem { model, start };
        let sol = solver.solve(&system, t, x, t_end)?;
        out.stats += &sol.stats;
        out.non_finite = sol.non_finite;
        for (ts, xs) in sol.t.iter().zip(&sol.x) {
            push_row(model, &mut out.rows, *ts, *xs, start);
        }
        push_row(model, &mut out.rows, sol.t_final, sol.x_final, start);
        (t, x) = (sol.t_final, sol.x_final);
        let kind = match sol.stop {
            StopReason::Event { index, .. } => kinds.get(index).copied(),
            _ => None,
        };
        out.stop = match (sol.stop, kind) {
            (StopReason::ReachedEnd, _) => ForwardStop::ReachedEnd { t },
            (_, Some(EventKind::Gamma0)) => ForwardStop::TwoPointContact { t, state: x },
            (_, Some(EventKind::LiftOff(i))) => ForwardStop::LiftOff {
                contact: crate::rigid_peg::dynamics::CONTACTS[i],
                t,
                state: x,
            },
            (_, Some(EventKind::Singular)) => painleve(t, x, PainleveCase::Singular),
            (_, Some(EventKind::Jam)) => painleve(t, x, PainleveCase::Unbounded),
            (_, Some(EventKind::Stop)) => continue,
            (reason, _) => ForwardStop::Integrator(reason),
        };
        return Ok(out);
    }
}

fn push_row(
    model: &ForwardModel,
    rows: &mut Vec<Row>,
    t: f64,
    x: Vector4<f64>,
    start: Option<Vector2<f64>>,
) {
    if rows.last().is_some_and(|r| r.t >= t) {
        return;
    }
    let normal = model
        .evaluate_clamped(&x, start)
        .map_or([f64::NAN; 3], |a| a.normal);
    rows.push(Row { t, x, normal });
}
