//! The state of one integration that does not depend on the system or the
//! method, only on the dimension (so it is compiled once per dimension):
//! step-size control, event location after an accepted step, the points
//! reported to the observer and stored, the statistics. The driver
//! (`driver.rs`) owns one and asks it, per attempted step, where the step
//! ends, whether it is accepted and what happens after it.

use nalgebra::SVector;

use super::dense::Interpolant;
use super::events::{Event, locate};
use super::options::{FALLBACK_FLOOR, Options, OutputMode};
use super::solution::{EventHit, Stats, StopReason};
use super::step_control::{PiController, error_norm};

/// Callbacks: progress after every accepted step, observer for every
/// reported point, step observer at the end of every accepted step.
pub(crate) struct Hooks<'h, const N: usize> {
    pub(crate) progress: Option<&'h mut dyn FnMut(f64)>,
    pub(crate) observer: Option<&'h mut super::ObserverFn<'h, N>>,
    pub(crate) step: Option<&'h mut super::ObserverFn<'h, N>>,
    /// A stop request looked at before every attempted step.
    pub(crate) interrupt: Option<&'h super::Interrupt>,
}

/// Room for the stored points of a run, reserved before it starts.
#[derive(Default)]
pub(crate) struct Storage<const N: usize> {
    pub(crate) t: Vec<f64>,
    pub(crate) x: Vec<SVector<f64, N>>,
}

impl<const N: usize> Storage<N> {
    /// Room for every point `options` asks to store when that number is
    /// known in advance (stored output at given times).
    ///
    /// # Errors
    /// [`super::IntegrateError::OutOfMemory`] when it cannot be reserved.
    pub(crate) fn reserve(options: &Options) -> Result<Self, super::IntegrateError> {
        let mut s = Storage::default();
        if let (true, OutputMode::AtTimes(times)) = (options.store, &options.output) {
            let n = times.len();
            if s.t.try_reserve_exact(n).is_err() || s.x.try_reserve_exact(n).is_err() {
                return Err(super::IntegrateError::OutOfMemory {
                    samples: n,
                    bytes: n as f64 * (8 * (N + 1)) as f64,
                });
            }
        }
        Ok(s)
    }
}

/// Collects the reported points according to the output mode.
pub(super) struct Recorder<'o, const N: usize> {
    pub(super) times: Option<&'o [f64]>,
    pub(super) next: usize,
    pub(super) store: bool,
    pub(super) t: Vec<f64>,
    pub(super) x: Vec<SVector<f64, N>>,
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

/// Step-size control: the step to try next and what the last attempt did.
pub(super) struct Control {
    pub(super) h: f64,
    pub(super) h_max: f64,
    /// Fixed stepping: the step and the number of steps.
    pub(super) fixed: Option<(f64, usize)>,
    /// The error controller of an adaptive method.
    pub(super) controller: Option<PiController>,
    pub(super) last_rejected: bool,
    pub(super) last_nonfinite: bool,
}

/// Everything of a run that does not depend on the system or the method
/// (only on the dimension), so that it is compiled once per dimension.
pub(super) struct State<'r, 'e, 'h, const N: usize> {
    pub(super) options: &'r Options,
    pub(super) events: &'r [Event<'e, N>],
    pub(super) hooks: &'r mut Hooks<'h, N>,
    pub(super) t0: f64,
    pub(super) t_end: f64,
    pub(super) t: f64,
    pub(super) x: SVector<f64, N>,
    pub(super) f: SVector<f64, N>,
    pub(super) stats: Stats,
    pub(super) recorder: Recorder<'r, N>,
    pub(super) control: Control,
    pub(super) needs_dense: bool,
    pub(super) attempts: usize,
    /// Event function values at the start of the current step.
    pub(super) g_prev: Vec<f64>,
    /// The events located in the current step, in time order.
    pub(super) found: Vec<EventHit<N>>,
    pub(super) solution_events: Vec<EventHit<N>>,
    /// End times of the current run of non-finite rejections, farthest
    /// first, for the probe that names the component at a NonFinite stop.
    pub(super) failed_ends: Vec<f64>,
    /// A stop found before the first step.
    pub(super) pending: Option<StopReason>,
}

impl<'r, 'e, 'h, const N: usize> State<'r, 'e, 'h, N> {
    /// The state at the start, `t0` reported; stored points go into
    /// `storage` (reserved by the caller).
    pub(super) fn new(
        (t0, x0): (f64, SVector<f64, N>),
        t_end: f64,
        options: &'r Options,
        events: &'r [Event<'e, N>],
        hooks: &'r mut Hooks<'h, N>,
        storage: Storage<N>,
    ) -> Self {
        let mut recorder = Recorder {
            times: match &options.output {
                OutputMode::EveryStep => None,
                OutputMode::AtTimes(times) => Some(times.as_slice()),
            },
            next: 0,
            store: options.store,
            t: storage.t,
            x: storage.x,
        };
        recorder.advance(t0, &x0, None, hooks);
        let needs_dense = !events.is_empty() || recorder.times.is_some();
        State {
            options,
            events,
            hooks,
            t0,
            t_end,
            t: t0,
            x: x0,
            f: SVector::zeros(),
            stats: Stats::default(),
            recorder,
            control: Control {
                h: 0.0,
                h_max: 0.0,
                fixed: None,
                controller: None,
                last_rejected: false,
                last_nonfinite: false,
            },
            needs_dense,
            attempts: 0,
            g_prev: Vec::new(),
            found: Vec::with_capacity(events.len()),
            solution_events: Vec::new(),
            failed_ends: Vec::new(),
            pending: None,
        }
    }

    /// The end of the next step (the last step lands exactly on `t_end`),
    /// or why there is none: the end reached, the step budget spent, the
    /// step under the floor of f64 resolution.
    pub(super) fn next_step_end(&mut self) -> Result<f64, StopReason> {
        if let Some(stop) = self.pending.take() {
            return Err(stop);
        }
        let (t, t_end) = (self.t, self.t_end);
        if t >= t_end {
            return Err(StopReason::ReachedEnd);
        }
        if self
            .hooks
            .interrupt
            .is_some_and(super::Interrupt::is_requested)
        {
            return Err(StopReason::Interrupted { t });
        }
        if self.attempts >= self.options.max_steps {
            return Err(StopReason::MaxSteps {
                t,
                steps: self.attempts,
            });
        }
        let c = &self.control;
        if c.h < round_off_floor(t, t_end) {
            return Err(if c.last_nonfinite {
                StopReason::NonFinite { t }
            } else {
                StopReason::StepSizeTooSmall { t, h: c.h }
            });
        }
        Ok(match c.fixed {
            Some((hf, n)) if self.stats.steps + 1 < n => {
                self.t0 + (self.stats.steps + 1) as f64 * hf
            }
            Some(_) => t_end,
            None if t + 1.01 * c.h >= t_end => t_end,
            None => t + c.h,
        })
    }

    /// An attempt that produced no step (a non-finite value, a singular
    /// iteration matrix): a fixed-step run stops, an adaptive one retries
    /// with a quarter of the step.
    pub(super) fn failed(&mut self, t1: f64, h_try: f64, nonfinite: bool) -> Option<StopReason> {
        if self.control.fixed.is_some() {
            self.failed_ends = vec![t1];
            return Some(StopReason::NonFinite { t: self.t });
        }
        self.stats.rejected += 1;
        self.control.last_rejected = true;
        self.control.last_nonfinite = nonfinite;
        if nonfinite {
            self.failed_ends.push(t1);
        }
        self.control.h = 0.25 * h_try;
        None
    }

    /// Whether the step to `(t1, x1)` with error estimate `err` is
    /// accepted; sets the next step either way.
    pub(super) fn accepts(
        &mut self,
        err: Option<&SVector<f64, N>>,
        x1: &SVector<f64, N>,
        t1: f64,
        h_try: f64,
    ) -> bool {
        let c = &mut self.control;
        if let (Some(controller), Some(err)) = (c.controller.as_mut(), err) {
            let o = &self.options;
            let n = o.error_components.unwrap_or(N);
            let mut norm = error_norm(err, (&self.x, x1), o, n);
            if let Some(m) = o.fallback_components
                && norm > 1.0
                && norm.is_finite()
                && h_try <= FALLBACK_FLOOR * round_off_floor(self.t, self.t_end)
            {
                let judged = error_norm(err, (&self.x, x1), o, m);
                if judged <= 1.0 {
                    self.stats.fallback_steps += 1;
                    norm = judged;
                }
            }
            if !norm.is_finite() {
                self.stats.rejected += 1;
                (c.last_rejected, c.last_nonfinite) = (true, true);
                self.failed_ends.push(t1);
                c.h = 0.25 * h_try;
                return false;
            }
            if norm > 1.0 {
                self.stats.rejected += 1;
                (c.last_rejected, c.last_nonfinite) = (true, false);
                c.h = controller.rejected(h_try, norm);
                return false;
            }
            let mut h_next = controller.accepted(h_try, norm);
            if c.last_rejected {
                h_next = h_next.min(h_try);
            }
            c.h = h_next.min(c.h_max);
        }
        (c.last_rejected, c.last_nonfinite) = (false, false);
        self.failed_ends.clear();
        self.stats.steps += 1;
        true
    }

    /// Moves to the accepted step's end `(t1, x1)`, `f1 = f(t1, x1)`:
    /// locates the events inside the step on `dense`, reports the points,
    /// and stops at the first terminal event.
    pub(super) fn advance(
        &mut self,
        t1: f64,
        x1: SVector<f64, N>,
        f1: SVector<f64, N>,
        dense: Option<&Interpolant<N>>,
    ) -> Option<StopReason> {
        self.found.clear();
        for (index, event) in self.events.iter().enumerate() {
            let g1 = event.eval(t1, &x1);
            self.stats.event_calls += 1;
            if let (Some(rising), Some(dense)) = (event.fires(self.g_prev[index], g1), dense) {
                let (te, xe, calls) =
                    locate(event, dense, (self.t, self.g_prev[index]), (t1, g1, &x1));
                self.stats.event_calls += calls;
                self.found.push(EventHit {
                    index,
                    t: te,
                    x: xe,
                    rising,
                });
            }
            self.g_prev[index] = g1;
        }
        self.found.sort_by(|a, b| a.t.total_cmp(&b.t));
        if let Some(p) = self
            .found
            .iter()
            .position(|hit| self.events[hit.index].is_terminal())
        {
            self.found.truncate(p + 1);
            let hit = self.found[p].clone();
            self.recorder.advance(hit.t, &hit.x, dense, self.hooks);
            self.solution_events.append(&mut self.found);
            if let Some(step) = self.hooks.step.as_mut() {
                step(hit.t, &hit.x);
            }
            if let Some(progress) = self.hooks.progress.as_mut() {
                progress(hit.t);
            }
            (self.t, self.x) = (hit.t, hit.x);
            self.failed_ends.clear();
            return Some(StopReason::Event {
                index: hit.index,
                t: hit.t,
            });
        }
        self.solution_events.append(&mut self.found);

        self.recorder.advance(t1, &x1, dense, self.hooks);
        if let Some(step) = self.hooks.step.as_mut() {
            step(t1, &x1);
        }
        if let Some(progress) = self.hooks.progress.as_mut() {
            progress(t1);
        }
        (self.t, self.x, self.f) = (t1, x1, f1);
        None
    }
}

/// The shortest step a run takes from `t` towards `t_end`:
/// `16 ε max(|t|, |t_end|)`.
fn round_off_floor(t: f64, t_end: f64) -> f64 {
    16.0 * f64::EPSILON * t.abs().max(t_end.abs()).max(f64::MIN_POSITIVE)
}
