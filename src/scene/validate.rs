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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_non_finite_with_field_and_value() {
        for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let e = positive("peg.mass", v).unwrap_err().to_string();
            assert!(
                e.contains("peg.mass") && e.contains(&format!("{v:?}")),
                "{e}"
            );
        }
    }

    #[test]
    fn sign_checks() {
        assert!(positive("a", 0.0).is_err());
        assert_eq!(positive("a", 1e-300).ok(), Some(1e-300));
        assert!(non_negative("a", -1e-300).is_err());
        assert_eq!(non_negative("a", 0.0).ok(), Some(0.0));
        assert!(in_range("a", 1.5, 0.0, 1.0).is_err());
        assert!(greater_than("t_end", 1.0, "t0", 1.0).is_err());
        assert_eq!(greater_than("t_end", 2.0, "t0", 1.0).ok(), Some(2.0));
    }

    #[test]
    fn repeated_list_entries_are_named_with_the_entry_they_repeat() {
        let mut c = Checker::default();
        c.distinct("grid.a", &[0.0, 2e-4, 1.0, 2e-4, -0.0, 3.0]);
        c.distinct("grid.b", &[1.0, f64::NAN, f64::NAN]);
        let e = c.finish().unwrap_err();
        let got: Vec<String> = e.errors.iter().map(|l| l.error.to_string()).collect();
        assert_eq!(got.len(), 2, "{got:?}");
        assert!(
            got[0].starts_with("`grid.a[3]` = 0.0002: repeats grid.a[1]"),
            "{got:?}"
        );
        assert!(
            got[1].starts_with("`grid.a[4]` = -0.0: repeats grid.a[0]"),
            "{got:?}"
        );
    }

    #[test]
    fn checker_collects_all() {
        let mut c = Checker::default();
        c.positive("a", -1.0);
        c.finite("b", f64::NAN);
        c.positive("c", 2.0);
        let e = c.finish().unwrap_err();
        assert_eq!(e.errors.len(), 2);
        assert_eq!(e.errors[1].error.field(), Some("b"));
    }
}
