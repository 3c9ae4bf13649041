//! Why a forward simulation of the rigid peg stopped: planned ends and
//! contact-state events are values ([`ForwardStop`]), with the time and the
//! state (γ, ψ, γ̇, ψ̇) where they happened.

use std::fmt;

use nalgebra::Vector4;

use crate::integrate::StopReason;
use crate::rigid_peg::modes::Mode;

/// Which kind of rigid-model breakdown a [`ForwardStop::Painleve`] reports.
#[derive(Clone, Debug, PartialEq)]
pub enum PainleveCase {
    /// No contact mode is consistent (the three-point mode needs a pulling
    /// contact and no mode with fewer contacts works either).
    Inconsistent,
    /// Several contact modes are consistent (non-uniqueness).
    Indeterminate(Vec<Mode>),
    /// The forward system's determinant changed sign: accelerations and
    /// reactions pass through infinity.
    Singular,
    /// A reaction grew past `forward_events::N_JAM`·m g: the determinant is
    /// tending to zero (approach to a Painlevé singularity, dynamic jam).
    Unbounded,
}

/// How a forward simulation ended.
#[derive(Clone, Debug, PartialEq)]
pub enum ForwardStop {
    /// The end time was reached.
    ReachedEnd {
        /// End time (s).
        t: f64,
    },
    /// The peg came to rest and static friction holds it.
    Stuck {
        /// Time the sliding speed fell to v_stop (s).
        t: f64,
        /// γ at rest (rad).
        gamma: f64,
        /// ψ at rest (rad).
        psi: f64,
    },
    /// γ fell to γ0 = arccos(d/D): B1 and B2 merge, three-point contact ends.
    TwoPointContact {
        /// Located time (s).
        t: f64,
        /// State there.
        state: Vector4<f64>,
    },
    /// A normal reaction fell through zero: that contact lifts off.
    LiftOff {
        /// Contact name: `"K"`, `"B1"` or `"B2"`.
        contact: &'static str,
        /// Located time (s).
        t: f64,
        /// State there.
        state: Vector4<f64>,
    },
    /// The rigid model has no (unique) answer.
    Painleve {
        /// Time (s).
        t: f64,
        /// State there.
        state: Vector4<f64>,
        /// What breaks down.
        case: PainleveCase,
    },
    /// The integrator stopped unplanned (step size underflow, non-finite
    /// values, step budget).
    Integrator(StopReason),
    /// More stop/restart cycles than the budget.
    RestartLimit {
        /// Time (s).
        t: f64,
        /// Restarts made.
        restarts: usize,
    },
}

impl ForwardStop {
    /// The time (s) of the stop and, for a located event, the state there;
    /// `None` for an integrator stop and for the restart budget (which
    /// ends the run without a point of the motion to compare).
    pub fn point(&self) -> Option<(f64, Option<Vector4<f64>>)> {
        match self {
            ForwardStop::TwoPointContact { t, state }
            | ForwardStop::LiftOff { t, state, .. }
            | ForwardStop::Painleve { t, state, .. } => Some((*t, Some(*state))),
            ForwardStop::ReachedEnd { t } | ForwardStop::Stuck { t, .. } => Some((*t, None)),
            ForwardStop::Integrator(_) | ForwardStop::RestartLimit { .. } => None,
        }
    }

    /// Short name of the event, e.g. `lift_off_B1`.
    pub fn name(&self) -> String {
        match self {
            ForwardStop::ReachedEnd { .. } => "reached_end".into(),
            ForwardStop::Stuck { .. } => "stuck".into(),
            ForwardStop::TwoPointContact { .. } => "gamma0".into(),
            ForwardStop::LiftOff { contact, .. } => format!("lift_off_{contact}"),
            ForwardStop::Painleve { .. } => "painleve".into(),
            ForwardStop::Integrator(_) => "integrator".into(),
            ForwardStop::RestartLimit { .. } => "restart_limit".into(),
        }
    }

    /// Planned end or a contact event (not an integrator failure).
    pub fn is_success(&self) -> bool {
        !matches!(
            self,
            ForwardStop::Integrator(_) | ForwardStop::RestartLimit { .. }
        )
    }
}

fn state(x: &Vector4<f64>) -> String {
    format!(
        "gamma = {:.9} rad, psi = {:.6} rad, gammadot = {:.6e} 1/s, psidot = {:.6e} 1/s",
        x[0], x[1], x[2], x[3]
    )
}

impl fmt::Display for ForwardStop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ForwardStop::ReachedEnd { t } => write!(f, "reached t_end = {t} s"),
            ForwardStop::Stuck { t, gamma, psi } => write!(
                f,
                "stuck (static friction holds) at t = {t} s, gamma = {gamma:.9} rad, psi = {psi:.6} rad"
            ),
            ForwardStop::TwoPointContact { t, state: x } => write!(
                f,
                "gamma reached gamma0 (B1, B2 merge: three-point contact ends) at t = {t} s, {}",
                state(x)
            ),
            ForwardStop::LiftOff {
                contact,
                t,
                state: x,
            } => {
                write!(
                    f,
                    "N_{contact} fell to 0 (lift-off of {contact}) at t = {t} s, {}",
                    state(x)
                )
            }
            ForwardStop::Painleve { t, state: x, case } => {
                let what = match case {
                    PainleveCase::Inconsistent => "no consistent contact mode".to_string(),
                    PainleveCase::Indeterminate(m) => {
                        format!("{} consistent contact modes", m.len())
                    }
                    PainleveCase::Singular => "singular contact system".to_string(),
                    PainleveCase::Unbounded => {
                        "reactions unbounded (approaching a singular contact system: dynamic jam)"
                            .to_string()
                    }
                };
                write!(f, "Painleve: {what} at t = {t} s, {}", state(x))
            }
            ForwardStop::Integrator(r) => write!(f, "integrator stopped: {r:?}"),
            ForwardStop::RestartLimit { t, restarts } => {
                write!(f, "{restarts} stop/restart cycles by t = {t} s")
            }
        }
    }
}
