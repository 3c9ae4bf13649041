//! The metrics of a sensitivity run and their derivatives along the chosen
//! scene fields, with elasticities `q/m ∂m/∂q`, or a flag naming why a
//! derivative does not exist:
//!
//! - `seat_time_s`: the time the target depth is reached, `∂t_e/∂q` of the
//!   seating event;
//! - `final_depth_m`: the depth at the end, `l_y dy(T)/dq + l_q`;
//! - `peak_contact_force_N`: the largest normal force, `F_y s(t*) + F_q` at
//!   its time `t*` (where `dF/dt = 0`, so `t*`'s own change drops out);
//! - `two_point_start_s`, `two_point_end_s`: the contact events where the
//!   peg enters or leaves two-point contact (one edge and the opposite wall
//!   both closed);
//! - `two_point_depth_m`: the depth where two-point contact starts,
//!   `l_y (s + f ∂t_e/∂q) + l_q` at that event (the depth's total change
//!   with the event's time).
//!
//! A derivative is flagged instead of given when a change of the field by
//! [`PERTURBATION`] of its value (predicted to first order) changes the
//! outcome (seated or not), the peak moves to another force maximum, a
//! contact grazes (an event appears or vanishes), or an event is crossed
//! tangentially.

use nalgebra::SVector;

use crate::scene::shared::sensitivities::{self, Measured};

use super::fields::{FIELDS, N_FIELDS};
use super::trajectory::{Derivatives, N_CONTACTS, Scan};
use crate::compliant_peg::directions::CompliantDirections;
use crate::compliant_peg::sensitivity::CONTACTS;
use crate::compliant_peg::system::N_STATE;

pub use crate::scene::shared::sensitivities::{PERTURBATION, Row};

/// The metric names, in output order.
pub const METRICS: [&str; 6] = [
    "seat_time_s",
    "final_depth_m",
    "peak_contact_force_N",
    "two_point_start_s",
    "two_point_end_s",
    "two_point_depth_m",
];

/// The rows of `chosen` fields (indices into [`FIELDS`]), `unused[k]`
/// marking the fields that move nothing.
pub(super) fn rows(
    sys: &CompliantDirections<N_FIELDS>,
    values: &SVector<f64, N_FIELDS>,
    (scan, d): (&Scan, &Derivatives<N_FIELDS>),
    y0: &SVector<f64, N_STATE>,
    (t_end, target): (f64, f64),
    chosen: &[usize],
    unused: &[bool; N_FIELDS],
) -> Vec<Row> {
    let mut metrics: Vec<Measured> = Vec::new();
    // Seat time.
    metrics.push(sensitivities::seat_time(
        d.seated
            .as_ref()
            .map(|e| (e.t, e.dt_dp.as_slice().to_vec())),
        t_end,
        values.as_slice().to_vec(),
        "not seated within t_end".to_owned(),
    ));
    // Final depth.
    let (l_y, l_q) = sys.depth_gradient(&d.y);
    let depth = sys.depth(&d.y);
    let dl = d.dy.transpose() * l_y + l_q;
    metrics.push(sensitivities::final_depth(
        (depth, dl.as_slice().to_vec()),
        d.seated.is_some(),
        target,
        values.as_slice().to_vec(),
    ));
    // Peak contact force.
    if let Some((c, _, f, df)) = d.peak {
        metrics.push(Measured {
            name: METRICS[2],
            value: Some(f),
            derivative: df.as_slice().to_vec(),
            flag: sensitivities::peak_switch_flag(
                String::new(),
                format!("on {} ", CONTACTS[c]),
                (f, scan.runner_up),
                df.as_slice().to_vec(),
                values.as_slice().to_vec(),
            ),
        });
    }
    if d.peak.is_none()
        && let Some((c, _, f)) = scan.peak
    {
        // The plain pass saw the peak; the sensitivity run did not locate
        // it between that pass's steps around it.
        metrics.push(Measured {
            name: METRICS[2],
            value: Some(f),
            derivative: vec![0.0; N_FIELDS],
            flag: Box::new(move |_| {
                Some(format!(
                    "the peak on {} was not located by the sensitivity run",
                    CONTACTS[c]
                ))
            }),
        });
    }
    // Two-point contact: one edge and the opposite wall closed.
    // A contact is closed when it penetrates. One only touching at the
    // start (a two-point start: within rounding, below 1e-9 of the
    // smaller fillet) takes its state at the end of the plain pass's first
    // step; its events before then are rounding at the start.
    let p = sys.parameter_vector();
    let touch = 1e-9 * p[5].min(p[6]);
    let touching: [bool; N_CONTACTS] = std::array::from_fn(|c| sys.delta(c, y0).abs() <= touch);
    let mut closed: [bool; N_CONTACTS] = std::array::from_fn(|c| {
        if touching[c] {
            scan.first_closed[c]
        } else {
            sys.delta(c, y0) > 0.0
        }
    });
    let two_point = |s: &[bool; N_CONTACTS]| (s[0] && s[1]) || (s[2] && s[3]);
    let (mut began, mut ended) = (None, None);
    let mut was = two_point(&closed);
    let first_step = scan.times.get(1).copied().unwrap_or(f64::INFINITY);
    for (c, e) in &d.contacts {
        if touching[*c] && e.t < first_step {
            continue;
        }
        closed[*c] = sys.delta_rate(*c, &e.y) > 0.0;
        let now = two_point(&closed);
        if now && !was && began.is_none() {
            began = Some(e);
        }
        if !now && was && ended.is_none() {
            ended = Some(e);
        }
        was = now;
    }
    let grazing = scan.grazing;
    let grazes = move |_: usize| {
        grazing.map(|(c, tg)| {
            format!(
                "contact {} grazes at t = {tg:.6e} s: an event appears or vanishes within a \
                 small change",
                CONTACTS[c]
            )
        })
    };
    for (name, hit) in [(METRICS[3], began), (METRICS[4], ended)] {
        if let Some(e) = hit {
            metrics.push(Measured {
                name,
                value: Some(e.t),
                derivative: e.dt_dp.as_slice().to_vec(),
                flag: Box::new(grazes),
            });
        }
    }
    if let Some(e) = began {
        let (l_y, l_q) = sys.depth_gradient(&e.y);
        let dl = e.state_at_event().transpose() * l_y + l_q;
        metrics.push(Measured {
            name: METRICS[5],
            value: Some(sys.depth(&e.y)),
            derivative: dl.as_slice().to_vec(),
            flag: Box::new(grazes),
        });
    }
    sensitivities::rows(&metrics, chosen, unused, values.as_slice(), &FIELDS)
}

/// The rows of a run whose sensitivities failed: every metric of the
/// chosen fields flagged with `reason`.
pub(super) fn failed(chosen: &[usize], reason: &str) -> Vec<Row> {
    sensitivities::failed(&METRICS, chosen, &FIELDS, reason)
}
