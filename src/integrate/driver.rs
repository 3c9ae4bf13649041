//! The one integration loop shared by every method: step-size control,
//! rejection of non-finite steps, event location, output and progress.
//!
//! A method plugs in through [`Stepper`]: it attempts one step and builds
//! the interpolant of an accepted step; everything else lives here.

use nalgebra::SVector;

use crate::system::OdeSystem;

use super::dense::Interpolant;
use super::events::{Event, locate};
use super::options::{Options, OutputMode};
use super::solution::{EventHit, Solution, Stats, StopReason};
use super::step_control::{PiController, error_norm, initial_step};

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

/// Callbacks: progress after every accepted step, observer for every
/// reported point.
pub(crate) struct Hooks<'h, const N: usize> {
    pub(crate) progress: Option<&'h mut dyn FnMut(f64)>,
    pub(crate) observer: Option<&'h mut super::ObserverFn<'h, N>>,
}

/// Collects the reported points according to the output mode.
struct Recorder<'o, const N: usize> {
    times: Option<&'o [f64]>,
    next: usize,
    store: bool,
    t: Vec<f64>,
    x: Vec<SVector<f64, N>>,
}

impl<const N: usize> Recorder<'_, N> {
    fn point(&mut self, t: f64, x: &SVector<f64, N>, hooks: &mut Hooks<'_, N>) {
        if let Some(observer) = hooks.observer.as_mut() {
            observer(t, x);
        }
        if self.store {
            self.t.push(t);
            self.x.push(*x);
        }
    }

    /// Reports the points up to `t_stop`, where the state is `x_stop`;
    /// requested times inside the step come from `dense`.
    fn advance(
        &mut self,
        t_stop: f64,
        x_stop: &SVector<f64, N>,
        dense: Option<&Interpolant<N>>,
        hooks: &mut Hooks<'_, N>,
    ) {
        match self.times {
            None => self.point(t_stop, x_stop, hooks),
            Some(times) => {
                while let Some(&tau) = times.get(self.next).filter(|&&tau| tau <= t_stop) {
                    let x = match dense {
                        Some(d) if tau < t_stop => d.eval(tau),
                        _ => *x_stop,
                    };
                    self.point(tau, &x, hooks);
                    self.next += 1;
                }
            }
        }
    }
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

/// Runs `stepper` on `system` from `(t0, x0)` to `t_end`. The options must
/// have been validated; `fixed_h` selects fixed stepping.
#[allow(clippy::too_many_arguments)]
pub(crate) fn run<const N: usize, S: OdeSystem<N>, M: Stepper<N>>(
    stepper: &mut M,
    system: &S,
    (t0, x0): (f64, SVector<f64, N>),
    t_end: f64,
    options: &Options,
    fixed_h: Option<f64>,
    events: &[Event<'_, N>],
    hooks: &mut Hooks<'_, N>,
) -> Solution<N> {
    let mut stats = Stats::default();
    let mut recorder = Recorder {
        times: match &options.output {
            OutputMode::EveryStep => None,
            OutputMode::AtTimes(times) => Some(times.as_slice()),
        },
        next: 0,
        store: options.store,
        t: Vec::new(),
        x: Vec::new(),
    };
    let (mut t, mut x) = (t0, x0);
    let mut found = Vec::with_capacity(events.len());
    let mut solution_events = Vec::new();
    // End times of the current run of non-finite rejections, farthest
    // first, for the probe that names the component at a NonFinite stop.
    let mut failed_ends: Vec<f64> = Vec::new();
    let finish = |stop, t, x, stats, recorder: Recorder<'_, N>, events, failed: &[f64]| {
        let non_finite = match stop {
            StopReason::NonFinite { .. } => super::non_finite::probe(system, t, &x, failed),
            _ => None,
        };
        Solution {
            t: recorder.t,
            x: recorder.x,
            events,
            stop,
            stats,
            t_final: t,
            x_final: x,
            non_finite,
            model_error: None,
        }
    };

    recorder.advance(t0, &x0, None, hooks);
    let mut f = system.rhs(t0, &x0);
    stats.rhs_calls += 1;
    if !all_finite(&f) {
        return finish(
            StopReason::NonFinite { t },
            t,
            x,
            stats,
            recorder,
            solution_events,
            &failed_ends,
        );
    }
    let mut g_prev: Vec<f64> = events.iter().map(|e| e.eval(t0, &x0)).collect();
    stats.event_calls += events.len();

    let span = t_end - t0;
    let h_max = options.h_max.unwrap_or(span).min(span);
    let fixed = fixed_h.map(|h| (h, fixed_step_count(span, h)));
    let mut controller = stepper.controller_order().map(PiController::new);
    let mut h = match (fixed, options.h0) {
        (Some((h, _)), _) => h,
        (None, Some(h0)) => h0.min(h_max),
        (None, None) => initial_step(
            system,
            t0,
            &x0,
            &f,
            stepper.order(),
            options.rtol,
            options.atol,
            h_max,
            &mut stats,
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
    let needs_dense = !events.is_empty() || recorder.times.is_some();
    let mut last_rejected = false;
    let mut last_nonfinite = false;
    let mut attempts = 0usize;

    while t < t_end {
        if attempts >= options.max_steps {
            let stop = StopReason::MaxSteps { t, steps: attempts };
            return finish(stop, t, x, stats, recorder, solution_events, &failed_ends);
        }
        let floor = 16.0 * f64::EPSILON * t.abs().max(t_end.abs()).max(f64::MIN_POSITIVE);
        if h < floor {
            let stop = if last_nonfinite {
                StopReason::NonFinite { t }
            } else {
                StopReason::StepSizeTooSmall { t, h }
            };
            return finish(stop, t, x, stats, recorder, solution_events, &failed_ends);
        }
        // The end of this step; the last step lands exactly on t_end.
        let t1 = match fixed {
            Some((hf, n)) if stats.steps + 1 < n => t0 + (stats.steps + 1) as f64 * hf,
            Some(_) => t_end,
            None if t + 1.01 * h >= t_end => t_end,
            None => t + h,
        };
        let h_try = t1 - t;
        attempts += 1;
        let (x1, f1, err) = match stepper.attempt(system, t, &x, &f, h_try, &mut stats) {
            Attempt::Done { x1, f1, err } => (x1, f1, err),
            outcome => {
                if fixed.is_some() {
                    return finish(
                        StopReason::NonFinite { t },
                        t,
                        x,
                        stats,
                        recorder,
                        solution_events,
                        &[t1],
                    );
                }
                stats.rejected += 1;
                last_rejected = true;
                last_nonfinite = matches!(outcome, Attempt::NonFinite);
                if last_nonfinite {
                    failed_ends.push(t1);
                }
                h = 0.25 * h_try;
                continue;
            }
        };
        if let (Some(controller), Some(err)) = (controller.as_mut(), err) {
            let norm = error_norm(&err, &x, &x1, options.rtol, options.atol);
            if !norm.is_finite() {
                stats.rejected += 1;
                (last_rejected, last_nonfinite) = (true, true);
                failed_ends.push(t1);
                h = 0.25 * h_try;
                continue;
            }
            if norm > 1.0 {
                stats.rejected += 1;
                (last_rejected, last_nonfinite) = (true, false);
                h = controller.rejected(h_try, norm);
                continue;
            }
            let mut h_next = controller.accepted(h_try, norm);
            if last_rejected {
                h_next = h_next.min(h_try);
            }
            h = h_next.min(h_max);
        }
        (last_rejected, last_nonfinite) = (false, false);
        failed_ends.clear();
        stats.steps += 1;
        // The interpolant is only built when something reads it.
        let dense = needs_dense.then(|| stepper.interpolant(t, h_try, (&x, &f), (&x1, &f1)));

        found.clear();
        for (index, event) in events.iter().enumerate() {
            let g1 = event.eval(t1, &x1);
            stats.event_calls += 1;
            if let (Some(rising), Some(dense)) = (event.fires(g_prev[index], g1), &dense) {
                let (te, xe, calls) = locate(event, dense, (t, g_prev[index]), (t1, g1, &x1));
                stats.event_calls += calls;
                found.push(EventHit {
                    index,
                    t: te,
                    x: xe,
                    rising,
                });
            }
            g_prev[index] = g1;
        }
        found.sort_by(|a, b| a.t.total_cmp(&b.t));
        if let Some(p) = found.iter().position(|hit| events[hit.index].is_terminal()) {
            found.truncate(p + 1);
            let hit = found[p].clone();
            recorder.advance(hit.t, &hit.x, dense.as_ref(), hooks);
            solution_events.append(&mut found);
            if let Some(progress) = hooks.progress.as_mut() {
                progress(hit.t);
            }
            let stop = StopReason::Event {
                index: hit.index,
                t: hit.t,
            };
            return finish(stop, hit.t, hit.x, stats, recorder, solution_events, &[]);
        }
        solution_events.append(&mut found);

        recorder.advance(t1, &x1, dense.as_ref(), hooks);
        if let Some(progress) = hooks.progress.as_mut() {
            progress(t1);
        }
        (t, x, f) = (t1, x1, f1);
    }
    finish(
        StopReason::ReachedEnd,
        t,
        x,
        stats,
        recorder,
        solution_events,
        &[],
    )
}
