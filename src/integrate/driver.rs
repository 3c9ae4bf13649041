//! The one integration loop shared by every method, as a run state in the
//! shape of `diffsol`'s solvers: [`Run::new`] starts it, [`Run::step`] makes
//! one attempt, [`Run::finish`] returns the [`Solution`]; [`run`] steps a run
//! to its end.
//!
//! A method plugs in through [`Stepper`]: it attempts one step and builds
//! the interpolant of an accepted step. Step-size control, rejection of
//! non-finite steps, event location, output and progress are the run's
//! [`State`] (`state.rs`), which does not depend on the method or the
//! system and so is compiled once per dimension.

use nalgebra::SVector;

use crate::system::OdeSystem;

use super::dense::Interpolant;
use super::events::Event;
use super::options::Options;
use super::solution::{Solution, Stats, StopReason};
use super::state::{Control, Hooks, State, Storage};
use super::step_control::{PiController, initial_step};

/// The outcome of one attempted step.
pub(crate) enum Attempt<const N: usize> {
    /// The step produced finite values: new state, `f` there, and the local
    /// error estimate (`None` for fixed-step methods).
    Done {
        x1: SVector<f64, N>,
        f1: SVector<f64, N>,
        err: Option<SVector<f64, N>>,
    },
    /// A stage value or the new state was not finite.
    NonFinite,
    /// The iteration matrix of an implicit method was singular.
    Singular,
}

/// A one-step method as seen by the driver.
pub(crate) trait Stepper<const N: usize> {
    /// Classical order (used for the starting step).
    fn order(&self) -> u32;
    /// Exponent base `q` of the step controller, `None` for fixed step.
    fn controller_order(&self) -> Option<u32>;
    /// Attempts the step `t → t + h` from `x` with `f0 = f(t, x)`.
    fn attempt<S: OdeSystem<N>>(
        &mut self,
        system: &S,
        t: f64,
        x: &SVector<f64, N>,
        f0: &SVector<f64, N>,
        h: f64,
        stats: &mut Stats,
    ) -> Attempt<N>;
    /// The interpolant of the step just accepted.
    fn interpolant(
        &self,
        t0: f64,
        h: f64,
        start: (&SVector<f64, N>, &SVector<f64, N>),
        end: (&SVector<f64, N>, &SVector<f64, N>),
    ) -> Interpolant<N>;
}

fn all_finite<const N: usize>(v: &SVector<f64, N>) -> bool {
    v.iter().all(|c| c.is_finite())
}

/// Number of fixed steps of size about `h` covering `span` (the last step
/// absorbs round-off instead of leaving a sliver).
fn fixed_step_count(span: f64, h: f64) -> usize {
    let r = span / h;
    let n = if (r - r.round()).abs() <= 1e-9 * r.max(1.0) {
        r.round()
    } else {
        r.ceil()
    };
    (n as usize).max(1)
}

/// Runs `stepper` on `system` from `(t0, x0)` to `t_end`: a [`Run`]
/// stepped until it stops, then finished. The options must have been
/// validated; `fixed_h` selects fixed stepping.
#[allow(clippy::too_many_arguments)]
pub(crate) fn run<const N: usize, S: OdeSystem<N>, M: Stepper<N>>(
    stepper: &mut M,
    system: &S,
    start: (f64, SVector<f64, N>),
    t_end: f64,
    options: &Options,
    fixed_h: Option<f64>,
    events: &[Event<'_, N>],
    hooks: &mut Hooks<'_, N>,
    storage: Storage<N>,
) -> Solution<N> {
    let mut run = Run::new(
        stepper, system, start, t_end, options, fixed_h, events, hooks, storage,
    );
    loop {
        if let Some(stop) = run.step() {
            return run.finish(stop);
        }
    }
}

/// One integration in progress: the method and the system, and the
/// [`State`] of the loop. [`Run::step`] makes one attempt (accepted or
/// rejected) and says when the run stops; [`Run::finish`] turns it into the
/// [`Solution`].
pub(crate) struct Run<'r, 'e, 'h, const N: usize, S, M> {
    stepper: &'r mut M,
    system: &'r S,
    state: State<'r, 'e, 'h, N>,
}

impl<'r, 'e, 'h, const N: usize, S: OdeSystem<N>, M: Stepper<N>> Run<'r, 'e, 'h, N, S, M> {
    /// Reports the start, evaluates `f` and the events there and chooses
    /// the first step. A non-finite `f(t0, x0)` stops the run at its first
    /// [`Run::step`].
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        stepper: &'r mut M,
        system: &'r S,
        (t0, x0): (f64, SVector<f64, N>),
        t_end: f64,
        options: &'r Options,
        fixed_h: Option<f64>,
        events: &'r [Event<'e, N>],
        hooks: &'r mut Hooks<'h, N>,
        storage: Storage<N>,
    ) -> Self {
        let mut state = State::new((t0, x0), t_end, options, events, hooks, storage);
        let f = system.rhs(t0, &x0);
        state.stats.rhs_calls += 1;
        state.f = f;
        if !all_finite(&f) {
            state.pending = Some(StopReason::NonFinite { t: t0 });
            return Run {
                stepper,
                system,
                state,
            };
        }
        state.g_prev = events.iter().map(|e| e.eval(t0, &x0)).collect();
        state.stats.event_calls += events.len();

        let span = t_end - t0;
        let h_max = options.h_max.unwrap_or(span).min(span);
        let fixed = fixed_h.map(|h| (h, fixed_step_count(span, h)));
        let mut h = match (fixed, options.h0) {
            (Some((h, _)), _) => h,
            (None, Some(h0)) => h0.min(h_max),
            (None, None) => initial_step(
                system,
                t0,
                &x0,
                &f,
                stepper.order(),
                options,
                h_max,
                &mut state.stats,
            ),
        };
        if fixed.is_none() {
            // A first step (a user hint, or the estimate from a state at rest
            // with a tolerance far below f64 resolution) under the step-size
            // floor would stop the run at t0 before any step: start above the
            // floor and let the controller reject it if it is too large.
            let floor0 = 16.0 * f64::EPSILON * t0.abs().max(t_end.abs()).max(f64::MIN_POSITIVE);
            h = h.max(64.0 * floor0).min(h_max);
        }
        state.control = Control {
            h,
            h_max,
            fixed,
            controller: stepper.controller_order().map(PiController::new),
            last_rejected: false,
            last_nonfinite: false,
        };
        Run {
            stepper,
            system,
            state,
        }
    }

    /// One attempted step: `None` while the run goes on (the step was
    /// accepted, or rejected with a smaller step to try), the reason when
    /// it stops (the end, a terminal event, a failure).
    pub(crate) fn step(&mut self) -> Option<StopReason> {
        let t1 = match self.state.next_step_end() {
            Ok(t1) => t1,
            Err(stop) => return Some(stop),
        };
        let st = &mut self.state;
        let h_try = t1 - st.t;
        st.attempts += 1;
        let attempt = self
            .stepper
            .attempt(self.system, st.t, &st.x, &st.f, h_try, &mut st.stats);
        let Attempt::Done { x1, f1, err } = attempt else {
            return st.failed(t1, h_try, matches!(attempt, Attempt::NonFinite));
        };
        if !st.accepts(err.as_ref(), &x1, t1, h_try) {
            return None;
        }
        // The interpolant is only built when something reads it.
        let dense = st.needs_dense.then(|| {
            self.stepper
                .interpolant(st.t, h_try, (&st.x, &st.f), (&x1, &f1))
        });
        st.advance(t1, x1, f1, dense.as_ref())
    }

    /// The solution of a run stopped for `stop`, with the non-finite
    /// component named when it stopped on a non-finite value.
    pub(crate) fn finish(self, stop: StopReason) -> Solution<N> {
        let st = self.state;
        let non_finite = match stop {
            StopReason::NonFinite { .. } => {
                super::non_finite::probe(self.system, st.t, &st.x, &st.failed_ends)
            }
            _ => None,
        };
        Solution {
            t: st.recorder.t,
            x: st.recorder.x,
            events: st.solution_events,
            stop,
            stats: st.stats,
            t_final: st.t,
            x_final: st.x,
            non_finite,
            model_error: None,
        }
    }
}
