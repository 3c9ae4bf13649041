//! Bounded work, announced: every scene estimates its work (output samples,
//! integrator steps, grid points, runs of a sweep, memory) before it runs,
//! and a scene whose estimate exceeds a limit is refused by `pegdyn check`
//! and `pegdyn run` with the field and the estimate named — unless the scene
//! raises the limit in its `[limits]` table:
//!
//! ```toml
//! [limits]
//! max_output_samples = 1_000_000   # stored output times of one integration
//! max_steps = 10_000_000           # integrator.max_steps (a sensitivity run: (1 + P) times it)
//! max_grid_points = 1_000_000      # points of a parameter grid (fig9 gamma x psidot)
//! max_runs = 2_500                 # integrations of a sweep (jamming sweep n^2)
//! max_memory_mb = 1_024            # estimated memory of the stored results, MiB
//! ```
//!
//! The estimates are computed in floating point from the scene's fields,
//! so that a count of `1e300` is an estimate, never an allocation.
//!
//! ```
//! use pegdyn::scene::limits::{Limits, WorkItem};
//! let work = [WorkItem::new("integrator.output_interval", "max_output_samples", 1e12, 256.0)];
//! let e = Limits::default().check(&work).unwrap_err().to_string();
//! assert!(e.contains("integrator.output_interval") && e.contains("1.000e12"), "{e}");
//! ```

use serde::Deserialize;

use crate::error::{SceneError, SceneErrors};

pub use super::reserve::{ReserveError, try_with_capacity};

/// The `[limits]` table: upper bounds on the work one scene may ask for.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Limits {
    /// Largest number of stored output samples of one integration.
    pub max_output_samples: u64,
    /// Largest integrator step budget (`integrator.max_steps`); a run
    /// integrating `k` times the model's states per step (forward
    /// sensitivities) counts `k` steps per step.
    pub max_steps: u64,
    /// Largest number of points of a parameter grid.
    pub max_grid_points: u64,
    /// Largest number of integrations of a sweep.
    pub max_runs: u64,
    /// Largest estimated memory of the stored results, MiB.
    pub max_memory_mb: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_output_samples: 1_000_000,
            max_steps: 10_000_000,
            max_grid_points: 1_000_000,
            max_runs: 2_500,
            max_memory_mb: 1_024,
        }
    }
}

/// One item of a scene's work estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkItem {
    /// The scene field that sets this amount of work, e.g. `gamma.count`.
    pub field: String,
    /// The `[limits]` key that bounds it, e.g. `max_grid_points`.
    pub limit: &'static str,
    /// The estimated count (samples, steps, points or runs).
    pub count: f64,
    /// Estimated bytes stored per counted item (0 when nothing is stored).
    pub bytes_each: f64,
    /// The field's own value, shown in the error (else the estimate is).
    pub value: Option<f64>,
}

impl WorkItem {
    /// An item: `count` units of work set by `field`, bounded by `limit`,
    /// storing `bytes_each` bytes per unit.
    pub fn new(field: impl Into<String>, limit: &'static str, count: f64, bytes_each: f64) -> Self {
        WorkItem {
            field: field.into(),
            limit,
            count,
            bytes_each,
            value: None,
        }
    }

    /// The same item, showing the field's own value `v` in errors.
    pub fn with_value(mut self, v: f64) -> Self {
        self.value = Some(v);
        self
    }

    fn shown(&self) -> Raw {
        Raw(match self.value {
            Some(v) => format!("{v:?}"),
            None => format!("{:.4e}", self.count),
        })
    }
}

impl Limits {
    /// The bound of the limit named `key` (`None` for an unknown key).
    pub fn get(&self, key: &str) -> Option<u64> {
        match key {
            "max_output_samples" => Some(self.max_output_samples),
            "max_steps" => Some(self.max_steps),
            "max_grid_points" => Some(self.max_grid_points),
            "max_runs" => Some(self.max_runs),
            "max_memory_mb" => Some(self.max_memory_mb),
            _ => None,
        }
    }

    /// Compares the estimate `work` with the limits; every item above its
    /// limit, and the total memory above `max_memory_mb`, is one error
    /// naming the field, the estimate and the `[limits]` key that raises it.
    ///
    /// # Errors
    /// All the violations at once.
    pub fn check(&self, work: &[WorkItem]) -> Result<(), SceneErrors> {
        let mut errors = Vec::new();
        for item in work {
            let bound = self.get(item.limit).unwrap_or(0) as f64;
            if item.count.is_nan() || item.count > bound {
                errors.push(SceneError::invalid(
                    item.field.clone(),
                    item.shown(),
                    format!(
                        "asks for about {:.3e} {} ({}), above the limit {bound:e}; \
                         raise `[limits] {} = ...` (or `--limit {}=...`) if this is intended",
                        item.count,
                        unit(item.limit),
                        item.limit,
                        item.limit,
                        item.limit,
                    ),
                ));
            }
        }
        let bytes: f64 = work.iter().map(|w| w.count * w.bytes_each).sum();
        let mib = bytes / (1024.0 * 1024.0);
        if mib.is_nan() || mib > self.max_memory_mb as f64 {
            let worst = work
                .iter()
                .max_by(|a, b| (a.count * a.bytes_each).total_cmp(&(b.count * b.bytes_each)));
            errors.push(SceneError::invalid(
                worst.map_or("limits", |w| w.field.as_str()),
                worst.map_or_else(|| Raw(format!("{mib:.3e} MiB")), WorkItem::shown),
                format!(
                    "the stored results would need about {mib:.3e} MiB, above the limit of {} MiB; \
                     raise `[limits] max_memory_mb = ...` (or `--limit max_memory_mb=...`) \
                     if this is intended",
                    self.max_memory_mb
                ),
            ));
        }
        if errors.is_empty() {
            Ok(())
        } else {
            Err(SceneErrors::new(errors))
        }
    }
}

/// Limits raised (or lowered) from outside the scene, e.g. by
/// `pegdyn run --limit max_output_samples=1e8`: `KEY=VALUE` pairs whose
/// keys are those of the `[limits]` table (the `max_` prefix may be left
/// out, and `samples` stands for `max_output_samples`). An override
/// replaces the scene's own value of that key.
///
/// ```
/// use pegdyn::scene::limits::{LimitOverrides, Limits};
/// let o = LimitOverrides::parse(&["samples=1e8", "max_runs=10000"]).unwrap();
/// let l = o.apply(Limits::default());
/// assert_eq!((l.max_output_samples, l.max_runs), (100_000_000, 10_000));
/// assert!(LimitOverrides::parse(&["max_sample=5"]).is_err());
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LimitOverrides {
    /// `(key of the [limits] table, value)`, in the order given.
    pub values: Vec<(&'static str, u64)>,
}

/// The `[limits]` keys.
pub const KEYS: [&str; 5] = [
    "max_output_samples",
    "max_steps",
    "max_grid_points",
    "max_runs",
    "max_memory_mb",
];

/// A `--limit KEY=VALUE` argument that cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("--limit `{arg}`: {reason}")]
pub struct LimitArgError {
    /// The argument as given.
    pub arg: String,
    /// What is wrong with it.
    pub reason: String,
}

impl LimitOverrides {
    /// Parses `KEY=VALUE` arguments. `VALUE` is a whole number `>= 1`,
    /// written as an integer (`100_000_000`) or a float (`1e8`).
    ///
    /// # Errors
    /// The first argument that has no `=`, an unknown key, or a value that
    /// is not a whole number in `[1, 2^64)`.
    pub fn parse<S: AsRef<str>>(args: &[S]) -> Result<Self, LimitArgError> {
        let mut values = Vec::new();
        for arg in args {
            let arg = arg.as_ref();
            let fail = |reason: String| LimitArgError {
                arg: arg.to_owned(),
                reason,
            };
            let (key, value) = arg
                .split_once('=')
                .ok_or_else(|| fail("expected KEY=VALUE, e.g. max_output_samples=1e8".into()))?;
            let key = key.trim();
            let canonical = match key {
                "samples" | "output_samples" => "max_output_samples",
                k => KEYS
                    .iter()
                    .copied()
                    .find(|c| *c == k || c.strip_prefix("max_") == Some(k))
                    .ok_or_else(|| {
                        fail(format!(
                            "unknown limit `{key}`; the keys are {} (as in the [limits] table)",
                            KEYS.join(", ")
                        ))
                    })?,
            };
            let text = value.trim().replace('_', "");
            let exact = match text.parse::<u64>() {
                Ok(n) => n,
                Err(_) => {
                    let v: f64 = text
                        .parse()
                        .map_err(|_| fail(format!("`{}` is not a number", value.trim())))?;
                    // 2^64 is the first f64 above u64::MAX.
                    let whole = v.is_finite() && v.fract() == 0.0;
                    if !(whole && (0.0..18_446_744_073_709_551_616.0).contains(&v)) {
                        return Err(fail(format!("{v:e} must be a whole number in [1, 2^64)")));
                    }
                    v as u64
                }
            };
            if exact == 0 {
                return Err(fail("must be a whole number in [1, 2^64)".into()));
            }
            values.push((canonical, exact));
        }
        Ok(LimitOverrides { values })
    }

    /// `limits` with every override applied.
    pub fn apply(&self, mut limits: Limits) -> Limits {
        for &(key, v) in &self.values {
            match key {
                "max_output_samples" => limits.max_output_samples = v,
                "max_steps" => limits.max_steps = v,
                "max_grid_points" => limits.max_grid_points = v,
                "max_runs" => limits.max_runs = v,
                _ => limits.max_memory_mb = v,
            }
        }
        limits
    }
}

/// A value shown as written (its `Debug` is its text, without quotes).
struct Raw(String);

impl std::fmt::Debug for Raw {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

fn unit(limit: &str) -> &'static str {
    match limit {
        "max_output_samples" => "output samples",
        "max_steps" => "integrator steps",
        "max_grid_points" => "grid points",
        "max_runs" => "runs",
        _ => "units",
    }
}

/// The number of output samples of a span `t_end − t0` sampled every `dt`
/// (the count [`crate::scene::IntegratorSpec::output_times`] yields), as
/// f64 so that absurd spans give an estimate instead of an overflow.
pub fn sample_count(t0: f64, t_end: f64, dt: f64) -> f64 {
    ((t_end - t0) / dt).floor() + 2.0
}
