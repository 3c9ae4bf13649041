//! [`integrate`] runs the variational system with the chosen method
//! (Dormand–Prince 5(4) explicitly; RODAS3/4 with one factorization of the
//! state's `cI − J` per step serving every sensitivity column), stops at
//! every located [`SensitivityEvent`] to record `∂t_e/∂p`, and restarts
//! there (or ends at a terminal one).

use nalgebra::{SMatrix, SVector};

use super::variational::Variational;
use super::{ParameterJacobian, SensitivityError};
use crate::integrate::{Direction, Event, EventFn, Method, Options, Solver, Stats, StopReason};

/// The gradient of an event function: `(∂g/∂y, ∂g/∂p)` at `(t, y)`.
pub type EventGradient<'a, const N: usize, const P: usize> =
    dyn Fn(f64, &SVector<f64, N>) -> (SVector<f64, N>, SVector<f64, P>) + 'a;

/// Stack a Rosenbrock run needs per entry of an `M × M` matrix (bytes):
/// the methods keep the Jacobian, the iteration matrix and their
/// temporaries in their frames (between 4 and 8 MiB at `M = 208` in the
/// tests' build); below this much left, the run continues on a stack of
/// twice that, allocated on the heap. The explicit method holds no such
/// matrix.
const STACK_PER_ENTRY: usize = 8 * 32;

/// An observer of a sensitivity run: `(t, y, ∂y/∂p)` at each reported
/// point ([`integrate_observed`]).
pub type SensitivityObserver<'a, const N: usize, const P: usize> =
    dyn FnMut(f64, &SVector<f64, N>, &SMatrix<f64, N, P>) + 'a;

/// An event `g(y, p) = 0` with its gradient in the state and in the `P`
/// chosen parameters (an event function of the state and parameters only,
/// not of the time).
pub struct SensitivityEvent<'a, const N: usize, const P: usize> {
    value: Box<EventFn<'a, N>>,
    /// `None` for a stop rule ([`SensitivityEvent::stop`]).
    gradient: Option<Box<EventGradient<'a, N, P>>>,
    direction: Direction,
    terminal: bool,
}

impl<'a, const N: usize, const P: usize> SensitivityEvent<'a, N, P> {
    /// A non-terminal event `g = 0` crossed in either direction, with the
    /// gradient `(∂g/∂y, ∂g/∂p)`.
    pub fn new(
        value: impl Fn(f64, &SVector<f64, N>) -> f64 + 'a,
        gradient: impl Fn(f64, &SVector<f64, N>) -> (SVector<f64, N>, SVector<f64, P>) + 'a,
    ) -> Self {
        SensitivityEvent {
            value: Box::new(value),
            gradient: Some(Box::new(gradient)),
            direction: Direction::Both,
            terminal: false,
        }
    }

    /// A terminal event `g = 0` crossed in either direction that only ends
    /// the run (a stop rule such as a force limit): its time's derivatives
    /// are not formed and it is not listed among the run's events, so `g`
    /// may be any function of the state, a step function included.
    pub fn stop(value: impl Fn(f64, &SVector<f64, N>) -> f64 + 'a) -> Self {
        SensitivityEvent {
            value: Box::new(value),
            gradient: None,
            direction: Direction::Both,
            terminal: true,
        }
    }

    /// Sets the direction filter.
    pub fn direction(mut self, direction: Direction) -> Self {
        self.direction = direction;
        self
    }

    /// Makes the event end the integration.
    pub fn terminal(mut self) -> Self {
        self.terminal = true;
        self
    }
}

/// A located event with the derivatives of its time.
#[derive(Clone, Debug, PartialEq)]
pub struct EventSensitivity<const N: usize, const P: usize> {
    /// The event's index in the list given to [`integrate`].
    pub index: usize,
    /// Its time `t_e`, s.
    pub t: f64,
    /// The state there.
    pub y: SVector<f64, N>,
    /// The right-hand side there, `f⁻`.
    pub f: SVector<f64, N>,
    /// The sensitivities at the fixed time `t_e`, `s(t_e)`.
    pub s: SMatrix<f64, N, P>,
    /// `∂t_e/∂p = −(g_y s + g_p) / (g_y f)`.
    pub dt_dp: SVector<f64, P>,
}

impl<const N: usize, const P: usize> EventSensitivity<N, P> {
    /// The derivative of the state at the event, `d y(t_e(p))/dp =
    /// s + f ∂t_e/∂p` (zero along `g_y`'s direction for `g` without `g_p`).
    pub fn state_at_event(&self) -> SMatrix<f64, N, P> {
        self.s + self.f * self.dt_dp.transpose()
    }
}

/// The end of an [`integrate`] run.
#[derive(Clone, Debug)]
pub struct SensitivityRun<const N: usize, const P: usize> {
    /// Final time, s.
    pub t: f64,
    /// Final state.
    pub y: SVector<f64, N>,
    /// Final sensitivities `∂y/∂p` at the fixed final time.
    pub s: SMatrix<f64, N, P>,
    /// Every located event, in time order.
    pub events: Vec<EventSensitivity<N, P>>,
    /// Why the integration stopped (a terminal event other than a stop
    /// rule is also the last entry of `events`).
    pub stop: StopReason,
    /// The integrator's work summed over the restarts.
    pub stats: Stats,
}

/// The sensitivities just after an event where the right-hand side switches
/// from `f_minus` to `f_plus`: `s⁺ = s⁻ + (f⁻ − f⁺) ∂t_e/∂p`.
pub fn event_jump<const N: usize, const P: usize>(
    s_minus: &SMatrix<f64, N, P>,
    f_minus: &SVector<f64, N>,
    f_plus: &SVector<f64, N>,
    dt_dp: &SVector<f64, P>,
) -> SMatrix<f64, N, P> {
    s_minus + (f_minus - f_plus) * dt_dp.transpose()
}

/// Integrates `ẏ = f(y)` from `(t0, y0)` with its sensitivities from `s0 =
/// ∂y₀/∂p` to `t_end` by `method` (the state and the scaled sensitivities
/// as one system, error control on them with `options`' tolerances and
/// error components. A Rosenbrock method factorizes the state's `cI − J`
/// once per step for every column (the system's
/// [`OdeSystem::variational_blocks`](crate::system::OdeSystem::variational_blocks));
/// its Jacobian's coupling blocks `∂(J s + ∂f/∂p)/∂y` are forward
/// differences of the sensitivities' rate, `N + 1` rates per step. `options`'
/// output settings are ignored; `options.max_steps` bounds the attempted
/// steps of the whole run, summed over its restarts). At each event the run stops, records
/// `∂t_e/∂p`, and restarts there (the right-hand side is continuous across
/// non-terminal events, so the sensitivities do not jump; a model that
/// switches at an event ends the run with a terminal event and restarts
/// with [`event_jump`]). `M` must be `N (1 + P)`.
///
/// # Errors
/// [`SensitivityError::Dimension`] for a wrong `M`,
/// [`SensitivityError::Integrate`] for invalid options or initial values,
/// [`SensitivityError::TangentialEvent`] for an event crossed with
/// `g_y f = 0`.
pub fn integrate<S, const N: usize, const P: usize, const M: usize>(
    system: &S,
    start: (f64, SVector<f64, N>, SMatrix<f64, N, P>),
    t_end: f64,
    method: Method,
    options: &Options,
    events: Vec<SensitivityEvent<'_, N, P>>,
) -> Result<SensitivityRun<N, P>, SensitivityError>
where
    S: ParameterJacobian<N, P>,
{
    integrate_observed::<S, N, P, M>(
        system,
        start,
        t_end,
        method,
        options,
        events,
        &mut |_, _, _| {},
    )
}

/// [`integrate`], calling `observer` with `(t, y, ∂y/∂p)` at the start and
/// at the end of every accepted step (a terminal event's point replaces
/// the end of its step; a restart at an event reports that point again).
///
/// # Errors
/// As [`integrate`].
pub fn integrate_observed<S, const N: usize, const P: usize, const M: usize>(
    system: &S,
    (t0, y0, s0): (f64, SVector<f64, N>, SMatrix<f64, N, P>),
    t_end: f64,
    method: Method,
    options: &Options,
    events: Vec<SensitivityEvent<'_, N, P>>,
    observer: &mut SensitivityObserver<'_, N, P>,
) -> Result<SensitivityRun<N, P>, SensitivityError>
where
    S: ParameterJacobian<N, P>,
{
    if M != N * (1 + P) {
        return Err(SensitivityError::Dimension {
            m: M,
            expected: N * (1 + P),
        });
    }
    let scale = system
        .parameters()
        .map(|p| if p != 0.0 && p.is_finite() { p } else { 1.0 });
    let var = Variational { system, scale };
    let mut options = options.clone();
    options.store = false;
    options.output = crate::integrate::OutputMode::EveryStep;
    let (mut t, mut z) = (t0, var.pack::<M>(&y0, &s0));
    let mut stats = Stats::default();
    let mut hits = Vec::new();
    let budget = options.max_steps;
    loop {
        // The restarts share the step budget.
        let attempts = stats.steps + stats.rejected;
        let Some(left) = budget.checked_sub(attempts).filter(|n| *n > 0) else {
            let (y, s) = var.unpack(&z);
            return Ok(SensitivityRun {
                t,
                y,
                s,
                events: hits,
                stop: StopReason::MaxSteps { t, steps: attempts },
                stats,
            });
        };
        options.max_steps = left;
        let var_ref = &var;
        let observe = &mut *observer;
        let mut solver = Solver::<M>::new(method, options.clone()).with_observer(
            move |t, z: &SVector<f64, M>| {
                let (y, s) = var_ref.unpack(z);
                observe(t, &y, &s);
            },
        );
        for e in &events {
            let g = &e.value;
            solver = solver.with_event(
                Event::new(move |t, z: &SVector<f64, M>| g(t, &SVector::from_fn(|i, _| z[i])))
                    .direction(e.direction)
                    .terminal(),
            );
        }
        let need = match method {
            Method::Rodas3 | Method::Rodas4 => STACK_PER_ENTRY * M * M,
            Method::Rk4 { .. } | Method::Dopri5 => 0,
        };
        let sol = stacker::maybe_grow(need, 2 * need, || solver.solve(&var, t, z, t_end))?;
        drop(solver);
        stats += &sol.stats;
        (t, z) = (sol.t_final, sol.x_final);
        let (y, s) = var.unpack(&z);
        let StopReason::Event { index, t: te } = sol.stop else {
            // A budget run out counts the attempts of the whole run.
            let stop = match sol.stop {
                StopReason::MaxSteps { t, .. } => StopReason::MaxSteps {
                    t,
                    steps: stats.steps + stats.rejected,
                },
                other => other,
            };
            return Ok(SensitivityRun {
                t,
                y,
                s,
                events: hits,
                stop,
                stats,
            });
        };
        let e = &events[index];
        let Some(gradient) = &e.gradient else {
            return Ok(SensitivityRun {
                t,
                y,
                s,
                events: hits,
                stop: sol.stop,
                stats,
            });
        };
        let f = system.rhs(te, &y);
        let (g_y, g_p) = gradient(te, &y);
        let rate = g_y.dot(&f);
        if !(rate != 0.0 && rate.is_finite()) {
            return Err(SensitivityError::TangentialEvent { index, t: te, rate });
        }
        let dt_dp = -(s.transpose() * g_y + g_p) / rate;
        hits.push(EventSensitivity {
            index,
            t: te,
            y,
            f,
            s,
            dt_dp,
        });
        if e.terminal || te >= t_end {
            return Ok(SensitivityRun {
                t,
                y,
                s,
                events: hits,
                stop: sol.stop,
                stats,
            });
        }
    }
}
