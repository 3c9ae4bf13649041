//! The run behind a `[sensitivities]` table: a plain pass (every step
//! kept) that finds the peak contact force and the contacts that graze,
//! then the forward-sensitivity run ([`crate::sensitivity::integrate`])
//! along the `Q` scene fields integrated (`N (1 + Q)` components), stopped
//! at the peak (the event `dF_c/dt = 0` falling, armed between the plain
//! pass's steps around it) to read the peak's derivative there, and at
//! every contact event and the seating. [`widen`] places the `Q` columns
//! among all the fields (zeros for the others).
//!
//! The run's legs (before, around and after the peak) and its restarts at
//! the events share one step budget, `integrator.max_steps`.

use nalgebra::{SMatrix, SVector};

use crate::compliant_peg::directions::CompliantDirections;
use crate::compliant_peg::system::N_STATE;
use crate::integrate::{Direction, Event, Method, Options, OutputMode, Solver, StopReason};
use crate::scene::shared::sensitivities::{self, StopOrError};
use crate::sensitivity::{EventSensitivity, SensitivityError, integrate};

/// The number of contacts (`compliant_peg::sensitivity::CONTACTS`).
pub(super) const N_CONTACTS: usize = 4;

/// Event index of the seating (after the contacts').
const SEATED: usize = N_CONTACTS;
/// Event index of the peak (armed only around it).
const PEAK: usize = N_CONTACTS + 1;

/// A grazing contact: its penetration's extremum stays this close to zero
/// (relative to the run's largest penetration) without crossing it.
pub(super) const GRAZE: f64 = 1e-3;

/// What the plain pass found.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Scan {
    /// The largest force: contact, step index, value (N).
    pub peak: Option<(usize, usize, f64)>,
    /// The largest other local maximum of any contact's force (N).
    pub runner_up: f64,
    /// A contact whose penetration comes within [`GRAZE`] of zero without
    /// crossing: contact, time (s).
    pub grazing: Option<(usize, f64)>,
    /// The pass's step times.
    pub times: Vec<f64>,
    /// Which contacts penetrate at the end of the first step.
    pub first_closed: [bool; N_CONTACTS],
}

/// The derivatives the metrics are made of, along `Q` fields.
#[derive(Clone, Debug)]
pub(super) struct Derivatives<const Q: usize> {
    /// The final time and state.
    pub t: f64,
    /// The final state.
    pub y: SVector<f64, N_STATE>,
    /// `d y(T)/dq`: the final state's derivative (along the seating's
    /// moving time when the run ends seated).
    pub dy: SMatrix<f64, N_STATE, Q>,
    /// Whether the run ended seated.
    pub seated: Option<EventSensitivity<N_STATE, Q>>,
    /// The contact events in time order: contact, event.
    pub contacts: Vec<(usize, EventSensitivity<N_STATE, Q>)>,
    /// The peak: contact, time, force (N) and its derivative.
    pub peak: Option<(usize, f64, f64, SVector<f64, Q>)>,
    /// Work of the sensitivity run: accepted steps and evaluations of the
    /// variational right-hand side.
    pub work: (usize, usize),
}

/// The plain pass: every step of a Dormand–Prince run with `options`,
/// ending at `t_end` or seated.
pub(super) fn scan<const Q: usize>(
    sys: &CompliantDirections<Q>,
    (t0, y0): (f64, SVector<f64, N_STATE>),
    t_end: f64,
    target: f64,
    options: &Options,
) -> Result<Scan, SensitivityError> {
    let mut options = options.clone();
    options.output = OutputMode::EveryStep;
    options.store = true;
    let seated = Event::new(move |_, y: &SVector<f64, N_STATE>| sys.depth(y) - target)
        .direction(Direction::Rising)
        .terminal();
    let sol = Solver::<N_STATE>::new(Method::Dopri5, options)
        .with_event(seated)
        .solve(sys, t0, y0, t_end)?;
    let n = sol.x.len();
    let force: Vec<[f64; N_CONTACTS]> = sol
        .x
        .iter()
        .map(|y| std::array::from_fn(|c| sys.force(c, y)))
        .collect();
    let delta: Vec<[f64; N_CONTACTS]> = sol
        .x
        .iter()
        .map(|y| std::array::from_fn(|c| sys.delta(c, y)))
        .collect();
    let mut peak: Option<(usize, usize, f64)> = None;
    for (k, f) in force.iter().enumerate() {
        for (c, v) in f.iter().enumerate() {
            if *v > 0.0 && peak.is_none_or(|(_, _, best)| *v > best) {
                peak = Some((c, k, *v));
            }
        }
    }
    let mut runner_up = 0.0_f64;
    let mut grazing = None;
    let deepest = delta
        .iter()
        .flat_map(|d| d.iter().copied())
        .fold(0.0_f64, f64::max);
    for k in 1..n.saturating_sub(1) {
        for c in 0..N_CONTACTS {
            let (a, b, e) = (force[k - 1][c], force[k][c], force[k + 1][c]);
            if b > a && b >= e && peak.is_some_and(|(pc, pk, _)| (pc, pk) != (c, k)) {
                runner_up = runner_up.max(b);
            }
            let (a, b, e) = (delta[k - 1][c], delta[k][c], delta[k + 1][c]);
            let extremum = (b > a && b >= e && b < 0.0) || (b < a && b <= e && b > 0.0);
            if extremum && b.abs() < GRAZE * deepest && grazing.is_none() {
                grazing = Some((c, sol.t[k]));
            }
        }
    }
    let first_closed = std::array::from_fn(|c| delta.get(1).is_some_and(|d| d[c] > 0.0));
    Ok(Scan {
        peak,
        runner_up,
        grazing,
        times: sol.t,
        first_closed,
    })
}

/// The sensitivity run from `(t0, y0, ∂y₀/∂q)` to `t_end`, stopped at the
/// peak found by `scan`; `M = N (1 + Q)`. `target` is the depth of the
/// seating and `target_column` the direction that is the target depth
/// itself, if one is.
///
/// # Errors
/// [`SensitivityError::TangentialEvent`] for an event crossed tangentially;
/// [`SensitivityError::Integrate`] for a run the integrator refused.
pub(super) fn derivatives<const Q: usize, const M: usize>(
    sys: &CompliantDirections<Q>,
    start: (f64, SVector<f64, N_STATE>, SMatrix<f64, N_STATE, Q>),
    t_end: f64,
    (target, target_column): (f64, Option<usize>),
    options: &Options,
    scan: &Scan,
) -> Result<Derivatives<Q>, StopOrError> {
    let events = |peak: Option<usize>| {
        let mut e: Vec<_> = (0..N_CONTACTS).map(|c| sys.contact_event(c)).collect();
        e.push(sys.depth_event(target, target_column));
        if let Some(c) = peak {
            e.push(sys.peak_event(c));
        }
        e
    };
    let mut out = Derivatives {
        t: start.0,
        y: start.1,
        dy: start.2,
        seated: None,
        contacts: Vec::new(),
        peak: None,
        work: (0, 0),
    };
    // The legs: up to the step before the peak, to the step after it with
    // the peak armed, then to the end.
    let mut legs: Vec<(f64, Option<usize>)> = Vec::new();
    let mut peak_at_end = None;
    if let Some((c, k, _)) = scan.peak {
        let last = scan.times.len().saturating_sub(1);
        if k == 0 {
            // The peak lies on the start: read it there.
            let (g_y, g_q) = sys.force_gradient(c, &start.1);
            let d = start.2.transpose() * g_y + g_q;
            out.peak = Some((c, start.0, sys.force(c, &start.1), d));
        } else if k == last {
            peak_at_end = Some(c);
        } else {
            legs.push((scan.times[k - 1], None));
            legs.push((scan.times[k + 1], Some(c)));
        }
    }
    legs.push((t_end, None));
    let mut cur = start;
    let mut attempts = 0;
    for (to, peak) in legs {
        if to <= cur.0 {
            continue;
        }
        // The legs share the step budget.
        let leg = sensitivities::leg(options, attempts, cur.0)?;
        let run = integrate::<_, N_STATE, Q, M>(sys, cur, to, Method::Dopri5, &leg, events(peak))?;
        out.work.0 += run.stats.steps;
        out.work.1 += run.stats.rhs_calls;
        attempts += run.stats.steps + run.stats.rejected;
        for e in run.events {
            match e.index {
                c if c < N_CONTACTS => out.contacts.push((c, e)),
                SEATED => out.seated = Some(e),
                _ => {
                    let c = peak.unwrap_or(0);
                    let (g_y, g_q) = sys.force_gradient(c, &e.y);
                    let d = e.s.transpose() * g_y + g_q;
                    out.peak = Some((c, e.t, sys.force(c, &e.y), d));
                }
            }
        }
        match run.stop {
            StopReason::ReachedEnd => {}
            StopReason::Event { index, .. } if index == SEATED || index == PEAK => {}
            other => return Err(StopOrError::Stopped(other)),
        }
        cur = (run.t, run.y, run.s);
        if out.seated.is_some() {
            break;
        }
    }
    out.t = cur.0;
    out.y = cur.1;
    out.dy = match &out.seated {
        Some(e) => e.state_at_event(),
        None => cur.2,
    };
    // A peak on the final state: its derivative along the final state's.
    if let Some(c) = peak_at_end {
        let (g_y, g_q) = sys.force_gradient(c, &out.y);
        let d = out.dy.transpose() * g_y + g_q;
        out.peak = Some((c, out.t, sys.force(c, &out.y), d));
    }
    Ok(out)
}
