//! Typed refusal of bad input to the jamming analysis.

use thiserror::Error;

/// A parameter of the jamming/wedging analysis was refused.
///
/// `field` names the input exactly as the scene file and the API spell it
/// (`r`, `c`, `mu`, `l`, ...), `value` is what was given, `reason` says what
/// was expected.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{field} = {value}: {reason}")]
pub struct ParamError {
    /// Name of the refused input (`r`, `c`, `mu`, `l`, `F`, `beta`, ...).
    pub field: &'static str,
    /// The value that was given.
    pub value: f64,
    /// What the value must satisfy.
    pub reason: &'static str,
}

/// Refuse `value` for `field` unless it is finite and `ok(value)` holds.
pub(crate) fn check(
    field: &'static str,
    value: f64,
    ok: impl Fn(f64) -> bool,
    reason: &'static str,
) -> Result<f64, ParamError> {
    if !value.is_finite() {
        return Err(ParamError {
            field,
            value,
            reason: "must be a finite number",
        });
    }
    if ok(value) {
        Ok(value)
    } else {
        Err(ParamError {
            field,
            value,
            reason,
        })
    }
}

/// Two-point sliding is indeterminate: the factor `k3 = k2 + μ k1 =
/// (1 − μ²) sin θ + 2μ cos θ` of the paper's Eq. 52 is zero to rounding
/// (at θ = −2 atan μ), so the contact forces `(k1 f_z − k2 f_x)/k3` and
/// `(f_z + μ f_x)/k3` are not determined by statics.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error(
    "two-point sliding is indeterminate at theta = {theta} rad: k3 = {k3} (Eq. 52) is zero to rounding"
)]
pub struct SlidingIndeterminate {
    /// The tilt θ (rad).
    pub theta: f64,
    /// The computed `k3` (within its rounding error of 0).
    pub k3: f64,
}
