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
    /// The curvature ratio `B/A` is so large that the contact ellipse is
    /// effectively a line (`a/b` beyond about `10⁷`), where Hertz's point
    /// contact does not apply and the elliptic integrals lose their digits.
    #[error(
        "curvature ratio B/A = {ratio:e} exceeds {limit:e}: the contact is a line contact, \
         outside Hertz's elliptical point-contact solution"
    )]
    LineContact {
        /// The ratio `B/A` given.
        ratio: f64,
        /// The largest ratio accepted ([`super::ellipticity::MAX_RATIO`]).
        limit: f64,
    },
    /// An iterative kernel did not converge within its iteration cap.
    #[error("{kernel} did not converge within {iterations} iterations for input {input:e}")]
    NoConvergence {
        /// The kernel, e.g. `ellipticity solve`.
        kernel: &'static str,
        /// The input it was given.
        input: f64,
        /// The iteration cap reached.
        iterations: usize,
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
