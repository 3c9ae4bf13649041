//! Errors of the Hertz contact computation: bad input named by field.

/// Why a Hertz contact could not be set up.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum HertzError {
    /// An input value is out of its physical range.
    #[error("`{field}` = {value}: {reason}")]
    Invalid {
        /// The offending field, e.g. `youngs_modulus` or `peg.poisson_ratio`.
        field: String,
        /// The value given.
        value: f64,
        /// Why it is refused.
        reason: &'static str,
    },
    /// The bodies do not touch in a point: one relative curvature is zero or
    /// negative (a line contact, or a conforming contact), where Hertz's
    /// elliptical solution does not apply.
    #[error(
        "not a point contact: relative curvatures A = {a} 1/m and B = {b} 1/m must both be positive"
    )]
    NotPointContact {
        /// The smaller relative curvature `A` (1/m).
        a: f64,
        /// The larger relative curvature `B` (1/m).
        b: f64,
    },
}

impl HertzError {
    /// The same error with `prefix.` put before the field name (so that a
    /// scene can report `peg.youngs_modulus` for a material's
    /// `youngs_modulus`).
    pub fn with_prefix(self, prefix: &str) -> HertzError {
        match self {
            HertzError::Invalid {
                field,
                value,
                reason,
            } => HertzError::Invalid {
                field: format!("{prefix}.{field}"),
                value,
                reason,
            },
            other => other,
        }
    }
}

/// `Ok(v)` if `v` is finite and positive, else an [`HertzError::Invalid`]
/// naming `field`.
pub(crate) fn positive(field: &str, v: f64) -> Result<f64, HertzError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(HertzError::Invalid {
            field: field.to_owned(),
            value: v,
            reason: "must be finite and > 0",
        })
    }
}
