//! The run behind an `insert_rcc` `[sensitivities]` table: one
//! forward-sensitivity run ([`crate::sensitivity::integrate_observed`]) of
//! the insertion along the design parameters ([`Directions`]) with the
//! scene's terminal events (the seating with `∂t_e/∂q`, the others as
//! stop rules), which records at every step the largest contact and wrist
//! forces, the onset of two-point contact and whether the peg's bottom met
//! a flat ([`Scan`]), keeping the points where the windows around them
//! start. Each windowed event is then located by integrating its window
//! again from its kept start, with the run's step there:
//!
//! - the onset of two-point contact, the gap of the pair that closes it
//!   at its stationary angle crossing zero: `∂t_e/∂q`;
//! - each peak, `dF/dt = F_y f + F_t = 0` falling: its derivative
//!   `F_y s + F_q` there (the peak time's own change drops out).
//!
//! The plain run of [`values`] does the same without sensitivities, so
//! that differences of its metrics check the derivatives. With the error
//! controlled on the state only, both runs take the same steps.

use nalgebra::{SMatrix, SVector};

use crate::compliant_peg_3d::Pair;
use crate::compliant_peg_3d::design::{Design, Directions, N_DESIGN};
use crate::compliant_peg_3d::insertion::{Insertion, N_STATE, depth_tilt, peg_state};
use crate::compliant_peg_3d::no_jam::MarginLoad;
use crate::compliant_peg_3d::outcome::{
    Criteria, counts, counts_of, terminal_conditions, two_point_counts,
};
use crate::integrate::{Direction, Event, Method, Options, OutputMode, Solver, Stats, StopReason};
use crate::scene::shared::sensitivities::StopOrError;
use crate::sensitivity::{
    EventSensitivity, SensitivityError, SensitivityEvent, integrate, integrate_observed,
};
use crate::system::OdeSystem;

/// Components of the sensitivity run: the state and one column per design
/// parameter.
pub(super) const M: usize = N_STATE * (1 + N_DESIGN);

/// The sensitivities of a point of the run.
type Columns = SMatrix<f64, N_STATE, N_DESIGN>;

/// The windowed events.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Watch {
    /// The largest contact normal force.
    ContactPeak,
    /// The largest wrist force.
    WristPeak,
    /// The onset of two-point contact: the pair that closes it and its
    /// angle (rad) at the first step in two-point contact.
    TwoPoint(Pair, u64),
    /// The least no-jam margin inside a stretch of two-point contact.
    LeastMargin,
}

/// A peak over the run's steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Peak {
    /// The step.
    pub step: usize,
    /// The value (N).
    pub value: f64,
    /// The largest other local maximum (N).
    pub runner_up: f64,
}

/// The least no-jam margin over the run's steps in two-point contact in
/// the bore.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Least {
    /// The step.
    pub step: usize,
    /// The value.
    pub value: f64,
    /// The least other local minimum (infinite without one).
    pub runner_up: f64,
    /// Whether the step is the first of its stretch of two-point contact
    /// in the bore (the least value then lies at the stretch's start).
    pub first: bool,
}

/// What the run found at its steps.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Scan {
    /// The run's step times.
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
    /// The least no-jam margin in two-point contact in the bore.
    pub margin: Option<Least>,
    /// Whether the run ended seated.
    pub seated: bool,
    /// How the run ended.
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
    pub dy: Columns,
    /// The seating.
    pub seated: Option<EventSensitivity<N_STATE, N_DESIGN>>,
    /// The onset of two-point contact.
    pub two_point: Option<EventSensitivity<N_STATE, N_DESIGN>>,
    /// The largest contact force: time, value (N), derivative.
    pub contact: Option<(f64, f64, SVector<f64, N_DESIGN>)>,
    /// The largest wrist force: time, value (N), derivative.
    pub wrist: Option<(f64, f64, SVector<f64, N_DESIGN>)>,
    /// The least no-jam margin: value, derivative and the gap to the
    /// parallelogram's next edge, or why it was not located.
    pub margin: Option<Result<LeastMargin, String>>,
    /// The work of the run and its windows (their counters summed).
    pub work: Stats,
}

/// The least no-jam margin located: its value, derivative and the gap to
/// the parallelogram's next edge there.
#[derive(Clone, Debug)]
pub(super) struct LeastMargin {
    /// The value.
    pub value: f64,
    /// `dm/dq`.
    pub derivative: SVector<f64, N_DESIGN>,
    /// How much farther the next edge is.
    pub edge_gap: f64,
}

/// The least value of `v` over the steps where it is a number, the least
/// other local minimum, and whether its step starts a stretch of numbers.
/// Values of the least one's stretch within [`FLAT`] of it are one flat
/// minimum (a margin that stays flat after the stretch starts, to the
/// run's error, wiggling at rounding): it is taken at the first of them,
/// whatever steps the run took in between, and none of them is another
/// minimum.
fn least(v: &[f64]) -> Option<Least> {
    let (min_step, value) = v
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, m)| !m.is_nan())
        .min_by(|a, b| a.1.total_cmp(&b.1))?;
    let flat = |k: usize| v[k] - value <= FLAT * value.abs().max(1.0);
    let start = (0..=min_step)
        .rev()
        .take_while(|&k| !v[k].is_nan())
        .last()
        .unwrap_or(min_step);
    let end = (min_step..v.len())
        .take_while(|&k| !v[k].is_nan())
        .last()
        .unwrap_or(min_step);
    let step = (start..=min_step).find(|&k| flat(k)).unwrap_or(min_step);
    let same = |k: usize| (start..=end).contains(&k) && flat(k);
    let runner_up = (1..v.len().saturating_sub(1))
        .filter(|&k| !same(k) && v[k] < v[k - 1] && v[k] <= v[k + 1])
        .map(|k| v[k])
        .fold(f64::INFINITY, f64::min);
    Some(Least {
        step,
        value,
        runner_up,
        first: step == 0 || v[step - 1].is_nan(),
    })
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

/// A reported point of a run: its step, time, state and what else the run
/// carries there (the sensitivities, or nothing).
#[derive(Clone, Debug)]
struct Point<X> {
    step: usize,
    t: f64,
    y: SVector<f64, N_STATE>,
    x: X,
}

/// Watches a run's reported points: the forces and contacts of
/// [`Scan`], and the points where the windows of its events start (the
/// step before the largest force so far; two steps before the first in
/// two-point contact).
struct Tracker<'a, X> {
    sys: &'a Insertion,
    times: Vec<f64>,
    contact: Vec<f64>,
    wrist: Vec<f64>,
    /// The no-jam margin in two-point contact in the bore (NaN elsewhere).
    margin: Vec<f64>,
    /// The last two points, newest first.
    recent: Vec<Point<X>>,
    /// The largest contact and wrist forces so far (N).
    largest: (f64, f64),
    contact_from: Option<Point<X>>,
    wrist_from: Option<Point<X>>,
    /// The least margin so far and the point before it.
    least: f64,
    margin_from: Option<Point<X>>,
    two_point: Option<(usize, Pair, f64)>,
    two_point_from: Option<Point<X>>,
    lost: Option<f64>,
    ring: Option<f64>,
    was: bool,
}

/// Where the windows start: the kept points of [`Tracker`].
struct Starts<X> {
    contact: Option<Point<X>>,
    wrist: Option<Point<X>>,
    two_point: Option<Point<X>>,
    margin: Option<Point<X>>,
}

impl<'a, X: Clone> Tracker<'a, X> {
    fn new(sys: &'a Insertion) -> Self {
        Tracker {
            sys,
            times: Vec::new(),
            contact: Vec::new(),
            wrist: Vec::new(),
            margin: Vec::new(),
            recent: Vec::with_capacity(3),
            largest: (0.0, 0.0),
            contact_from: None,
            wrist_from: None,
            least: f64::INFINITY,
            margin_from: None,
            two_point: None,
            two_point_from: None,
            lost: None,
            ring: None,
            was: false,
        }
    }

    /// Takes the point `(t, y)` carrying `x`; a point not after the last
    /// (a restart's repeat) is skipped.
    fn observe(&mut self, t: f64, y: &SVector<f64, N_STATE>, x: &X) {
        if self.times.last().is_some_and(|last| t <= *last) {
            return;
        }
        let sys = self.sys;
        let k = self.times.len();
        let ys = peg_state(y);
        let forces = sys.peg.forces(&ys).unwrap_or_default();
        let contact = forces.iter().map(|f| f.normal_force).fold(0.0, f64::max);
        let wrist = sys.wrist_load(t, &ys).map_or(0.0, |(_, l)| l.force.norm());
        // The largest so far, the later of equals (as `peak` chooses).
        if contact > 0.0 && contact >= self.largest.0 {
            self.largest.0 = contact;
            self.contact_from = self.recent.first().cloned();
        }
        if wrist > 0.0 && wrist >= self.largest.1 {
            self.largest.1 = wrist;
            self.wrist_from = self.recent.first().cloned();
        }
        if self.ring.is_none() && forces.iter().any(|f| f.contact.ring) {
            self.ring = Some(t);
        }
        let found = counts_of(forces.iter().map(|f| f.contact.pair));
        let now = two_point_counts(&found);
        if now
            && !self.was
            && self.two_point.is_none()
            && let Some(previous) = self.recent.first()
        {
            let before = counts(&sys.contacts(&previous.y));
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
                self.two_point = Some((k, p, angle));
                self.two_point_from = self.recent.last().cloned();
            }
        }
        if self.was && !now && self.two_point.is_some() && self.lost.is_none() {
            self.lost = Some(t);
        }
        self.was = now;
        // The margin in two-point contact in the bore, as the summary's.
        let margin = (now && depth_tilt(&sys.peg.params, &ys).0 > sys.peg.params.mouth_fillet)
            .then(|| sys.no_jam_margin(t, y, MarginLoad::Applied).ok().flatten())
            .flatten()
            .map_or(f64::NAN, |m| m.value);
        if margin <= self.least {
            self.least = margin;
            self.margin_from = self.recent.first().cloned();
        }
        self.times.push(t);
        self.contact.push(contact);
        self.wrist.push(wrist);
        self.margin.push(margin);
        self.recent.insert(
            0,
            Point {
                step: k,
                t,
                y: *y,
                x: x.clone(),
            },
        );
        self.recent.truncate(2);
    }

    /// The scan of the run that ended with `stop`, and the windows'
    /// starts (a start that is not the step its window needs is dropped).
    fn finish(self, stop: StopReason) -> (Scan, Starts<X>) {
        let scan = Scan {
            contact: peak(&self.contact),
            wrist: peak(&self.wrist),
            two_point: self.two_point,
            two_point_lost: self.lost,
            ring: self.ring,
            margin: least(&self.margin),
            seated: matches!(stop, StopReason::Event { index: 0, .. }),
            stop,
            times: self.times,
        };
        let at = |p: Option<Point<X>>, step: Option<usize>| {
            p.filter(|p| step.is_some_and(|s| s > 0 && p.step == s - 1))
        };
        let starts = Starts {
            contact: at(self.contact_from, scan.contact.map(|p| p.step)),
            wrist: at(self.wrist_from, scan.wrist.map(|p| p.step)),
            two_point: self.two_point_from.filter(|p| {
                scan.two_point
                    .is_some_and(|(k, ..)| p.step == k.saturating_sub(2))
            }),
            margin: at(self.margin_from, scan.margin.map(|m| m.step)),
        };
        (scan, starts)
    }
}

/// The windows of `scan` with their kept starts: each watch, the point
/// its window starts from, the step the run took there and the window's
/// end (one step past a peak; the first step in two-point contact). A
/// peak on the start or the end has none: it is read there.
fn windows<X>(scan: &Scan, starts: Starts<X>) -> Vec<(Watch, Point<X>, f64, f64)> {
    let t = &scan.times;
    let last = t.len().saturating_sub(1);
    let mut out = Vec::new();
    let step = |p: &Point<X>| t.get(p.step + 1).map_or(0.0, |next| next - p.t);
    for (watch, peak, start) in [
        (Watch::ContactPeak, scan.contact, starts.contact),
        (Watch::WristPeak, scan.wrist, starts.wrist),
    ] {
        if let (Some(p), Some(start)) = (peak, start)
            && p.step < last
        {
            let h = step(&start);
            out.push((watch, start, h, t[p.step + 1]));
        }
    }
    if let (Some((k, pair, angle)), Some(start)) = (scan.two_point, starts.two_point) {
        let h = step(&start);
        out.push((Watch::TwoPoint(pair, angle.to_bits()), start, h, t[k]));
    }
    if let (Some(m), Some(start)) = (scan.margin, starts.margin)
        && !m.first
        && m.step < last
    {
        let h = step(&start);
        out.push((Watch::LeastMargin, start, h, t[m.step + 1]));
    }
    out
}

/// Where the least no-jam margin of `scan` lies.
#[derive(Clone, Copy, Debug, PartialEq)]
enum LeastAt {
    /// Inside a stretch of two-point contact: located by its window.
    Inside,
    /// At the onset of two-point contact (located with it).
    Onset,
    /// At the run's end.
    End,
}

/// Where the least margin of `scan` lies, or why it is not located: at
/// the start of a stretch of two-point contact in the bore that is not
/// the located onset of two-point contact (the tip passing the mouth
/// round's depth, or two-point contact made again).
fn least_at(scan: &Scan) -> Option<Result<LeastAt, String>> {
    let m = scan.margin?;
    let last = scan.times.len().saturating_sub(1);
    Some(if m.step == last {
        Ok(LeastAt::End)
    } else if !m.first {
        Ok(LeastAt::Inside)
    } else if scan.two_point.is_some_and(|(k, ..)| k == m.step) {
        Ok(LeastAt::Onset)
    } else {
        Err(format!(
            "the least no-jam margin lies where a stretch of two-point contact in the bore \
             starts at t = {:.6e} s, not at the onset of two-point contact (the tip passing \
             the mouth round's depth, or two-point contact made again): not located",
            scan.times[m.step]
        ))
    })
}

/// The least margin at the located onset `e` of two-point contact: the
/// applied load's value, and the derivative of the contacts' resultant's
/// margin along the onset's moving time (`m_y (s + f ∂t_e/∂q) + m_q`,
/// the module documentation of [`crate::compliant_peg_3d::no_jam`]),
/// when the two agree (the peg's inertia negligible) and the onset lies
/// below the least value at the steps (to [`FLAT`]).
fn margin_at_onset(
    sys: &Insertion,
    d: &Design,
    e: &EventSensitivity<N_STATE, N_DESIGN>,
    at_steps: f64,
) -> Result<LeastMargin, String> {
    let applied = sys
        .no_jam_margin(e.t, &e.y, MarginLoad::Applied)
        .ok()
        .flatten()
        .ok_or("the no-jam margin has no plane at the onset of two-point contact")?;
    if applied.value > at_steps + FLAT * at_steps.abs().max(1.0) {
        return Err(format!(
            "the no-jam margin falls after the onset of two-point contact ({:.6e} there, \
             {at_steps:.6e} at a step): its least value inside the first step is not located",
            applied.value
        ));
    }
    let (contacts, g_y, g_q, _) = sys
        .no_jam_margin_gradient(e.t, &e.y, d, MarginLoad::Contacts)
        .ok()
        .flatten()
        .ok_or("the contacts' resultant has no plane at the onset of two-point contact")?;
    let inertia = (contacts - applied.value).abs();
    if inertia > INERTIA_TOLERANCE * applied.value.abs().max(1.0) {
        return Err(format!(
            "the peg's inertia moves the no-jam margin by {inertia:.3e} at the onset of \
             two-point contact: the contacts' resultant does not stand for the applied load"
        ));
    }
    Ok(LeastMargin {
        value: applied.value,
        derivative: e.state_at_event().transpose() * g_y + g_q,
        edge_gap: applied.edge_gap,
    })
}

/// How far (relative to the margin, or absolute below 1) the margin at
/// the first step in two-point contact may lie below its value at the
/// onset for the onset to stand as the least: the steady slide's margin is
/// flat to the runs' error there.
const FLAT: f64 = 1e-9;

/// The largest difference between the margins of the applied load and of
/// the contacts' resultant (relative to the margin, or absolute below 1)
/// at which the second's derivative stands for the first's.
const INERTIA_TOLERANCE: f64 = 1e-6;

/// The least margin of the applied load at `(t, y)` with the state's
/// derivative `dy` and the time's `dt` (zero at a fixed time).
fn margin_reading(
    sys: &Insertion,
    d: &Design,
    (t, y, dy, dt): (
        f64,
        &SVector<f64, N_STATE>,
        &Columns,
        SVector<f64, N_DESIGN>,
    ),
) -> Result<LeastMargin, String> {
    let none = || "the no-jam margin has no plane at its least value".to_owned();
    let m = sys
        .no_jam_margin(t, y, MarginLoad::Applied)
        .ok()
        .flatten()
        .ok_or_else(none)?;
    let (_, g_y, g_q, rate) = sys
        .no_jam_margin_gradient(t, y, d, MarginLoad::Applied)
        .ok()
        .flatten()
        .ok_or_else(none)?;
    Ok(LeastMargin {
        value: m.value,
        derivative: dy.transpose() * g_y + g_q + dt * rate,
        edge_gap: m.edge_gap,
    })
}

/// The options of a window's run: `options` starting with the step `h`
/// the run took there.
fn window_options(options: &Options, h: f64) -> Options {
    Options {
        h0: (h > 0.0).then_some(h),
        ..options.clone()
    }
}

/// The sensitivity run of `dir` from `(t0, y0, ∂y₀/∂q)` to `t_end` with
/// the terminal events of `criteria` (the seating with its derivatives),
/// then its windows: the scan and the derivatives.
///
/// # Errors
/// [`StopOrError`] when the integrator stops short or refuses.
pub(super) fn derivatives(
    dir: &Directions<'_>,
    start: (f64, SVector<f64, N_STATE>, Columns),
    t_end: f64,
    criteria: Criteria,
    (method, options): (Method, &Options),
) -> Result<(Scan, Derivatives), StopOrError> {
    let sys = dir.system;
    let d = &dir.design;
    let mut events = Vec::new();
    for (k, g) in terminal_conditions(sys, criteria).into_iter().enumerate() {
        let event = if k == 0 {
            SensitivityEvent::new(g, move |_, y| {
                let (_, g_y, g_q) = sys.depth_gradient(y, d);
                (g_y, g_q)
            })
            .terminal()
        } else {
            SensitivityEvent::stop(g)
        };
        events.push(event.direction(Direction::Rising));
    }
    let mut tracker = Tracker::<Columns>::new(sys);
    let run = integrate_observed::<_, N_STATE, N_DESIGN, M>(
        dir,
        start,
        t_end,
        method,
        options,
        events,
        &mut |t, y, s| tracker.observe(t, y, s),
    )?;
    match run.stop {
        StopReason::ReachedEnd | StopReason::Event { .. } => {}
        other => return Err(StopOrError::Stopped(other)),
    }
    let (scan, starts) = tracker.finish(run.stop);
    let seated = run.events.into_iter().find(|e| e.index == 0);
    let mut out = Derivatives {
        t: run.t,
        y: run.y,
        dy: seated.as_ref().map_or(run.s, |e| e.state_at_event()),
        seated,
        two_point: None,
        contact: None,
        wrist: None,
        margin: None,
        work: run.stats,
    };
    for (watch, from, h, to) in windows(&scan, starts) {
        let leg = window_options(options, h);
        let w = integrate::<_, N_STATE, N_DESIGN, M>(
            dir,
            (from.t, from.y, from.x),
            to,
            method,
            &leg,
            vec![watch_event(dir, watch)],
        )?;
        out.work += &w.stats;
        let Some(e) = w.events.into_iter().next() else {
            continue;
        };
        match watch {
            Watch::TwoPoint(..) => out.two_point = Some(e),
            Watch::LeastMargin => {
                out.margin = Some(margin_reading(sys, d, (e.t, &e.y, &e.s, SVector::zeros())));
            }
            Watch::ContactPeak | Watch::WristPeak => {
                let found = peak_at(sys, d, watch, (e.t, &e.y, &e.s));
                if watch == Watch::ContactPeak {
                    out.contact = found;
                } else {
                    out.wrist = found;
                }
            }
        }
    }
    let last = scan.times.len().saturating_sub(1);
    let dt_end = out.seated.as_ref().map_or(SVector::zeros(), |e| e.dt_dp);
    out.margin = match least_at(&scan) {
        None => None,
        Some(Err(reason)) => Some(Err(reason)),
        Some(Ok(LeastAt::Inside)) => Some(out.margin.take().unwrap_or_else(|| {
            Err("the least no-jam margin inside two-point contact was not located".to_owned())
        })),
        Some(Ok(LeastAt::Onset)) => Some(match (&out.two_point, scan.margin) {
            (Some(e), Some(m)) => margin_at_onset(sys, d, e, m.value),
            _ => Err("the onset of two-point contact was not located".to_owned()),
        }),
        Some(Ok(LeastAt::End)) => Some(margin_reading(sys, d, (out.t, &out.y, &out.dy, dt_end))),
    };
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
    Ok((scan, out))
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
/// (`F_y f + F_t`), the closing pair's gap at its stationary angle, or
/// minus the margin's rate `−(m_y f + m_t)` (falling through zero at the
/// least margin).
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
            Watch::LeastMargin => sys
                .no_jam_margin_gradient(t, y, d, MarginLoad::Applied)
                .ok()
                .flatten()
                .map_or(0.0, |(_, g_y, _, m_t)| -(g_y.dot(&sys.rhs(t, y)) + m_t)),
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

/// The metrics' values of the plain run of [`derivatives`] (no
/// sensitivities: the same terminal events, the same windows): the seat
/// time, the final depth, the peaks, the two-point onset's time and
/// depth, each with its index in [`super::metrics::METRICS`].
///
/// # Errors
/// [`StopOrError`] when the integrator stops short or refuses.
pub(super) fn values(
    dir: &Directions<'_>,
    start: (f64, SVector<f64, N_STATE>),
    t_end: f64,
    criteria: Criteria,
    (method, options): (Method, &Options),
) -> Result<Vec<(usize, f64)>, StopOrError> {
    let sys = dir.system;
    let d = &dir.design;
    let prm = sys.peg.params;
    let plain = |options: Options| {
        Solver::<N_STATE>::new(
            method,
            Options {
                output: OutputMode::EveryStep,
                store: false,
                ..options
            },
        )
    };
    let mut tracker = Tracker::<()>::new(sys);
    let sol = {
        let mut solver = plain(options.clone()).with_observer(|t, y: &SVector<f64, N_STATE>| {
            tracker.observe(t, y, &());
        });
        for g in terminal_conditions(sys, criteria) {
            solver = solver.with_event(Event::new(g).direction(Direction::Rising).terminal());
        }
        solver
            .solve(sys, start.0, start.1, t_end)
            .map_err(|e| StopOrError::Error(SensitivityError::from(e)))?
    };
    match sol.stop {
        StopReason::ReachedEnd | StopReason::Event { .. } => {}
        other => return Err(StopOrError::Stopped(other)),
    }
    let (scan, starts) = tracker.finish(sol.stop);
    let least = least_at(&scan);
    let end = (sol.t_final, sol.x_final);
    let mut out = Vec::new();
    if scan.seated {
        out.push((0, end.0));
    }
    out.push((1, depth_tilt(&prm, &peg_state(&end.1)).0));
    for (watch, from, h, to) in windows(&scan, starts) {
        let mut solver = plain(window_options(options, h)).with_event(
            Event::new(watch_value(dir, watch))
                .direction(Direction::Falling)
                .terminal(),
        );
        let w = solver
            .solve(sys, from.t, from.y, to)
            .map_err(|e| StopOrError::Error(SensitivityError::from(e)))?;
        let StopReason::Event { t, .. } = w.stop else {
            continue;
        };
        let y = &w.x_final;
        match watch {
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
                if least == Some(Ok(LeastAt::Onset)) {
                    out.extend(applied_margin(sys, t, y).map(|m| (6, m)));
                }
            }
            Watch::LeastMargin => out.extend(applied_margin(sys, t, y).map(|m| (6, m))),
        }
    }
    if least == Some(Ok(LeastAt::End)) {
        out.extend(applied_margin(sys, end.0, &end.1).map(|m| (6, m)));
    }
    let last = scan.times.len().saturating_sub(1);
    for (k, p) in [(2, scan.contact), (3, scan.wrist)] {
        if let Some(p) = p
            && (p.step == 0 || p.step == last)
        {
            let (t, y) = if p.step == 0 { start } else { end };
            let f = if k == 2 {
                sys.peak_contact(&y).ok().flatten().map(|(_, f)| f)
            } else {
                sys.wrist_force_gradient(t, &y, d).map(|(f, ..)| f)
            };
            out.extend(f.map(|f| (k, f)));
        }
    }
    out.sort_by_key(|(k, _)| *k);
    Ok(out)
}

/// The applied load's no-jam margin at `(t, y)`.
fn applied_margin(sys: &Insertion, t: f64, y: &SVector<f64, N_STATE>) -> Option<f64> {
    sys.no_jam_margin(t, y, MarginLoad::Applied)
        .ok()
        .flatten()
        .map(|m| m.value)
}
