//! The run behind an `insert_rcc` `[sensitivities]` table: a plain pass
//! (Dormand–Prince, every step kept, the scene's terminal events) that
//! finds the largest contact and wrist forces, the onset of two-point
//! contact and whether the peg's bottom met a flat, then the
//! forward-sensitivity run ([`crate::sensitivity::integrate`]) of the
//! insertion along the design parameters ([`Directions`]), which locates,
//! each in a window of the plain pass's steps around it:
//!
//! - the seating, `depth(y) = seat_depth` (terminal): `∂t_e/∂q`;
//! - the onset of two-point contact, the gap of the pair that closes it
//!   at its stationary angle crossing zero: `∂t_e/∂q`;
//! - each peak, `dF/dt = F_y f + F_t = 0` falling: its derivative
//!   `F_y s + F_q` there (the peak time's own change drops out).
//!
//! The run's restarts at the events share one step budget,
//! `integrator.max_steps`.

use nalgebra::{SMatrix, SVector};

use crate::compliant_peg_3d::Pair;
use crate::compliant_peg_3d::design::{Design, Directions, N_DESIGN};
use crate::compliant_peg_3d::insertion::{Insertion, N_STATE, depth_tilt, peg_state};
use crate::compliant_peg_3d::outcome::{Criteria, counts, terminal_events, two_point_counts};
use crate::integrate::{Direction, Event, Method, Options, OutputMode, Solver, StopReason};
use crate::scene::shared::sensitivities::{self, StopOrError};
use crate::sensitivity::{EventSensitivity, SensitivityError, SensitivityEvent, integrate};
use crate::system::OdeSystem;

/// Components of the sensitivity run: the state and one column per design
/// parameter.
pub(super) const M: usize = N_STATE * (1 + N_DESIGN);

/// The windowed events, in the order of [`Scan::windows`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Watch {
    /// The largest contact normal force.
    ContactPeak,
    /// The largest wrist force.
    WristPeak,
    /// The onset of two-point contact: the pair that closes it and its
    /// angle (rad) at the first step in two-point contact.
    TwoPoint(Pair, u64),
}

/// A peak over the plain pass's steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Peak {
    /// The step.
    pub step: usize,
    /// The value (N).
    pub value: f64,
    /// The largest other local maximum (N).
    pub runner_up: f64,
}

/// What the plain pass found.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Scan {
    /// The pass's step times.
    pub times: Vec<f64>,
    /// The largest contact normal force.
    pub contact: Option<Peak>,
    /// The largest wrist force.
    pub wrist: Option<Peak>,
    /// The first step in two-point contact, the pair that closed last and
    /// its angle there (rad).
    pub two_point: Option<(usize, Pair, f64)>,
    /// A time at which two-point contact, once made, was lost again before
    /// the end (s).
    pub two_point_lost: Option<f64>,
    /// The first time the peg's bottom lay on a flat as a ring (s).
    pub ring: Option<f64>,
    /// Whether the pass ended seated.
    pub seated: bool,
    /// How the pass ended.
    pub stop: StopReason,
}

/// The derivatives the metrics are made of.
#[derive(Clone, Debug)]
pub(super) struct Derivatives {
    /// The final time (s).
    pub t: f64,
    /// The final state.
    pub y: SVector<f64, N_STATE>,
    /// `d y(T)/dq` (along the seating's moving time when seated).
    pub dy: SMatrix<f64, N_STATE, N_DESIGN>,
    /// The seating.
    pub seated: Option<EventSensitivity<N_STATE, N_DESIGN>>,
    /// The onset of two-point contact.
    pub two_point: Option<EventSensitivity<N_STATE, N_DESIGN>>,
    /// The largest contact force: time, value (N), derivative.
    pub contact: Option<(f64, f64, SVector<f64, N_DESIGN>)>,
    /// The largest wrist force: time, value (N), derivative.
    pub wrist: Option<(f64, f64, SVector<f64, N_DESIGN>)>,
    /// Accepted steps and evaluations of the variational right-hand side.
    pub work: (usize, usize),
}

/// The largest value of `v` over the steps and the largest other local
/// maximum.
fn peak(v: &[f64]) -> Option<Peak> {
    let (step, value) = v
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, f)| *f > 0.0)
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    let runner_up = (1..v.len().saturating_sub(1))
        .filter(|&k| k != step && v[k] > v[k - 1] && v[k] >= v[k + 1])
        .map(|k| v[k])
        .fold(0.0, f64::max);
    Some(Peak {
        step,
        value,
        runner_up,
    })
}

/// The plain pass from `(t0, y0)` to `t_end` with `options` and the
/// scene's terminal events of `criteria`.
///
/// # Errors
/// The integrator's refusal.
pub(super) fn scan(
    sys: &Insertion,
    (t0, y0): (f64, SVector<f64, N_STATE>),
    t_end: f64,
    criteria: Criteria,
    options: &Options,
) -> Result<Scan, SensitivityError> {
    let mut options = options.clone();
    options.output = OutputMode::EveryStep;
    options.store = true;
    let mut solver = Solver::<N_STATE>::new(Method::Dopri5, options);
    for e in terminal_events(sys, criteria) {
        solver = solver.with_event(e);
    }
    let sol = solver.solve(sys, t0, y0, t_end)?;
    let (mut contact, mut wrist) = (Vec::new(), Vec::new());
    let (mut two_point, mut lost, mut ring) = (None, None, None);
    let mut was = false;
    for (k, (t, y)) in sol.t.iter().zip(&sol.x).enumerate() {
        let ys = peg_state(y);
        let forces = sys.peg.forces(&ys).unwrap_or_default();
        contact.push(forces.iter().map(|f| f.normal_force).fold(0.0, f64::max));
        wrist.push(sys.wrist_load(*t, &ys).map_or(0.0, |(_, l)| l.force.norm()));
        if ring.is_none() && forces.iter().any(|f| f.contact.ring) {
            ring = Some(*t);
        }
        let found = counts(&forces.iter().map(|f| f.contact).collect::<Vec<_>>());
        let now = two_point_counts(&found);
        if now && !was && two_point.is_none() && k > 0 {
            let before = counts(&sys.contacts(&sol.x[k - 1]));
            // The pair that closed it: absent a step before (the shallower
            // of the two when both closed within one step).
            let new = [Pair::EdgeSide, Pair::RimWall]
                .into_iter()
                .filter(|p| before[p.index()] == 0)
                .filter_map(|p| {
                    forces
                        .iter()
                        .filter(|f| f.contact.pair == p && !f.contact.ring)
                        .map(|f| (p, f.contact.angle, f.contact.penetration))
                        .min_by(|a, b| a.2.total_cmp(&b.2))
                })
                .min_by(|a, b| a.2.total_cmp(&b.2));
            if let Some((p, angle, _)) = new {
                two_point = Some((k, p, angle));
            }
        }
        if was && !now && two_point.is_some() && lost.is_none() {
            lost = Some(*t);
        }
        was = now;
    }
    let seated = matches!(sol.stop, StopReason::Event { index: 0, .. });
    Ok(Scan {
        contact: peak(&contact),
        wrist: peak(&wrist),
        two_point,
        two_point_lost: lost,
        ring,
        seated,
        stop: sol.stop,
        times: sol.t,
    })
}

/// The windowed events of `scan`: each with the span of the plain pass's
/// steps in which it is armed; a peak on the start or the end is read
/// there instead.
fn windows(scan: &Scan) -> Vec<(Watch, f64, f64)> {
    let t = &scan.times;
    let last = t.len().saturating_sub(1);
    let mut out = Vec::new();
    for (watch, p) in [
        (Watch::ContactPeak, scan.contact),
        (Watch::WristPeak, scan.wrist),
    ] {
        if let Some(p) = p
            && p.step > 0
            && p.step < last
        {
            out.push((watch, t[p.step - 1], t[p.step + 1]));
        }
    }
    if let Some((k, pair, angle)) = scan.two_point {
        out.push((
            Watch::TwoPoint(pair, angle.to_bits()),
            t[k.saturating_sub(2)],
            t[k],
        ));
    }
    out
}

/// The sensitivity run of `dir` from `(t0, y0, ∂y₀/∂q)` to `t_end`, the
/// seating at `seat` (m), with the windows of `scan`; `M = N (1 + P)`.
///
/// # Errors
/// [`StopOrError`] when the integrator stops short or refuses.
pub(super) fn derivatives(
    dir: &Directions<'_>,
    start: (f64, SVector<f64, N_STATE>, SMatrix<f64, N_STATE, N_DESIGN>),
    t_end: f64,
    seat: f64,
    options: &Options,
    scan: &Scan,
) -> Result<Derivatives, StopOrError> {
    let sys = dir.system;
    let d = &dir.design;
    let prm = sys.peg.params;
    let seated = || {
        SensitivityEvent::new(
            move |_, y: &SVector<f64, N_STATE>| depth_tilt(&prm, &peg_state(y)).0 - seat,
            move |_, y| {
                let (_, g_y, g_q) = sys.depth_gradient(y, d);
                (g_y, g_q)
            },
        )
        .direction(Direction::Rising)
        .terminal()
    };
    let windows = windows(scan);
    let mut out = Derivatives {
        t: start.0,
        y: start.1,
        dy: start.2,
        seated: None,
        two_point: None,
        contact: None,
        wrist: None,
        work: (0, 0),
    };
    let mut done: Vec<Watch> = Vec::new();
    let mut cur = start;
    let mut attempts = 0;
    'legs: for to in cuts(&windows, t_end) {
        while cur.0 < to {
            let armed = armed(&windows, cur.0, to, &done);
            let mut events = vec![seated()];
            events.extend(armed.iter().map(|w| watch_event(dir, *w)));
            let leg = sensitivities::leg(options, attempts, cur.0)?;
            let run = integrate::<_, N_STATE, N_DESIGN, M>(dir, cur, to, &leg, events)?;
            out.work.0 += run.stats.steps;
            out.work.1 += run.stats.rhs_calls;
            attempts += run.stats.steps + run.stats.rejected;
            cur = (run.t, run.y, run.s);
            for e in run.events {
                if e.index == 0 {
                    out.seated = Some(e);
                    break 'legs;
                }
                let w = armed[e.index - 1];
                done.push(w);
                match w {
                    Watch::TwoPoint(..) => out.two_point = Some(e),
                    Watch::ContactPeak => {
                        out.contact = peak_at(sys, d, w, (e.t, &e.y, &e.s));
                    }
                    Watch::WristPeak => out.wrist = peak_at(sys, d, w, (e.t, &e.y, &e.s)),
                }
            }
            match run.stop {
                StopReason::ReachedEnd | StopReason::Event { .. } => {}
                other => return Err(StopOrError::Stopped(other)),
            }
        }
    }
    out.t = cur.0;
    out.y = cur.1;
    out.dy = match &out.seated {
        Some(e) => e.state_at_event(),
        None => cur.2,
    };
    let last = scan.times.len().saturating_sub(1);
    let dt_end = out.seated.as_ref().map_or(SVector::zeros(), |e| e.dt_dp);
    // A peak on the start or the end: read there.
    for (watch, p) in [
        (Watch::ContactPeak, scan.contact),
        (Watch::WristPeak, scan.wrist),
    ] {
        let Some(p) = p else { continue };
        let (t, y, s, dt) = if p.step == 0 {
            (start.0, start.1, start.2, SVector::zeros())
        } else if p.step == last {
            (out.t, out.y, out.dy, dt_end)
        } else {
            continue;
        };
        match watch {
            Watch::ContactPeak => out.contact = peak_at(sys, d, watch, (t, &y, &s)),
            _ => {
                let f_t = sys
                    .wrist_force_gradient(t, &y, d)
                    .map_or(0.0, |(.., rate)| rate);
                out.wrist =
                    peak_at(sys, d, watch, (t, &y, &s)).map(|(t, v, der)| (t, v, der + dt * f_t));
            }
        }
    }
    Ok(out)
}

/// The peak of `watch` at `(t, y)` (the largest contact force, or the
/// wrist's force) with its derivative `F_y s + F_q`.
fn peak_at(
    sys: &Insertion,
    d: &Design,
    watch: Watch,
    (t, y, s): (
        f64,
        &SVector<f64, N_STATE>,
        &SMatrix<f64, N_STATE, N_DESIGN>,
    ),
) -> Option<(f64, f64, SVector<f64, N_DESIGN>)> {
    let (f, g_y, g_q) = if watch == Watch::ContactPeak {
        let (i, _) = sys.peak_contact(y).ok()??;
        sys.normal_force_gradient(y, i, d).ok()??
    } else {
        let (f, g_y, g_q, _) = sys.wrist_force_gradient(t, y, d)?;
        (f, g_y, g_q)
    };
    Some((t, f, s.transpose() * g_y + g_q))
}

/// The value of a windowed watch's event function: a peak's `dF/dt`
/// (`F_y f + F_t`), or the closing pair's gap at its stationary angle.
fn watch_value<'a>(
    dir: &'a Directions<'a>,
    w: Watch,
) -> impl Fn(f64, &SVector<f64, N_STATE>) -> f64 + Copy + 'a {
    let sys = dir.system;
    let d = &dir.design;
    move |t: f64, y: &SVector<f64, N_STATE>| -> f64 {
        match w {
            Watch::ContactPeak => sys
                .peak_contact(y)
                .ok()
                .flatten()
                .and_then(|(i, _)| sys.normal_force_gradient(y, i, d).ok().flatten())
                .map_or(0.0, |(_, g_y, _)| g_y.dot(&sys.rhs(t, y))),
            Watch::WristPeak => sys
                .wrist_force_gradient(t, y, d)
                .map_or(0.0, |(_, g_y, _, f_t)| g_y.dot(&sys.rhs(t, y)) + f_t),
            Watch::TwoPoint(pair, bits) => sys
                .stationary_gap(y, pair, f64::from_bits(bits))
                .map_or(1.0, |(g, _)| g),
        }
    }
}

/// The event of a windowed watch ([`watch_value`] falling through zero):
/// for a peak with the gradient in the state by central differences and
/// none in the parameters (the peak's derivative does not use its time's);
/// for the two-point onset with the gap's exact gradients.
fn watch_event<'a>(dir: &'a Directions<'a>, w: Watch) -> SensitivityEvent<'a, N_STATE, N_DESIGN> {
    let (sys, d) = (dir.system, &dir.design);
    let value = watch_value(dir, w);
    let event = match w {
        Watch::TwoPoint(pair, bits) => SensitivityEvent::new(value, move |_, y| {
            sys.gap_gradient(y, pair, f64::from_bits(bits), d)
                .map_or((SVector::zeros(), SVector::zeros()), |(_, g_y, g_q)| {
                    (g_y, g_q)
                })
        }),
        _ => SensitivityEvent::new(value, move |t, y| {
            let g_y = SVector::from_fn(|i, _| {
                let h = 1e-7 * y[i].abs().max(1e-6);
                let (mut up, mut down) = (*y, *y);
                up[i] += h;
                down[i] -= h;
                (value(t, &up) - value(t, &down)) / (2.0 * h)
            });
            (g_y, SVector::zeros())
        }),
    };
    event.direction(Direction::Falling).terminal()
}

/// The metrics' values of a plain run (no sensitivities) with the events
/// of [`derivatives`]: the seat time, the final depth, the peaks, the
/// two-point onset's time and depth, each with its index in
/// [`super::metrics::METRICS`].
///
/// # Errors
/// [`StopOrError`] when the integrator stops short or refuses.
pub(super) fn values(
    dir: &Directions<'_>,
    start: (f64, SVector<f64, N_STATE>),
    t_end: f64,
    seat: f64,
    options: &Options,
    scan: &Scan,
) -> Result<Vec<(usize, f64)>, StopOrError> {
    let sys = dir.system;
    let d = &dir.design;
    let prm = sys.peg.params;
    let windows = windows(scan);
    let mut out = Vec::new();
    let mut done: Vec<Watch> = Vec::new();
    let mut cur = start;
    'legs: for to in cuts(&windows, t_end) {
        while cur.0 < to {
            let armed: Vec<Watch> = armed(&windows, cur.0, to, &done);
            let mut solver = Solver::<N_STATE>::new(Method::Dopri5, options.clone()).with_event(
                Event::new(move |_, y: &SVector<f64, N_STATE>| {
                    depth_tilt(&prm, &peg_state(y)).0 - seat
                })
                .direction(Direction::Rising)
                .terminal(),
            );
            for w in &armed {
                solver = solver.with_event(
                    Event::new(watch_value(dir, *w))
                        .direction(Direction::Falling)
                        .terminal(),
                );
            }
            let sol = solver
                .solve(sys, cur.0, cur.1, to)
                .map_err(|e| StopOrError::Error(e.into()))?;
            cur = (sol.t_final, sol.x_final);
            match sol.stop {
                StopReason::ReachedEnd => {}
                StopReason::Event { index: 0, t } => {
                    out.push((0, t));
                    break 'legs;
                }
                StopReason::Event { index, t } => {
                    let w = armed[index - 1];
                    done.push(w);
                    let y = &sol.x_final;
                    match w {
                        Watch::ContactPeak => {
                            if let Ok(Some((_, f))) = sys.peak_contact(y) {
                                out.push((2, f));
                            }
                        }
                        Watch::WristPeak => {
                            if let Some((f, ..)) = sys.wrist_force_gradient(t, y, d) {
                                out.push((3, f));
                            }
                        }
                        Watch::TwoPoint(..) => {
                            out.push((4, t));
                            out.push((5, depth_tilt(&prm, &peg_state(y)).0));
                        }
                    }
                }
                other => return Err(StopOrError::Stopped(other)),
            }
        }
    }
    out.push((1, depth_tilt(&prm, &peg_state(&cur.1)).0));
    let last = scan.times.len().saturating_sub(1);
    for (k, p) in [(2, scan.contact), (3, scan.wrist)] {
        if let Some(p) = p
            && (p.step == 0 || p.step == last)
        {
            let (t, y) = if p.step == 0 { start } else { cur };
            let f = if k == 2 {
                sys.peak_contact(&y).ok().flatten().map(|(_, f)| f)
            } else {
                sys.wrist_force_gradient(t, &y, d).map(|(f, ..)| f)
            };
            out.extend(f.map(|f| (k, f)));
        }
    }
    Ok(out)
}

/// The legs' ends: the windows' ends, then `t_end`, in order.
fn cuts(windows: &[(Watch, f64, f64)], t_end: f64) -> Vec<f64> {
    let mut cuts: Vec<f64> = windows.iter().flat_map(|w| [w.1, w.2]).collect();
    cuts.push(t_end);
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    cuts
}

/// The watches armed on a leg from `from` to `to`: those whose window
/// covers it and that have not fired.
fn armed(windows: &[(Watch, f64, f64)], from: f64, to: f64, done: &[Watch]) -> Vec<Watch> {
    windows
        .iter()
        .filter(|w| w.1 <= from && to <= w.2 && !done.contains(&w.0))
        .map(|w| w.0)
        .collect()
}
