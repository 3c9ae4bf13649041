//! Rounding error of the generated functions, measured: every function of
//! [`crate::generated::registry::FUNCTIONS`] is evaluated at `f64` and at
//! double-double ([`crate::scalar::Dd`]) on a grid of hard points
//! ([`grid`]), and the `f64` result is compared with the double-double one.
//!
//! Both evaluations start from the *same* `f64` inputs (converted exactly),
//! and run the *same* formula, so the double-double result is the exact
//! value of that formula to about 1e-30 relative: the difference is the
//! rounding error of the `f64` evaluation, not the error of the model (a
//! formula that is wrong is wrong at both precisions) and not the
//! sensitivity to input errors.
//!
//! `pegdyn accuracy` prints [`Report`] as a table and can write it as CSV;
//! `docs/ACCURACY.md` records the numbers with and without the stable
//! numerical rewrites of the generator.

pub mod grid;
mod table;

use crate::generated::{DdFunction, Function};
use crate::scalar::Dd;
pub use grid::Point;

/// The spacing of `f64` at `x` (the ulp of `|x|`; of the smallest normal
/// number for `|x|` below it).
pub fn ulp(x: f64) -> f64 {
    let a = x.abs().max(f64::MIN_POSITIVE);
    f64::from_bits(a.to_bits() + 1) - a
}

/// Error of one output entry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EntryError {
    /// `|value − reference|` in ulps of the reference (∞ when exactly one
    /// of them is not finite, or the reference is 0 and the value is not).
    pub ulps: f64,
    /// `|value − reference| / |reference|` (∞ for a zero reference and a
    /// non-zero value; 0 when both are 0).
    pub relative: f64,
    /// The value is NaN or infinite while the reference is finite.
    pub non_finite: bool,
}

/// Compares an `f64` result with its double-double reference.
pub fn entry_error(value: f64, reference: Dd) -> EntryError {
    let r = reference.hi();
    if !value.is_finite() || !r.is_finite() {
        let same = value == r || (value.is_nan() && r.is_nan());
        let bad = if same { 0.0 } else { f64::INFINITY };
        return EntryError {
            ulps: bad,
            relative: bad,
            non_finite: !value.is_finite() && r.is_finite(),
        };
    }
    let err = (Dd::from(value) - reference).hi().abs();
    EntryError {
        ulps: if err == 0.0 { 0.0 } else { err / ulp(r) },
        relative: if err == 0.0 { 0.0 } else { err / r.abs() },
        non_finite: false,
    }
}

/// The worst error of one function over the grid of its module.
#[derive(Clone, Debug, PartialEq)]
pub struct FunctionAccuracy {
    /// `module::function`.
    pub path: String,
    /// Grid points evaluated.
    pub points: usize,
    /// Output entries compared (points × entries).
    pub entries: usize,
    /// Worst error in ulps.
    pub max_ulps: f64,
    /// Worst relative error.
    pub max_relative: f64,
    /// Worst normwise error: `|value − reference|` over the largest
    /// `|reference|` among the entries of the same output at the same point
    /// (meaningful where an entry's exact value is 0 or tiny, as in
    /// Jacobians, where ulps and relative error are not).
    pub max_normwise: f64,
    /// Where the worst ulps occurred: point label and output entry.
    pub worst_at: String,
    /// Entries that are NaN or infinite at `f64` with a finite reference.
    pub non_finite: usize,
}

/// Every function's accuracy, in registry order, and the modules without a
/// hard grid.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    /// One row per evaluated function.
    pub functions: Vec<FunctionAccuracy>,
    /// Modules skipped because [`grid::points`] has no grid for them.
    pub skipped: Vec<String>,
}

/// Why a function could not be evaluated at a point.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum AccuracyError {
    /// The grid point does not give a value for an input symbol.
    #[error("grid point `{point}` of module `{module}` has no value for input symbol `{symbol}`")]
    MissingSymbol {
        /// The generated module.
        module: String,
        /// The grid point's name.
        point: String,
        /// The input symbol without a value.
        symbol: String,
    },
}

/// The inputs of `f` at `point`, one vector per input.
fn inputs(f: &Function, point: &Point) -> Result<Vec<Vec<f64>>, AccuracyError> {
    f.inputs
        .iter()
        .map(|(_, names)| {
            names
                .iter()
                .map(|&s| {
                    point.value(s).ok_or_else(|| AccuracyError::MissingSymbol {
                        module: f.module.to_owned(),
                        point: point.label.clone(),
                        symbol: s.to_owned(),
                    })
                })
                .collect()
        })
        .collect()
}

/// Evaluates `f` at every point at both precisions; the worst error.
pub fn measure_function(
    dd: &DdFunction,
    points: &[Point],
) -> Result<FunctionAccuracy, AccuracyError> {
    let f = &dd.function;
    let mut acc = FunctionAccuracy {
        path: f.path(),
        points: points.len(),
        entries: 0,
        max_ulps: 0.0,
        max_relative: 0.0,
        max_normwise: 0.0,
        worst_at: String::new(),
        non_finite: 0,
    };
    for p in points {
        let x = inputs(f, p)?;
        let xf: Vec<&[f64]> = x.iter().map(Vec::as_slice).collect();
        let xd: Vec<Vec<Dd>> = x
            .iter()
            .map(|v| v.iter().map(|&c| Dd::from(c)).collect())
            .collect();
        let xd: Vec<&[Dd]> = xd.iter().map(Vec::as_slice).collect();
        let (lo, hi) = ((f.eval_f64)(&xf), (dd.eval_dd)(&xd));
        // Scale of each output at this point: its largest |reference|.
        let mut scale = Vec::with_capacity(hi.len());
        let mut start = 0;
        for &(_, len) in f.outputs {
            let end = (start + len).min(hi.len());
            let m = hi[start..end]
                .iter()
                .map(|r| r.hi().abs())
                .filter(|v| v.is_finite())
                .fold(0.0, f64::max);
            scale.extend(std::iter::repeat_n(m, end - start));
            start = end;
        }
        for (k, (&v, &r)) in lo.iter().zip(&hi).enumerate() {
            if v.is_finite() && r.is_finite() {
                let err = (Dd::from(v) - r).hi().abs();
                let s = scale.get(k).copied().unwrap_or(0.0);
                let nw = if err == 0.0 {
                    0.0
                } else if s > 0.0 {
                    err / s
                } else {
                    f64::INFINITY
                };
                acc.max_normwise = acc.max_normwise.max(nw);
            }
            let e = entry_error(v, r);
            acc.entries += 1;
            acc.non_finite += usize::from(e.non_finite);
            acc.max_relative = acc.max_relative.max(e.relative);
            if e.ulps > acc.max_ulps || acc.worst_at.is_empty() {
                acc.max_ulps = acc.max_ulps.max(e.ulps);
                acc.worst_at = format!("{} / {}", p.label, f.output_name(k));
            }
        }
    }
    Ok(acc)
}

/// Measures every function in `functions` on the hard grid of its module,
/// restricted to the points whose label contains `only` if given.
pub fn measure(functions: &[DdFunction], only: Option<&str>) -> Result<Report, AccuracyError> {
    let mut report = Report::default();
    for dd in functions {
        let f = &dd.function;
        match grid::points(f.module) {
            Some(mut points) => {
                if let Some(sub) = only {
                    points.retain(|p| p.label.contains(sub));
                }
                if !points.is_empty() {
                    report.functions.push(measure_function(dd, &points)?);
                }
            }
            None => {
                if !report.skipped.iter().any(|m| m == f.module) {
                    report.skipped.push(f.module.to_owned());
                }
            }
        }
    }
    Ok(report)
}
