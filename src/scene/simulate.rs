//! Running an [`OdeSystem`] as a scene asks: map the `[integrator]` table
//! onto the integrators' [`Solver`], sample the output times, report
//! progress, and describe how the integration ended.

use nalgebra::SVector;

use crate::error::RunError;
use crate::integrate::{
    self, Event, IntegrateError, MethodKind, NonFiniteAt, NonFiniteQuantity, Options, OutputMode,
    Solution, Solver, StopReason,
};
use crate::scene::integrator::DefaultMethod;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::numbers::significant;
use crate::scene::progress::Progress;
use crate::scene::summary::{EventRecord, IntegrationSummary, StepFailure};
use crate::system::OdeSystem;

/// The integrator method and options described by `spec`, for a state
/// whose components are called `names` (`integrator.atol_scale`).
///
/// # Errors
/// [`RunError::Integrate`] for `rk4` without `h` (never for a spec that
/// passed [`IntegratorSpec::check`]); [`RunError::Field`] for an
/// `atol_scale` entry that names no state component.
pub fn solver_config(
    spec: &IntegratorSpec,
    names: &[&str],
) -> Result<(integrate::Method, Options), RunError> {
    let kind = spec.method.kind().unwrap_or(MethodKind::Dopri5);
    let method = kind.with_step(spec.h).ok_or({
        RunError::Integrate(IntegrateError::InvalidOption {
            name: "h",
            value: f64::NAN,
            reason: "is required for rk4",
        })
    })?;
    let mut options = spec.tolerances("integrator", names)?;
    options.max_steps = spec.max_steps;
    options.output = OutputMode::AtTimes(spec.try_output_times()?);
    if spec.method.is_adaptive() {
        options.h0 = spec.h;
    }
    Ok((method, options))
}

/// Integrates `system` from `x0` over the span of `spec`, sampled at
/// [`IntegratorSpec::output_times`], with `events` (non-terminal or
/// terminal), reporting progress.
///
/// # Errors
/// [`RunError::Integrate`] when the integrator rejects its input.
pub fn integrate<'a, const N: usize, S: OdeSystem<N>>(
    system: &S,
    x0: SVector<f64, N>,
    spec: &IntegratorSpec,
    events: Vec<Event<'a, N>>,
    progress: &'a mut Progress,
) -> Result<Solution<N>, RunError> {
    integrate_watching(system, x0, spec, events, progress, |_, _| {})
}

/// As [`integrate`], calling `on_step` with the end of every accepted step
/// (a terminal event's point for the step it ends), e.g. to take peaks
/// that fall between two output times.
///
/// # Errors
/// [`RunError::Integrate`] when the integrator rejects its input.
pub fn integrate_watching<'a, const N: usize, S: OdeSystem<N>>(
    system: &S,
    x0: SVector<f64, N>,
    spec: &IntegratorSpec,
    events: Vec<Event<'a, N>>,
    progress: &'a mut Progress,
    on_step: impl FnMut(f64, &SVector<f64, N>) + 'a,
) -> Result<Solution<N>, RunError> {
    let mut solver = configured(spec, system.state_names(), events, true, progress)?
        .with_progress(|t| progress.update(t))
        .with_step_observer(on_step);
    let mut sol = interrupted(solver.solve(system, spec.t0, x0, spec.t_end)?)?;
    with_final_sample(&mut sol);
    Ok(sol)
}

/// The solution, or [`RunError::Interrupted`] when a stop was requested.
fn interrupted<const N: usize>(sol: Solution<N>) -> Result<Solution<N>, RunError> {
    match sol.stop {
        StopReason::Interrupted { .. } => Err(RunError::Interrupted),
        _ => Ok(sol),
    }
}

/// Appends the final state `(t_final, x_final)` to the stored samples when
/// the last sample is earlier (a terminal event, or a stop between two
/// output times): a time series ends where its run ended, so that every
/// peak or end value read from the samples includes the end.
pub fn with_final_sample<const N: usize>(sol: &mut Solution<N>) {
    if sol.t.last().is_none_or(|&t| t < sol.t_final) {
        sol.t.push(sol.t_final);
        sol.x.push(sol.x_final);
    }
}

/// The solver of `spec` with `events`, storing its samples or not; sets
/// `progress`'s span.
fn configured<'a, const N: usize>(
    spec: &IntegratorSpec,
    names: &[&str],
    events: Vec<Event<'a, N>>,
    store: bool,
    progress: &mut Progress,
) -> Result<Solver<'a, N>, RunError> {
    let (method, mut options) = solver_config(spec, names)?;
    options.store = store;
    progress.set_span(spec.t0, spec.t_end);
    Ok(events
        .into_iter()
        .fold(Solver::new(method, options), Solver::with_event)
        .with_interrupt(progress.interrupt()))
}

/// As [`integrate`], without storing the samples: each sample goes to
/// `sink(t, x)` as the integrator reports it (in time order), then the
/// final state when it is later than the last sample (as
/// [`with_final_sample`]), so that a scene can stream its CSV in bounded
/// memory. The returned solution has empty `t` / `x`; the first error
/// `sink` returns stops further calls and is returned after the
/// integration.
///
/// # Errors
/// [`RunError::Integrate`] when the integrator rejects its input; the
/// first error of `sink`.
pub fn integrate_streaming<'a, const N: usize, S: OdeSystem<N>>(
    system: &S,
    x0: SVector<f64, N>,
    spec: &IntegratorSpec,
    events: Vec<Event<'a, N>>,
    progress: &'a mut Progress,
    mut sink: impl FnMut(f64, &SVector<f64, N>) -> Result<(), RunError> + 'a,
) -> Result<Solution<N>, RunError> {
    let solver = configured(spec, system.state_names(), events, false, progress)?;
    let mut failed: Option<RunError> = None;
    let mut last: Option<f64> = None;
    let sol = {
        let (failed, last, sink) = (&mut failed, &mut last, &mut sink);
        let mut solver = solver
            .with_progress(|t| progress.update(t))
            .with_observer(move |t, x| {
                *last = Some(t);
                if failed.is_none()
                    && let Err(e) = sink(t, x)
                {
                    *failed = Some(e);
                }
            });
        solver.solve(system, spec.t0, x0, spec.t_end)?
    };
    if failed.is_none()
        && last.is_none_or(|t| t < sol.t_final)
        && let Err(e) = sink(sol.t_final, &sol.x_final)
    {
        failed = Some(e);
    }
    match failed {
        Some(e) => Err(e),
        None => interrupted(sol),
    }
}

/// A human-readable account of `stop`, naming events by `event_names`
/// (index order; a missing name prints as `#index`).
pub fn describe_stop(stop: &StopReason, event_names: &[&str]) -> String {
    match *stop {
        StopReason::ReachedEnd => "reached t_end".into(),
        StopReason::Event { index, t } => match event_names.get(index) {
            Some(name) => format!("event `{name}` at t = {} s", significant(t)),
            None => format!("event #{index} at t = {} s", significant(t)),
        },
        StopReason::StepSizeTooSmall { t, h } => {
            format!(
                "step size too small (h = {h:.3e} s) at t = {} s",
                significant(t)
            )
        }
        StopReason::NonFinite { t } => format!(
            "state became non-finite after t = {} s (an extreme scene value: rates, loads or \
             moduli over many decades, or a tolerance below f64 resolution)",
            significant(t)
        ),
        StopReason::Interrupted { t } => {
            format!("interrupted at t = {} s", significant(t))
        }
        StopReason::MaxSteps { t, steps } => {
            format!(
                "step budget of {steps} steps exhausted at t = {} s",
                significant(t)
            )
        }
    }
}

/// [`describe_stop`], and for a non-finite stop with a probed component
/// `non_finite` ([`crate::integrate::Solution::non_finite`]): which
/// component, its last finite value, the time and the likely cause.
pub fn describe_stop_at(
    stop: &StopReason,
    non_finite: Option<&NonFiniteAt>,
    event_names: &[&str],
) -> String {
    match (stop, non_finite) {
        (StopReason::NonFinite { t }, Some(nf)) => {
            let what = match nf.quantity {
                NonFiniteQuantity::Rate => "the rate of",
                NonFiniteQuantity::State => "the state",
            };
            format!(
                "state became non-finite after t = {} s: {what} {} became {} (last finite value \
                 {}); likely cause: {}",
                significant(*t),
                nf.component(),
                nf.value,
                significant(nf.last_finite),
                nf.likely_cause()
            )
        }
        _ => describe_stop(stop, event_names),
    }
}

/// How `sol` ended and what it cost, naming events by `event_names`.
pub fn integration_summary<const N: usize>(
    spec: &IntegratorSpec,
    sol: &Solution<N>,
    event_names: &[&str],
) -> IntegrationSummary {
    IntegrationSummary {
        method: spec.resolved(DefaultMethod::NON_STIFF).0.method,
        t_end: sol.t_final,
        stop: describe_stop_at(&sol.stop, sol.non_finite.as_ref(), event_names),
        success: sol.stop.is_success(),
        steps: sol.stats.steps,
        rejected: sol.stats.rejected,
        rhs_calls: sol.stats.rhs_calls,
        events: event_records(sol, event_names),
        step_failure: match sol.stop {
            StopReason::StepSizeTooSmall { t, h } => Some(StepFailure::TooSmall { t, h }),
            StopReason::MaxSteps { t, steps } if steps > 0 => Some(StepFailure::Budget {
                t,
                mean: (t - spec.t0) / steps as f64,
            }),
            _ => None,
        },
    }
}

/// Every event of `sol` in time order, named by `event_names` (`#index`
/// when missing); the last is terminal when the integration stopped on it.
pub fn event_records<const N: usize>(sol: &Solution<N>, event_names: &[&str]) -> Vec<EventRecord> {
    let terminal_at = match sol.stop {
        StopReason::Event { index, t } => Some((index, t)),
        _ => None,
    };
    let last = sol.events.len().checked_sub(1);
    sol.events
        .iter()
        .enumerate()
        .map(|(k, hit)| {
            let name = event_names
                .get(hit.index)
                .map_or_else(|| format!("#{}", hit.index), |n| (*n).to_string());
            let direction = if hit.rising { 1.0 } else { -1.0 };
            let mut details = vec![("direction".to_string(), direction)];
            details.extend(
                hit.x
                    .iter()
                    .enumerate()
                    .map(|(i, v)| (format!("x[{i}]"), *v)),
            );
            EventRecord {
                name,
                t: hit.t,
                terminal: Some(k) == last && terminal_at == Some((hit.index, hit.t)),
                details,
            }
        })
        .collect()
}
