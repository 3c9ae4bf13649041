//! What the `[sensitivities]` tables of the scene kinds share
//! (`insert_compliant`, `insert_rcc`; `docs/sensitivities.md`): a run's
//! metrics with their derivatives along every field and the flags that
//! withhold a derivative ([`Measured`]), turned into one row per metric
//! and chosen field ([`rows`]), and the files and ranking of those rows
//! ([`output`]).

pub mod output;

use serde::Deserialize;

use crate::error::{RunError, SceneError};
use crate::integrate::{Options, StopReason};
use crate::sensitivity::SensitivityError;

/// The `[sensitivities]` table: the scene fields to differentiate by.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SensitivitiesTable {
    /// The scene fields, by their names (each kind lists its own).
    pub parameters: Vec<String>,
    /// What the sensitivity run's step control measures
    /// (`error_control = "state"`, the default, or `"all"`).
    #[serde(default)]
    pub error_control: ErrorControl,
}

/// What the step control of a sensitivity run measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ErrorControl {
    /// The state only: the run takes the plain run's steps, and the
    /// sensitivities are the exact derivatives of the computed solution
    /// along them (internal differentiation, Bock). They converge with
    /// the tolerances as the state does, and a contact whose force has a
    /// derivative that is unbounded but integrable (two points of one
    /// pair meeting, where a point moves like the square root of the pose)
    /// does not stop the run.
    #[default]
    State,
    /// The state and the sensitivities (each column scaled by its field's
    /// value): the sensitivities' own error is controlled, at the cost of
    /// more steps, and a run stops (flagged) where their derivative is
    /// unbounded.
    All,
}

impl ErrorControl {
    /// The error control of a scene's `[sensitivities]` table, the
    /// default without one.
    #[must_use]
    pub fn of(table: Option<&SensitivitiesTable>) -> Self {
        table.map_or_else(Self::default, |t| t.error_control)
    }

    /// The options of a sensitivity run of `m` components (`n` states,
    /// `p` of the columns moving) from the plain run's `options`: for
    /// [`ErrorControl::State`] the norm over the `n` states; for
    /// [`ErrorControl::All`] over all `m`, the tolerances scaled by
    /// `√(n (1 + p)/m)` so that the padded columns, which stay zero, do
    /// not loosen them.
    #[must_use]
    pub fn options(self, options: &Options, n: usize, p: usize, m: usize) -> Options {
        match self {
            ErrorControl::State => Options {
                error_components: Some(n),
                ..options.clone()
            },
            ErrorControl::All => {
                #[allow(clippy::cast_precision_loss)] // component counts are small
                let shrink = ((n * (1 + p)) as f64 / m as f64).sqrt();
                Options {
                    rtol: options.rtol * shrink,
                    atol: options.atol * shrink,
                    fallback_components: Some(n),
                    ..options.clone()
                }
            }
        }
    }
}

/// The field of a scene that names the parameters.
pub const PARAMETERS_FIELD: &str = "sensitivities.parameters";

/// The indices into `fields` (a kind's field names) of the `parameters` a
/// `[sensitivities]` table names, in the order named, and the errors
/// naming [`PARAMETERS_FIELD`]: an empty list or an unknown name (each
/// with the valid names), a name given twice.
pub fn choose(parameters: &[String], fields: &[&str]) -> (Vec<usize>, Vec<SceneError>) {
    let mut errors = Vec::new();
    let mut chosen = Vec::new();
    let valid = fields.join(", ");
    if parameters.is_empty() {
        errors.push(SceneError::invalid(
            PARAMETERS_FIELD,
            parameters,
            format!("name at least one field; the fields are: {valid}"),
        ));
    }
    for name in parameters {
        match fields.iter().position(|f| f == name) {
            None => errors.push(SceneError::invalid(
                PARAMETERS_FIELD,
                name,
                format!("unknown field; the fields are: {valid}"),
            )),
            Some(k) if chosen.contains(&k) => {
                errors.push(SceneError::invalid(PARAMETERS_FIELD, name, "named twice"));
            }
            Some(k) => chosen.push(k),
        }
    }
    (chosen, errors)
}

/// The relative change of a field within which a derivative must hold for
/// it to be reported.
pub const PERTURBATION: f64 = 1e-3;

/// One metric's derivative along one field.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The metric, with its unit (`seat_time_s`).
    pub metric: &'static str,
    /// The field (its name in the scene).
    pub parameter: &'static str,
    /// The metric's value (None when the run has none, e.g. not seated).
    pub value: Option<f64>,
    /// `∂m/∂q` (None when flagged).
    pub derivative: Option<f64>,
    /// `q/m ∂m/∂q` (None when flagged or `m = 0`).
    pub elasticity: Option<f64>,
    /// Why there is no derivative, or that the field is not used; empty
    /// otherwise.
    pub flag: String,
}

/// A metric of a run: value, derivatives along every field (indexed like
/// the kind's field list), and a flag for every field (`None` where the
/// derivative holds).
pub struct Measured<'a> {
    /// The metric, with its unit.
    pub name: &'static str,
    /// Its value (None when the run has none).
    pub value: Option<f64>,
    /// `∂m/∂q` along every field.
    pub derivative: Vec<f64>,
    /// Why the derivative along field `k` is withheld, if it is.
    pub flag: Box<dyn Fn(usize) -> Option<String> + 'a>,
}

/// The rows of `metrics` for the `chosen` fields (indices into `fields`,
/// the kind's field names, with their `values`), `unused[k]` marking the
/// fields that move nothing the run depends on (a zero derivative,
/// flagged as not used). A flagged derivative is withheld; a derivative
/// that is not finite is flagged, never written as a number.
pub fn rows(
    metrics: &[Measured],
    chosen: &[usize],
    unused: &[bool],
    values: &[f64],
    fields: &[&'static str],
) -> Vec<Row> {
    let mut out = Vec::new();
    for m in metrics {
        for &k in chosen {
            let flag = if unused[k] {
                Some("not used by this model".to_owned())
            } else {
                (m.flag)(k)
            };
            let (derivative, elasticity) = match (&flag, unused[k]) {
                (_, true) => (Some(0.0), Some(0.0)),
                (Some(_), false) => (None, None),
                (None, false) => {
                    // `+ 0.0`: a zero derivative is written `0` whatever
                    // its sign (a −0 would read as a decrease).
                    let der = m.derivative[k] + 0.0;
                    let el = m
                        .value
                        .filter(|v| *v != 0.0)
                        .map(|v| values[k] / v * der + 0.0);
                    (Some(der), el)
                }
            };
            // A derivative that overflowed (a degenerate contact geometry,
            // say) is flagged, never written as a number.
            let (flag, derivative, elasticity) = match derivative {
                Some(v) if !v.is_finite() || elasticity.is_some_and(|e| !e.is_finite()) => (
                    Some("the derivative is not finite at this point".to_owned()),
                    None,
                    None,
                ),
                _ => (flag, derivative, elasticity),
            };
            out.push(Row {
                metric: m.name,
                parameter: fields[k],
                value: m.value,
                derivative,
                elasticity,
                flag: flag.unwrap_or_default(),
            });
        }
    }
    out
}

/// The flag of a peak whose next local maximum is within the first-order
/// change of a 0.1 % ([`PERTURBATION`]) change of a field: the peak may
/// switch to that maximum, where its derivative does not hold. `value` and
/// `runner_up` in N, `derivative` and `values` per field; `subject` names
/// the peak in the message (`" contact force"`, or empty) and `place`
/// where it is (`"on the tip "`, or empty).
pub fn peak_switch_flag(
    subject: String,
    place: String,
    (value, runner_up): (f64, f64),
    derivative: Vec<f64>,
    values: Vec<f64>,
) -> Box<dyn Fn(usize) -> Option<String>> {
    Box::new(move |k| {
        let shift = PERTURBATION * values[k].abs() * derivative[k].abs();
        let gap = value - runner_up;
        (gap < 2.0 * shift || gap <= 1e-9 * value).then(|| {
            format!(
                "the peak{subject} switches to another force maximum within a 0.1% change \
                 (peak {place}{value:.6e} N; next maximum {runner_up:.6e} N)"
            )
        })
    })
}

/// The rows of a run whose sensitivities failed: every metric of
/// `metrics` along the chosen fields flagged with `reason`.
pub fn failed(
    metrics: &[&'static str],
    chosen: &[usize],
    fields: &[&'static str],
    reason: &str,
) -> Vec<Row> {
    metrics
        .iter()
        .flat_map(|m| {
            chosen.iter().map(move |&k| Row {
                metric: m,
                parameter: fields[k],
                value: None,
                derivative: None,
                elasticity: None,
                flag: reason.to_owned(),
            })
        })
        .collect()
}

/// Why a sensitivity run ended without derivatives.
#[derive(Debug)]
pub enum StopOrError {
    /// The integrator stopped short (step size, budget, non-finite state).
    Stopped(StopReason),
    /// The sensitivity integrator refused (a tangential event, bad input).
    Error(SensitivityError),
}

impl From<SensitivityError> for StopOrError {
    fn from(e: SensitivityError) -> Self {
        StopOrError::Error(e)
    }
}

impl StopOrError {
    /// The flag of every row of a run that ended so (a tangential event,
    /// a stop short of the end), or the error that ends the scene's run
    /// (the integrator's refusal of its input).
    ///
    /// # Errors
    /// [`RunError::Sensitivity`] for a refusal other than a tangential
    /// event.
    pub fn flag(self) -> Result<String, RunError> {
        match self {
            StopOrError::Error(SensitivityError::TangentialEvent { t, .. }) => {
                Ok(format!("an event is crossed tangentially at t = {t:.6e} s"))
            }
            StopOrError::Error(e) => Err(e.into()),
            StopOrError::Stopped(stop) => {
                Ok(format!("the sensitivity run stopped short: {stop:?}"))
            }
        }
    }
}

/// The seat time `seat_time_s`: the seating event's time `t` and
/// `∂t_e/∂q` (`derivative`, one per field), flagged where a change of the
/// field by [`PERTURBATION`] of its `values` (to first order) moves it past
/// `t_end`; without a seating, every field flagged with `unseated`.
pub fn seat_time<'a>(
    seated: Option<(f64, Vec<f64>)>,
    t_end: f64,
    values: Vec<f64>,
    unseated: String,
) -> Measured<'a> {
    match seated {
        Some((t, dt)) => Measured {
            name: "seat_time_s",
            value: Some(t),
            derivative: dt.clone(),
            flag: Box::new(move |k| {
                (t_end - t < PERTURBATION * values[k].abs() * dt[k].abs()).then(|| {
                    "seated near t_end: a 0.1% change of the field leaves the peg unseated"
                        .to_owned()
                })
            }),
        },
        None => Measured {
            name: "seat_time_s",
            value: None,
            derivative: vec![0.0; values.len()],
            flag: Box::new(move |_| Some(unseated.clone())),
        },
    }
}

/// The final depth `final_depth_m`: its value and derivative along every
/// field, flagged where the run ended unseated and a change of the field
/// by [`PERTURBATION`] of its `values` (to first order) reaches `target`.
pub fn final_depth<'a>(
    (depth, derivative): (f64, Vec<f64>),
    seated: bool,
    target: f64,
    values: Vec<f64>,
) -> Measured<'a> {
    Measured {
        name: "final_depth_m",
        value: Some(depth),
        derivative: derivative.clone(),
        flag: Box::new(move |k| {
            (!seated && target - depth < PERTURBATION * values[k].abs() * derivative[k].abs()).then(
                || {
                    "ends near the target depth: a 0.1% change of the field seats the peg"
                        .to_owned()
                },
            )
        }),
    }
}

/// The options of one leg of a sensitivity run whose legs share
/// `options.max_steps`, `attempts` of them taken when the leg starts at
/// `t`.
///
/// # Errors
/// [`StopOrError::Stopped`] when the budget is spent.
pub fn leg(options: &Options, attempts: usize, t: f64) -> Result<Options, StopOrError> {
    let Some(left) = options.max_steps.checked_sub(attempts).filter(|n| *n > 0) else {
        return Err(StopOrError::Stopped(StopReason::MaxSteps {
            t,
            steps: attempts,
        }));
    };
    Ok(Options {
        max_steps: left,
        ..options.clone()
    })
}
