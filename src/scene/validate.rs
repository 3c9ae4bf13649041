//! Validation helpers for scene values. Each check names the field by its
//! dotted path and reports the offending value; NaN and ±inf are rejected
//! by every numeric check (TOML can spell them `nan` and `inf`).
//!
//! Two styles: free functions returning `Result<f64, SceneError>` for use
//! with `?`, and [`Checker`], which collects every problem so that
//! `pegdyn check` can report them all at once.
//!
//! ```
//! use pegdyn::scene::validate::Checker;
//! let mut c = Checker::default();
//! let m = c.positive("peg.mass", -1.0);
//! let l = c.positive("peg.length", 0.5);
//! assert_eq!(l, 0.5);
//! let errors = c.finish().unwrap_err();
//! assert_eq!(errors.errors.len(), 1);
//! assert!(errors.to_string().contains("peg.mass"));
//! # let _ = m;
//! ```

use crate::error::{SceneError, SceneErrors};

/// `v` is finite (not NaN, not ±inf).
pub fn finite(field: &str, v: f64) -> Result<f64, SceneError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(SceneError::invalid(field, v, "must be a finite number"))
    }
}

/// `v` is finite and `> 0`.
pub fn positive(field: &str, v: f64) -> Result<f64, SceneError> {
    finite(field, v)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(SceneError::invalid(field, v, "must be positive"))
    }
}

/// `v` is finite and `>= 0`.
pub fn non_negative(field: &str, v: f64) -> Result<f64, SceneError> {
    finite(field, v)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err(SceneError::invalid(field, v, "must not be negative"))
    }
}

/// `v` is finite and in the closed interval `[lo, hi]`.
pub fn in_range(field: &str, v: f64, lo: f64, hi: f64) -> Result<f64, SceneError> {
    finite(field, v)?;
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(SceneError::invalid(
            field,
            v,
            format!("must lie in [{lo}, {hi}]"),
        ))
    }
}

/// `v` is finite and strictly greater than `bound`, the value of field
/// `bound_field` (e.g. `t_end > t0`).
pub fn greater_than(field: &str, v: f64, bound_field: &str, bound: f64) -> Result<f64, SceneError> {
    finite(field, v)?;
    if v > bound {
        Ok(v)
    } else {
        Err(SceneError::invalid(
            field,
            v,
            format!("must be greater than {bound_field} = {bound:?}"),
        ))
    }
}

/// Collects validation problems instead of stopping at the first one.
/// Each method returns the value it checked so that it can be used inline.
#[derive(Debug, Default)]
pub struct Checker {
    errors: Vec<SceneError>,
}

impl Checker {
    /// Records the error of `result`, if any, and returns its value (or
    /// `fallback` on error, so that the caller can continue checking).
    pub fn check<T>(&mut self, result: Result<T, SceneError>, fallback: T) -> T {
        match result {
            Ok(v) => v,
            Err(e) => {
                self.errors.push(e);
                fallback
            }
        }
    }

    /// Records an error.
    pub fn push(&mut self, error: SceneError) {
        self.errors.push(error);
    }

    /// Records `error` unless the same error (same message) is recorded
    /// already: a problem every point of a grid shares is reported once.
    pub fn push_once(&mut self, error: SceneError) {
        let text = error.to_string();
        if !self.errors.iter().any(|e| e.to_string() == text) {
            self.errors.push(error);
        }
    }

    /// Appends the errors of a nested check (e.g. an integrator table).
    pub fn extend(&mut self, result: Result<(), SceneErrors>) {
        if let Err(e) = result {
            self.errors.extend(e.errors.into_iter().map(|l| l.error));
        }
    }

    /// See [`finite`].
    pub fn finite(&mut self, field: &str, v: f64) -> f64 {
        self.check(finite(field, v), v)
    }

    /// See [`positive`].
    pub fn positive(&mut self, field: &str, v: f64) -> f64 {
        self.check(positive(field, v), v)
    }

    /// See [`non_negative`].
    pub fn non_negative(&mut self, field: &str, v: f64) -> f64 {
        self.check(non_negative(field, v), v)
    }

    /// See [`in_range`].
    pub fn in_range(&mut self, field: &str, v: f64, lo: f64, hi: f64) -> f64 {
        self.check(in_range(field, v, lo, hi), v)
    }

    /// See [`greater_than`].
    pub fn greater_than(&mut self, field: &str, v: f64, bound_field: &str, bound: f64) -> f64 {
        self.check(greater_than(field, v, bound_field, bound), v)
    }

    /// Refuses every entry of the list `field` that repeats an earlier one
    /// (`field[k]` named, with the index it repeats): a grid or list point
    /// is computed once, so a repeat would either run twice and count
    /// twice or be silently dropped.
    pub fn distinct(&mut self, field: &str, values: &[f64]) {
        for (k, v) in values.iter().enumerate() {
            if let Some(j) = values[..k].iter().position(|u| u == v) {
                self.push(SceneError::invalid(
                    format!("{field}[{k}]"),
                    v,
                    format!("repeats {field}[{j}]: each value is computed once; remove the repeat"),
                ));
            }
        }
    }

    /// Whether a problem of `field` has been recorded.
    pub fn has_error(&self, field: &str) -> bool {
        self.errors.iter().any(|e| e.field() == Some(field))
    }

    /// Whether nothing has been recorded so far.
    pub fn is_ok(&self) -> bool {
        self.errors.is_empty()
    }

    /// `Ok(())` when no problem was recorded, else all of them.
    pub fn finish(self) -> Result<(), SceneErrors> {
        if self.errors.is_empty() {
            Ok(())
        } else {
            Err(SceneErrors::new(self.errors))
        }
    }
}
