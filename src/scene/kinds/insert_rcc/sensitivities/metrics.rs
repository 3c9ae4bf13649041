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
//!   and `l_y (s + f ∂t_e/∂q) + l_q`;
//! - `least_no_jam_margin`: the least no-jam margin in two-point contact
//!   in the bore (the load applied to the peg against Whitney's
//!   parallelogram, [`crate::compliant_peg_3d::no_jam`]): inside a stretch
//!   of two-point contact where its rate `m_y f + m_t` rises through zero,
//!   `m_y s + m_q`; at the seating `m_y (s + f ∂t_e/∂q) + m_t ∂t_e/∂q +
//!   m_q`; at the onset of two-point contact (where the peg still slides
//!   on one point and the load sits on the parallelogram's side less the
//!   friction law's slip) the same along the onset's moving time, of the
//!   contacts' resultant (which equals the applied load there less the
//!   peg's inertia, checked to 10⁻⁶).
//!
//! A derivative is flagged instead of given when a change of the field by
//! [`PERTURBATION`] of its value (predicted to first order) changes the
//! outcome (seated or not), the peak moves to another force maximum (the
//! least margin to another minimum, or the nearest edge of the
//! parallelogram to another), two
//! point contact is lost again after it starts (the onset grazes), or the
//! peg's bottom lies on a flat (the distributed ring's derivatives in the
//! parameters are not carried).

use nalgebra::SVector;

use super::trajectory::{Derivatives, LeastMargin, Scan};
use crate::compliant_peg_3d::design::{Design, N_DESIGN};
use crate::compliant_peg_3d::insertion::Insertion;
use crate::scene::shared::compliant_peg_3d::design::FIELDS;
use crate::scene::shared::sensitivities::{self, Measured, PERTURBATION, Row};

/// The metric names, in output order.
pub const METRICS: [&str; 7] = [
    "seat_time_s",
    "final_depth_m",
    "peak_contact_force_N",
    "peak_wrist_force_N",
    "two_point_start_s",
    "two_point_depth_m",
    "least_no_jam_margin",
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
    if let Some(found) = &d.margin {
        metrics.push(least_margin(found, scan, &values));
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

/// The least no-jam margin's metric: its value and derivative, flagged
/// where a 0.1 % change of a field (to first order) moves it to another
/// local minimum or to another edge of the parallelogram, or with the
/// reason it was not located.
fn least_margin<'a>(
    found: &Result<LeastMargin, String>,
    scan: &Scan,
    values: &SVector<f64, N_DESIGN>,
) -> Measured<'a> {
    let at_steps = scan.margin.map(|m| m.value);
    match found {
        Err(reason) => {
            let reason = reason.clone();
            Measured {
                name: METRICS[6],
                value: at_steps,
                derivative: vec![0.0; N_DESIGN],
                flag: Box::new(move |_| Some(reason.clone())),
            }
        }
        Ok(m) => {
            let (value, gap) = (m.value, m.edge_gap);
            let runner_up = scan.margin.map_or(f64::INFINITY, |l| l.runner_up);
            let der = m.derivative;
            let values = *values;
            Measured {
                name: METRICS[6],
                value: Some(value),
                derivative: der.as_slice().to_vec(),
                flag: Box::new(move |k| {
                    let shift = PERTURBATION * values[k].abs() * der[k].abs();
                    if runner_up - value < 2.0 * shift {
                        Some(format!(
                            "the least no-jam margin switches to another minimum within a 0.1% \
                             change (least {value:.6e}; next minimum {runner_up:.6e})"
                        ))
                    } else if gap < 2.0 * shift || gap <= 1e-12 {
                        Some(format!(
                            "the nearest edge of the no-jam parallelogram changes within a 0.1% \
                             change (the next edge {gap:.3e} farther)"
                        ))
                    } else {
                        None
                    }
                }),
            }
        }
    }
}

/// The rows of a run whose sensitivities failed.
pub(super) fn failed(chosen: &[usize], reason: &str) -> Vec<Row> {
    sensitivities::failed(&METRICS, chosen, &FIELDS, reason)
}
