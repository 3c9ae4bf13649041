//! The arcs the certified search starts from, and the sine and cosine of
//! the angles it evaluates most: the start arcs' ends and midpoints.
//!
//! Most searches decide every start arc from its enclosures and the slopes
//! at its ends, so these 16 angles take most of a search's sines and
//! cosines. [`sin_cos`] returns them from a table filled by `f64::sin_cos`
//! itself, so an angle gets the same values whether it is looked up or
//! computed: the search's ends shared by neighbouring arcs stay evaluated
//! identically.

use std::f64::consts::TAU;
use std::sync::LazyLock;

/// The number of arcs the circle starts as.
pub const START: usize = 8;

/// The `k`-th start arc `[lo, hi]` (rad), `k < START`; the last ends at
/// the float `2π`.
pub fn arc(k: usize) -> (f64, f64) {
    let step = TAU / START as f64;
    let lo = k as f64 * step;
    let hi = if k + 1 == START {
        TAU
    } else {
        (k + 1) as f64 * step
    };
    (lo, hi)
}

/// The start arcs' first ends (even `j`) and midpoints (odd `j`),
/// `j < 2 START`, each as the search computes it, with its `(sin, cos)`
/// (the circle's end `2π` is evaluated as its start, `0`).
static TABLE: LazyLock<[(f64, (f64, f64)); 2 * START]> = LazyLock::new(|| {
    std::array::from_fn(|j| {
        let (lo, hi) = arc(j / 2);
        let t = if j % 2 == 0 { lo } else { 0.5 * (lo + hi) };
        (t, t.sin_cos())
    })
});

/// `(sin t, cos t)`: from the table at the start arcs' ends and midpoints
/// (the same values as `t.sin_cos()`), computed elsewhere.
pub fn sin_cos(t: f64) -> (f64, f64) {
    // The nearest table index (a truncating cast of `x + ½`, `x ≥ −½`).
    let x = t * ((2 * START) as f64 / TAU) + 0.5;
    if (0.0..(2 * START) as f64).contains(&x) {
        let (at, v) = TABLE[x as usize];
        if at.to_bits() == t.to_bits() {
            return v;
        }
    }
    t.sin_cos()
}
