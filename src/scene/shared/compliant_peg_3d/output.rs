//! Outputs of a run of the compliant 3-D peg: the time series CSV (every
//! contact force and point, the wrist's force, moment and deflection,
//! depth, tilt, energy balance), the event list CSV and the figures
//! (forces against time or depth, the contact-state timeline, side and
//! top views of the peg at each event, [`super::views`]).
//!
//! Time-series columns: `t_s, depth_m, tilt_rad, azimuth_rad, px_m, py_m,
//! pz_m, points`, then per pair and slot `k = 1, 2` (the pair's points in
//! order of edge angle; zeros when absent): `<pair>_<k>_N_N` (normal
//! force), `<pair>_<k>_Ft_N` (friction), `<pair>_<k>_x_m, _y_m, _z_m`
//! (point); then `wrist_Fx_N, wrist_Fy_N, wrist_Fz_N` (force on the peg,
//! robot axes), `wrist_Mx_Nm, wrist_My_Nm, wrist_Mz_Nm` (moment about the
//! compliance centre), `wrist_dx_m, wrist_dy_m, wrist_dz_m` (deflection),
//! `kinetic_J, balance_J`.

use nalgebra::SVector;

use crate::compliant_peg_3d::Pair;
use crate::compliant_peg_3d::insertion::{Insertion, N_STATE, Sample, peg_state};
use crate::compliant_peg_3d::outcome::{Transition, counts, label, two_point_counts};
use crate::error::RunError;
use crate::integrate::{EventHit, Solution};
use crate::output::csv::format_f64;
use crate::output::names::Part;
use crate::output::plot::{Panel, Series, Style};
use crate::scene::context::RunContext;
use crate::scene::summary::Metric;

use super::insertion::RunPeaks;

/// Slots per pair in the CSV.
const SLOTS: usize = 2;

fn header() -> Vec<String> {
    let mut h: Vec<String> = [
        "t_s",
        "depth_m",
        "tilt_rad",
        "azimuth_rad",
        "px_m",
        "py_m",
        "pz_m",
        "points",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    for p in Pair::ALL {
        for k in 1..=SLOTS {
            for q in ["N_N", "Ft_N", "x_m", "y_m", "z_m"] {
                h.push(format!("{}_{k}_{q}", p.name()));
            }
        }
    }
    for q in [
        "wrist_Fx_N",
        "wrist_Fy_N",
        "wrist_Fz_N",
        "wrist_Mx_Nm",
        "wrist_My_Nm",
        "wrist_Mz_Nm",
        "wrist_dx_m",
        "wrist_dy_m",
        "wrist_dz_m",
        "kinetic_J",
        "balance_J",
    ] {
        h.push(q.into());
    }
    h
}

fn row(t: f64, y: &SVector<f64, N_STATE>, s: &Sample) -> Vec<f64> {
    let mut r = vec![
        t,
        s.depth,
        s.tilt,
        s.azimuth,
        y[0],
        y[1],
        y[2],
        s.forces.len() as f64,
    ];
    for p in Pair::ALL {
        let mut of: Vec<_> = s.forces.iter().filter(|f| f.contact.pair == p).collect();
        of.sort_by(|a, b| a.contact.angle.total_cmp(&b.contact.angle));
        for k in 0..SLOTS {
            match of.get(k) {
                Some(f) => r.extend([
                    f.normal_force,
                    f.friction.norm(),
                    f.contact.point.x,
                    f.contact.point.y,
                    f.contact.point.z,
                ]),
                None => r.extend([0.0; 5]),
            }
        }
    }
    match &s.wrist {
        Some(w) => {
            r.extend(w.force_robot.iter());
            r.extend(w.moment_robot.iter());
            r.extend(w.deflection.iter());
        }
        None => r.extend([0.0; 9]),
    }
    r.push(s.kinetic);
    r.push(s.balance);
    r
}

/// What the writer found along the run: the peaks of its forces and
/// moments, and the energy balance's drift over the samples.
#[derive(Debug, Default)]
pub struct Peaks {
    /// The largest contact force, pressure and wrist load.
    pub forces: RunPeaks,
    /// Largest `|E − E₀|` (J).
    pub drift: f64,
    /// Largest of `|W|`, `|W_r|`, `T`, for the drift's scale (J).
    pub scale: f64,
}

/// Samples of the run, one per output time.
pub struct Samples {
    /// `(t, y, sample)`.
    pub rows: Vec<(f64, SVector<f64, N_STATE>, Sample)>,
}

/// Evaluates every output state of `sol`.
///
/// # Errors
/// A Hertz setup error at an output state.
pub fn samples(sys: &Insertion, sol: &Solution<N_STATE>) -> Result<Samples, RunError> {
    let mut rows = Vec::with_capacity(sol.t.len());
    for (&t, y) in sol.t.iter().zip(&sol.x) {
        let s = sys.sample(t, y)?;
        rows.push((t, *y, s));
    }
    Ok(Samples { rows })
}

impl Peaks {
    /// Takes the energy balance of output sample `smp` at state `y` into
    /// the drift; `e0` is the balance at the start. (Event states are left
    /// out: at a located contact transition the contact potential is
    /// evaluated exactly where a point appears, which measures the contact
    /// search there, not the integration's drift.)
    fn include_energy(&mut self, y: &SVector<f64, N_STATE>, smp: &Sample, e0: f64) {
        self.drift = self.drift.max((smp.balance - e0).abs());
        self.scale = self
            .scale
            .max(y[13].abs())
            .max(y[15].abs())
            .max(smp.kinetic);
    }
}

/// Writes `<name>.csv` (the samples, which end with the run's final state)
/// and returns the peak forces and moments over the samples, the states
/// of `events` (the located events of the run, contact transitions and the
/// terminal one) and `steps` (the peaks over the ends of the run's accepted
/// steps), so that a peak is never missed because it fell between two
/// samples; the energy drift over the samples.
///
/// # Errors
/// Output errors; a Hertz setup error at an event state.
pub fn write_series(
    ctx: &RunContext,
    sys: &Insertion,
    s: &Samples,
    events: &[EventHit<N_STATE>],
    steps: &RunPeaks,
) -> Result<Peaks, RunError> {
    let h = header();
    let hr: Vec<&str> = h.iter().map(String::as_str).collect();
    let mut csv = ctx.table(Part::Main, &hr)?;
    let mut peaks = Peaks {
        forces: *steps,
        ..Peaks::default()
    };
    let e0 = s.rows.first().map_or(0.0, |r| r.2.balance);
    for (t, y, smp) in &s.rows {
        csv.row(&row(*t, y, smp))?;
        peaks.forces.include_sample(sys, y, smp);
        peaks.include_energy(y, smp, e0);
    }
    csv.finish()?;
    for e in events {
        peaks
            .forces
            .include_sample(sys, &e.x, &sys.sample(e.t, &e.x)?);
    }
    Ok(peaks)
}

/// One located contact transition.
#[derive(Clone, Debug)]
pub struct EventRow {
    /// Time (s).
    pub t: f64,
    /// State there.
    pub y: SVector<f64, N_STATE>,
    /// What changed, e.g. `edge_side 2 -> 1`.
    pub what: String,
    /// The contact state after it.
    pub state: String,
    /// Whether the state after it is two-point contact (mouth edge on the
    /// side and rim on the wall,
    /// [`two_point`](crate::compliant_peg_3d::outcome::two_point)).
    pub two_point: bool,
}

/// The contact transitions of `sol` (events with index below
/// `what.len()`), described. The contact state after each is the start
/// state's point counts updated by every transition so far, so the list
/// reads consistently from the first event to the last.
pub fn transitions(sys: &Insertion, sol: &Solution<N_STATE>, what: &[Transition]) -> Vec<EventRow> {
    let mut cur = sol
        .x
        .first()
        .map_or([0; Pair::ALL.len()], |y| counts(&sys.contacts(y)));
    sol.events
        .iter()
        .filter(|e| e.index < what.len())
        .map(|e| {
            let (pair, k) = what[e.index];
            let (from, to) = if e.rising { (k - 1, k) } else { (k, k - 1) };
            cur[pair] = to;
            EventRow {
                t: e.t,
                y: e.x,
                what: format!("{} {from} -> {to}", Pair::ALL[pair].name()),
                state: label(&cur),
                two_point: two_point_counts(&cur),
            }
        })
        .collect()
}

/// Writes `<name>.events.csv` (`t_s, transition, contact_state, depth_m,
/// tilt_rad`).
///
/// # Errors
/// Output errors.
pub fn write_events(
    ctx: &RunContext,
    sys: &Insertion,
    events: &[EventRow],
) -> Result<(), RunError> {
    let mut csv = ctx.table(
        Part::Sub("events"),
        &["t_s", "transition", "contact_state", "depth_m", "tilt_rad"],
    )?;
    for e in events {
        let (d, g, _) =
            crate::compliant_peg_3d::insertion::depth_tilt(&sys.peg.params, &peg_state(&e.y));
        csv.row_cells(&[
            &format_f64(e.t),
            &e.what,
            &e.state,
            &format_f64(d),
            &format_f64(g),
        ])?;
    }
    Ok(csv.finish()?)
}

/// The contact-state timeline: each pair's point count against time.
pub fn timeline(s: &Samples) -> Panel {
    let mut p = Panel::new("Contact state", "t [s]", "points per pair");
    for (i, pair) in Pair::ALL.iter().enumerate() {
        let pts: Vec<(f64, f64)> = s
            .rows
            .iter()
            .map(|(t, _, smp)| {
                (
                    *t,
                    smp.forces
                        .iter()
                        .filter(|f| f.contact.pair == *pair)
                        .count() as f64
                        + 0.05 * i as f64,
                )
            })
            .collect();
        if pts.iter().any(|p| p.1 >= 1.0) || i == 0 {
            p = p.with(Series::line(pair.name(), pts).colored(i));
        }
    }
    p
}

/// Contact normal forces against time, pair by pair and slot.
pub fn forces_panel(s: &Samples) -> Panel {
    let mut p = Panel::new("Contact normal forces", "t [s]", "Q [N]");
    for (i, pair) in Pair::ALL.iter().enumerate() {
        for k in 0..SLOTS {
            let pts: Vec<(f64, f64)> = s
                .rows
                .iter()
                .map(|(t, _, smp)| {
                    let mut of: Vec<_> = smp
                        .forces
                        .iter()
                        .filter(|f| f.contact.pair == *pair)
                        .collect();
                    of.sort_by(|a, b| a.contact.angle.total_cmp(&b.contact.angle));
                    (*t, of.get(k).map_or(0.0, |f| f.normal_force))
                })
                .collect();
            if pts.iter().any(|p| p.1 > 0.0) {
                let st = if k == 0 { Style::Solid } else { Style::Dashed };
                p = p.with(
                    Series::line(format!("{} {}", pair.name(), k + 1), pts)
                        .styled(st)
                        .colored(i),
                );
            }
        }
    }
    if p.series.is_empty() {
        p = p.with(Series::line(
            "no contact",
            s.rows.iter().map(|(t, ..)| (*t, 0.0)).collect(),
        ));
    }
    p
}

/// The run's common metrics, with a warning after the energy balance's
/// drift when it exceeds [`crate::scene::ENERGY_DRIFT_WARNING`].
pub fn metrics(peaks: &Peaks) -> Vec<Metric> {
    let drift = peaks.drift / peaks.scale.max(1e-300);
    let mut m = vec![
        Metric::new("peak contact normal force", peaks.forces.contact, "N"),
        Metric::new("peak wrist force", peaks.forces.wrist_force, "N"),
        Metric::new(
            "peak wrist lateral moment",
            peaks.forces.wrist_moment,
            "N m",
        ),
        Metric::new("max |E - E0| / max(|W|, |W_r|, T)", drift, ""),
    ];
    m.extend(crate::scene::energy_drift_warning(drift));
    m
}
