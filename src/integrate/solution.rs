//! What an integration returns: the trajectory, why it stopped, and what it
//! cost. Stopping early is an expected outcome, so it is a value
//! ([`StopReason`]), not an error.

use nalgebra::SVector;

/// Why the integration stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StopReason {
    /// The end time was reached.
    ReachedEnd,
    /// Terminal event number `index` (position in the solver's event list)
    /// fired at time `t`.
    Event {
        /// Index of the event in the order the events were added.
        index: usize,
        /// Located event time.
        t: f64,
    },
    /// The step size fell below the round-off floor `16 ε |t|` at time `t`
    /// (the error test kept failing, or the iteration matrix was singular).
    StepSizeTooSmall {
        /// Time of the last accepted step.
        t: f64,
        /// The rejected step size.
        h: f64,
    },
    /// The right-hand side (or the state) stayed non-finite however small
    /// the step: the solution could not be continued past `t`. The
    /// trajectory holds only finite values up to `t`.
    NonFinite {
        /// Time of the last finite accepted state.
        t: f64,
    },
    /// The step budget ([`super::Options::max_steps`], accepted plus
    /// rejected) ran out at time `t`.
    MaxSteps {
        /// Time of the last accepted step.
        t: f64,
        /// Number of attempted steps.
        steps: usize,
    },
    /// A stop was requested from outside ([`super::Interrupt`], e.g. a
    /// signal or Ctrl-C) before the step from time `t`.
    Interrupted {
        /// Time of the last accepted step.
        t: f64,
    },
}

impl StopReason {
    /// `true` for the planned ends of an integration: the end time or a
    /// terminal event.
    pub fn is_success(&self) -> bool {
        matches!(self, StopReason::ReachedEnd | StopReason::Event { .. })
    }
}

/// Work counters of one integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (error test failed, non-finite values, singular matrix).
    pub rejected: usize,
    /// Calls of [`crate::system::OdeSystem::rhs`] made by the integrator
    /// (not counting those inside a finite-difference Jacobian).
    pub rhs_calls: usize,
    /// Calls of [`crate::system::OdeSystem::jacobian`].
    pub jacobian_calls: usize,
    /// Calls of [`crate::system::OdeSystem::time_derivative`].
    pub time_derivative_calls: usize,
    /// LU factorizations of the iteration matrix.
    pub lu_factorizations: usize,
    /// Evaluations of event functions (including root finding).
    pub event_calls: usize,
    /// Accepted steps judged by [`super::Options::fallback_components`]
    /// alone (0 without a fallback).
    pub fallback_steps: usize,
}

impl std::ops::AddAssign<&Stats> for Stats {
    /// Adds the counters of a later integration (e.g. the next phase or
    /// window of a run made of several).
    fn add_assign(&mut self, s: &Stats) {
        self.steps += s.steps;
        self.rejected += s.rejected;
        self.rhs_calls += s.rhs_calls;
        self.jacobian_calls += s.jacobian_calls;
        self.time_derivative_calls += s.time_derivative_calls;
        self.lu_factorizations += s.lu_factorizations;
        self.event_calls += s.event_calls;
        self.fallback_steps += s.fallback_steps;
    }
}

/// An event that fired (terminal or not).
#[derive(Debug, Clone, PartialEq)]
pub struct EventHit<const N: usize> {
    /// Index of the event in the order the events were added.
    pub index: usize,
    /// Located time: the first time at which the event function has its
    /// new sign (within the root-finding tolerance of a few ulps of `t`).
    pub t: f64,
    /// Interpolated state at `t`.
    pub x: SVector<f64, N>,
    /// `true` if the event function went from negative to non-negative.
    pub rising: bool,
}

/// The result of an integration.
#[derive(Debug, Clone)]
pub struct Solution<const N: usize> {
    /// Output times (see [`super::OutputMode`]); empty if storing is off.
    pub t: Vec<f64>,
    /// States at the output times.
    pub x: Vec<SVector<f64, N>>,
    /// Every event that fired, in time order (a terminal event is last).
    pub events: Vec<EventHit<N>>,
    /// Why the integration stopped.
    pub stop: StopReason,
    /// Work counters.
    pub stats: Stats,
    /// Time at which the integration stopped.
    pub t_final: f64,
    /// State at `t_final` (always finite).
    pub x_final: SVector<f64, N>,
    /// For a [`StopReason::NonFinite`] stop: the first non-finite
    /// component found at the last finite state (`None` otherwise, or when
    /// the probe found every component finite).
    pub non_finite: Option<super::NonFiniteAt>,
    /// The first error the model returned
    /// ([`crate::system::OdeSystem::try_rhs`],
    /// [`crate::system::OdeSystem::try_jacobian`]), at an accepted state
    /// or a trial stage; `None` when it never refused. A refused step is
    /// rejected like a non-finite one.
    pub model_error: Option<crate::system::ModelError>,
}
