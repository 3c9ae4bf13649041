//! The metrics of an `insert_rcc` sensitivity run and their derivatives
//! along the chosen fields, or a flag naming why a derivative does not
//! exist:
//!
//! - `seat_time_s`: the time the seat depth is reached, `∂t_e/∂q`;
//! - `final_depth_m`: the tip's depth at the end, `l_y dy(T)/dq + l_q`;
//! - `peak_contact_force_N`, `peak_wrist_force_N`: the largest contact
//!   normal force and the largest wrist force, `F_y s(t*) + F_q` at the
//!   peak's time `t*` (where `dF/dt = 0`: `t*`'s own change drops out;
//!   a peak at the seating adds `(F_y f + F_t) ∂t_e/∂q`);
//! - `two_point_start_s`, `two_point_depth_m`: the time and the tip's
//!   depth at which two-point contact (the mouth edge on the peg's side
//!   and the rim on the wall) starts, `∂t_e/∂q` of the closing pair's gap
//!   and `l_y (s + f ∂t_e/∂q) + l_q`.
//!
//! A derivative is flagged instead of given when a change of the field by
//! [`PERTURBATION`](crate::scene::shared::sensitivities::PERTURBATION) of its value (predicted to first order) changes the
//! outcome (seated or not), the peak moves to another force maximum, two
//! point contact is lost again after it starts (the onset grazes), or the
//! peg's bottom lies on a flat (the distributed ring's derivatives in the
//! parameters are not carried).

use nalgebra::SVector;

use super::trajectory::{Derivatives, Scan};
use crate::compliant_peg_3d::design::{Design, N_DESIGN};
use crate::compliant_peg_3d::insertion::Insertion;
use crate::scene::shared::compliant_peg_3d::design::FIELDS;
use crate::scene::shared::sensitivities::{self, Measured, Row};

/// The metric names, in output order.
pub const METRICS: [&str; 6] = [
    "seat_time_s",
    "final_depth_m",
    "peak_contact_force_N",
    "peak_wrist_force_N",
    "two_point_start_s",
    "two_point_depth_m",
];

/// What the rows are made of: the system and its design quantities, the
/// fields' values, what the run found at its steps and the derivatives.
pub(super) struct Inputs<'a> {
    /// The system.
    pub sys: &'a Insertion,
    /// Its quantities in dual numbers of the fields.
    pub design: &'a Design,
    /// The fields' values.
    pub values: &'a SVector<f64, N_DESIGN>,
    /// What the run found at its steps.
    pub scan: &'a Scan,
    /// The sensitivity run's derivatives.
    pub d: &'a Derivatives,
    /// `t_end` (s) and the seat depth (m).
    pub ends: (f64, f64),
}

/// The rows of the fields `names` (slot by slot), `unused[j]` marking the
/// slots whose field moves nothing.
pub(super) fn rows(x: &Inputs, names: &[&'static str], unused: &[bool; N_DESIGN]) -> Vec<Row> {
    let (t_end, seat) = x.ends;
    let values = *x.values;
    let (scan, d) = (x.scan, x.d);
    let mut metrics: Vec<Measured> = Vec::new();
    let zero = vec![0.0; N_DESIGN];
    let stop = format!("{:?}", scan.stop);
    let at_seat = d
        .seated
        .as_ref()
        .map(|e| (e.t, e.dt_dp.as_slice().to_vec()));
    let unseated = format!("not seated (the run ended: {stop})");
    metrics.push(sensitivities::seat_time(
        at_seat,
        t_end,
        values.as_slice().to_vec(),
        unseated,
    ));
    let (depth, l_y, l_q) = x.sys.depth_gradient(&d.y, x.design);
    let dl = d.dy.transpose() * l_y + l_q;
    metrics.push(sensitivities::final_depth(
        (depth, dl.as_slice().to_vec()),
        d.seated.is_some(),
        seat,
        values.as_slice().to_vec(),
    ));
    for (name, what, found, peak) in [
        (METRICS[2], "contact force", d.contact, scan.contact),
        (METRICS[3], "wrist force", d.wrist, scan.wrist),
    ] {
        match (found, peak) {
            (Some((_, f, der)), _) => metrics.push(Measured {
                name,
                value: Some(f),
                derivative: der.as_slice().to_vec(),
                flag: match peak {
                    Some(p) => sensitivities::peak_switch_flag(
                        format!(" {what}"),
                        String::new(),
                        (p.value, p.runner_up),
                        der.as_slice().to_vec(),
                        values.as_slice().to_vec(),
                    ),
                    None => Box::new(|_| None),
                },
            }),
            (None, Some(p)) => metrics.push(Measured {
                name,
                value: Some(p.value),
                derivative: zero.clone(),
                flag: Box::new(move |_| {
                    Some(format!(
                        "the peak {what} was not located by the sensitivity run"
                    ))
                }),
            }),
            (None, None) => {}
        }
    }
    if let Some(e) = &d.two_point {
        let lost = scan.two_point_lost;
        let grazes = move |_: usize| {
            lost.map(|t| {
                format!(
                    "two-point contact is lost again at t = {t:.6e} s: its onset grazes, an \
                     event appears or vanishes within a small change"
                )
            })
        };
        let (depth, l_y, l_q) = x.sys.depth_gradient(&e.y, x.design);
        let dd = e.state_at_event().transpose() * l_y + l_q;
        metrics.push(Measured {
            name: METRICS[4],
            value: Some(e.t),
            derivative: e.dt_dp.as_slice().to_vec(),
            flag: Box::new(grazes),
        });
        metrics.push(Measured {
            name: METRICS[5],
            value: Some(depth),
            derivative: dd.as_slice().to_vec(),
            flag: Box::new(grazes),
        });
    } else if scan.two_point.is_some() {
        for name in [METRICS[4], METRICS[5]] {
            metrics.push(Measured {
                name,
                value: None,
                derivative: zero.clone(),
                flag: Box::new(|_| {
                    Some("the onset of two-point contact was not located".to_owned())
                }),
            });
        }
    }
    if let Some(t) = scan.ring {
        for m in &mut metrics {
            m.flag = Box::new(move |_| {
                Some(format!(
                    "the peg's bottom lies on a flat at t = {t:.6e} s: the distributed ring's \
                     derivatives in the parameters are not carried"
                ))
            });
        }
    }
    let slots: Vec<usize> = (0..names.len()).collect();
    sensitivities::rows(&metrics, &slots, unused, values.as_slice(), names)
}

/// The rows of a run whose sensitivities failed.
pub(super) fn failed(chosen: &[usize], reason: &str) -> Vec<Row> {
    sensitivities::failed(&METRICS, chosen, &FIELDS, reason)
}
