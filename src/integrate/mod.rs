//! Integrators for [`OdeSystem`]s: fixed-step RK4, adaptive Dormand–Prince
//! 5(4) with dense output, the L-stable Rosenbrock methods RODAS3 and
//! RODAS4 for stiff systems, and event location for all of them.
//!
//! Methods are data ([`tableau`]) run by one engine; one driver loop does
//! step control, event location and output for all of them. Expected ends
//! of an integration (end time, terminal event, step size underflow,
//! non-finite right-hand side, step budget) are values of [`StopReason`];
//! only invalid input is an [`IntegrateError`]. A model that cannot
//! evaluate its equations at a state says why
//! ([`crate::system::OdeSystem::try_rhs`]); the step is then rejected as
//! for a non-finite value, and the first such error is returned in
//! [`Solution::model_error`].
//!
//! ```
//! use nalgebra::Vector2;
//! use pegdyn::integrate::{Direction, Event, Method, Options, Solver, StopReason};
//! use pegdyn::system::FnSystem;
//!
//! // Harmonic oscillator q̈ = −q from q = 1: q first falls through zero at π/2.
//! let oscillator = FnSystem(|_t: f64, x: &Vector2<f64>| Vector2::new(x[1], -x[0]));
//! let mut solver = Solver::new(Method::Dopri5, Options::with_tolerances(1e-10, 1e-12))
//!     .with_event(Event::new(|_t, x: &Vector2<f64>| x[0]).direction(Direction::Falling).terminal());
//! let sol = solver.solve(&oscillator, 0.0, Vector2::new(1.0, 0.0), 10.0).unwrap();
//! let StopReason::Event { index: 0, t } = sol.stop else { panic!("{:?}", sol.stop) };
//! assert!((t - std::f64::consts::FRAC_PI_2).abs() < 1e-10);
//! ```

mod dense;
mod driver;
mod events;
mod explicit_rk;
mod fallible;
mod interrupt;
pub(crate) mod iteration;
pub(crate) mod kinematic;
pub(crate) mod lu;
mod method;
mod non_finite;
mod options;
mod rosenbrock;
mod solution;
mod state;
mod step_control;
pub mod tableau;

use nalgebra::SVector;

use crate::system::OdeSystem;

pub use events::{Direction, Event, EventFn};
pub use interrupt::Interrupt;
pub use method::{Method, MethodKind};
pub use non_finite::{NonFiniteAt, NonFiniteQuantity};
pub use options::{
    FALLBACK_FLOOR, IntegrateError, MAX_STEP_BUDGET, MIN_ATOL, MIN_RTOL, Options, OutputMode,
};
pub use solution::{EventHit, Solution, Stats, StopReason};

use explicit_rk::ExplicitRk;
use rosenbrock::Rosenbrock;
use state::{Hooks, Storage};
use tableau::{RosenbrockTableau, Tableau};

/// Progress callback type: called with the time after every accepted step.
pub type ProgressFn<'a> = dyn FnMut(f64) + 'a;
/// Observer callback type: called with every reported point (see
/// [`OutputMode`]), also when [`Options::store`] is off.
pub type ObserverFn<'a, const N: usize> = dyn FnMut(f64, &SVector<f64, N>) + 'a;

/// A configured integrator: method, options, events and callbacks.
pub struct Solver<'a, const N: usize> {
    method: Method,
    options: Options,
    events: Vec<Event<'a, N>>,
    progress: Option<Box<ProgressFn<'a>>>,
    observer: Option<Box<ObserverFn<'a, N>>>,
    step: Option<Box<ObserverFn<'a, N>>>,
    interrupt: Option<Interrupt>,
}

impl<'a, const N: usize> Solver<'a, N> {
    /// A solver without events or callbacks.
    pub fn new(method: Method, options: Options) -> Self {
        Solver {
            method,
            options,
            events: Vec::new(),
            progress: None,
            observer: None,
            step: None,
            interrupt: None,
        }
    }

    /// Adds an event; its index in [`StopReason::Event`] and [`EventHit`]
    /// is the number of events added before it.
    pub fn with_event(mut self, event: Event<'a, N>) -> Self {
        self.events.push(event);
        self
    }

    /// Sets the progress callback (time after each accepted step).
    pub fn with_progress(mut self, progress: impl FnMut(f64) + 'a) -> Self {
        self.progress = Some(Box::new(progress));
        self
    }

    /// Sets the observer (every reported point, e.g. to stream CSV rows).
    pub fn with_observer(mut self, observer: impl FnMut(f64, &SVector<f64, N>) + 'a) -> Self {
        self.observer = Some(Box::new(observer));
        self
    }

    /// Sets the step observer: the end of every accepted step (for a step
    /// a terminal event ends, the event's point), whatever the output
    /// mode, e.g. to take a peak that falls between two output times.
    pub fn with_step_observer(mut self, step: impl FnMut(f64, &SVector<f64, N>) + 'a) -> Self {
        self.step = Some(Box::new(step));
        self
    }

    /// Stops the integration with [`StopReason::Interrupted`] before the
    /// next attempted step once `interrupt` is requested.
    pub fn with_interrupt(mut self, interrupt: &Interrupt) -> Self {
        self.interrupt = Some(interrupt.clone());
        self
    }

    /// The options in use.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// Integrates `system` from `x0` at `t0` to `t_end` (forward in time).
    ///
    /// # Errors
    /// [`IntegrateError`] if the options, the interval or the initial state
    /// are invalid. Every other way of stopping is a [`StopReason`].
    pub fn solve<S: OdeSystem<N>>(
        &mut self,
        system: &S,
        t0: f64,
        x0: SVector<f64, N>,
        t_end: f64,
    ) -> Result<Solution<N>, IntegrateError> {
        self.options.validate(t0, t_end)?;
        if self.options.component_atol.len() > N {
            return Err(IntegrateError::InvalidOption {
                name: "component_atol",
                value: self.options.component_atol.len() as f64,
                reason: "has more entries than the state has components",
            });
        }
        if let Some((index, &value)) = x0.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(IntegrateError::NonFiniteInitialState { index, value });
        }
        let mut hooks = Hooks {
            progress: self
                .progress
                .as_deref_mut()
                .map(|p| p as &mut dyn FnMut(f64)),
            observer: self
                .observer
                .as_deref_mut()
                .map(|o| o as &mut dyn FnMut(f64, &SVector<f64, N>)),
            step: self
                .step
                .as_deref_mut()
                .map(|o| o as &mut dyn FnMut(f64, &SVector<f64, N>)),
            interrupt: self.interrupt.as_ref(),
        };
        let start = (t0, x0);
        let storage = Storage::reserve(&self.options)?;
        let (options, events) = (&self.options, self.events.as_slice());
        let checked = fallible::Checked::new(system);
        let system = &checked;
        let h = match self.method {
            Method::Rk4 { h } if !(h.is_finite() && h > 0.0) => {
                return Err(IntegrateError::InvalidOption {
                    name: "h",
                    value: h,
                    reason: "must be finite and positive",
                });
            }
            Method::Rk4 { h } => Some(h),
            Method::Dopri5 | Method::Rodas3 | Method::Rodas4 => None,
        };
        // One driver for every method; only the stepper differs.
        macro_rules! run {
            ($stepper:expr) => {
                driver::run(
                    &mut $stepper,
                    system,
                    start,
                    t_end,
                    options,
                    h,
                    events,
                    &mut hooks,
                    storage,
                )
            };
        }
        let mut solution = match self.method {
            Method::Rk4 { .. } => run!(ExplicitRk::<N, 4>::new(Tableau::rk4())),
            Method::Dopri5 => run!(ExplicitRk::<N, 7>::new(Tableau::dopri5())),
            Method::Rodas3 => run!(Rosenbrock::<N, 4>::new(&RosenbrockTableau::rodas3())),
            Method::Rodas4 => run!(Rosenbrock::<N, 6>::new(&RosenbrockTableau::rodas4())),
        };
        solution.model_error = checked.into_first();
        Ok(solution)
    }
}

/// Integrates without events or callbacks: shorthand for
/// `Solver::new(method, options.clone()).solve(system, t0, x0, t_end)`.
///
/// # Errors
/// As [`Solver::solve`].
pub fn solve<const N: usize, S: OdeSystem<N>>(
    system: &S,
    method: Method,
    (t0, x0): (f64, SVector<f64, N>),
    t_end: f64,
    options: &Options,
) -> Result<Solution<N>, IntegrateError> {
    Solver::new(method, options.clone()).solve(system, t0, x0, t_end)
}
