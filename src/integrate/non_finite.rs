//! Where an integration turned non-finite: the first state component whose
//! rate or value is NaN or infinite, probed at the last finite state, and
//! the likely cause read from the magnitudes around it.

use nalgebra::SVector;

use crate::system::OdeSystem;

/// Which quantity of a component was found non-finite.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NonFiniteQuantity {
    /// The right-hand side `ẋᵢ = fᵢ(t, x)` at a finite state.
    Rate,
    /// The state `xᵢ` after a step from the last finite state.
    State,
}

/// The first non-finite component found when an integration stopped with
/// [`super::StopReason::NonFinite`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonFiniteAt {
    /// Time of the last finite state, s (the stop's `t`).
    pub t: f64,
    /// Index of the state component.
    pub index: usize,
    /// Its name ([`crate::system::OdeSystem::state_names`]), if the
    /// system names its state.
    pub name: Option<&'static str>,
    /// Rate or state.
    pub quantity: NonFiniteQuantity,
    /// The non-finite value (NaN or ±inf).
    pub value: f64,
    /// The component's last finite value `xᵢ(t)`.
    pub last_finite: f64,
    /// The largest finite `|xⱼ|` or `|fⱼ|` seen at the last finite state:
    /// near `f64::MAX` it points at overflow.
    pub largest: f64,
}

/// Magnitude above which a finite value is taken as "about to overflow".
pub const OVERFLOW_NEAR: f64 = 1e150;

impl NonFiniteAt {
    /// `` `name` `` or `component #i` when the system has no names.
    pub fn component(&self) -> String {
        match self.name {
            Some(n) => format!("`{n}`"),
            None => format!("component #{}", self.index),
        }
    }

    /// One phrase naming the likely cause, from the quantity and the
    /// magnitudes at the last finite state.
    pub fn likely_cause(&self) -> &'static str {
        match (
            self.quantity,
            self.largest >= OVERFLOW_NEAR,
            self.value.is_nan(),
        ) {
            (_, true, _) => {
                "overflow: the state or its rates grew beyond 1e150 before they turned \
                 non-finite (rates, loads, masses or lengths over many decades, or a motion \
                 that runs away)"
            }
            (NonFiniteQuantity::Rate, false, true) => {
                "the equations are undefined at this state (a division 0/0 or a singular mass \
                 matrix: a vanishing mass, length or modulus, or a configuration outside the \
                 model's domain)"
            }
            (NonFiniteQuantity::Rate, false, false) => {
                "a division by zero in the equations at this state (a vanishing mass, length, \
                 modulus or force scale, or a singular configuration)"
            }
            (NonFiniteQuantity::State, false, _) => {
                "the step left the model's domain: the rates are finite but the state after a \
                 step is not (a very stiff or very fast motion for the tolerances)"
            }
        }
    }
}

fn first_non_finite<const N: usize>(v: &SVector<f64, N>) -> Option<(usize, f64)> {
    v.iter().copied().enumerate().find(|(_, c)| !c.is_finite())
}

fn largest_finite<const N: usize>(vs: &[&SVector<f64, N>]) -> f64 {
    vs.iter()
        .flat_map(|v| v.iter())
        .filter(|c| c.is_finite())
        .fold(0.0f64, |m, c| m.max(c.abs()))
}

/// Probes the system at the last finite state `(t, x)`: the rate there,
/// then an explicit Euler step to each end time in `ends` (of the failed
/// steps, largest first) and the rate there, then the rate at
/// `t + √ε·max(|t|, 1)` (where a finite-difference time derivative looks).
/// Returns the first non-finite component met, or `None` when every probe
/// stays finite (the non-finite value arose inside a method's stages
/// only). Costs at most 10 calls of `rhs` (the first 8 ends are probed).
pub(crate) fn probe<const N: usize, S: OdeSystem<N>>(
    system: &S,
    t: f64,
    x: &SVector<f64, N>,
    ends: &[f64],
) -> Option<NonFiniteAt> {
    let f = system.rhs(t, x);
    let at = |index: usize, quantity, value, largest| NonFiniteAt {
        t,
        index,
        name: system.state_names().get(index).copied(),
        quantity,
        value,
        last_finite: x[index],
        largest,
    };
    if let Some((i, v)) = first_non_finite(&f) {
        return Some(at(i, NonFiniteQuantity::Rate, v, largest_finite(&[x, &f])));
    }
    let largest = largest_finite(&[x, &f]);
    for &t1 in ends.iter().filter(|t1| t1.is_finite() && **t1 > t).take(8) {
        let x1 = x + f * (t1 - t);
        if let Some((i, v)) = first_non_finite(&x1) {
            return Some(at(i, NonFiniteQuantity::State, v, largest));
        }
        let f1 = system.rhs(t1, &x1);
        if let Some((i, v)) = first_non_finite(&f1) {
            return Some(at(i, NonFiniteQuantity::Rate, v, largest));
        }
    }
    let f1 = system.rhs(t + f64::EPSILON.sqrt() * t.abs().max(1.0), x);
    first_non_finite(&f1).map(|(i, v)| at(i, NonFiniteQuantity::Rate, v, largest))
}
