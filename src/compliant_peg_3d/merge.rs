//! Continuous merging of two contact points of one pair (B1 and B2 of the
//! three-point lean meeting at the two-point configuration).
//!
//! Two penetrating minima `α₁`, `α₂` of one pair's gap `g(α)` are separated
//! by a maximum `α_c` (a col of the overlap). Counting each minimum as a
//! full Hertz point makes the summed force jump when they merge: just
//! before, two points of depth `δ`; just after, one. The rule used instead
//! is inclusion–exclusion of the two overlaps: with `f(δ) = (2/5) k δ^{5/2}`,
//!
//! ```text
//! V = Σ_minima f(δ_i) − Σ_cols f(max(0, δ_c))
//! ```
//!
//! over the cols between consecutive penetrating minima along the circle
//! (when every col of a circle with two or more minima penetrates, the
//! overlap is one ring and the col of least penetration is not subtracted).
//! `V` is symmetric in the points, continuous and continuously
//! differentiable where the points exist: as the stretch between two points
//! starts to overlap `f(δ_c)` rises from zero with zero slope; when a
//! minimum and its col annihilate (a fold) `f(δ_i) − f(δ_c) → 0`; when both
//! minima and the col meet (the symmetric pitchfork at `γ₀`) the three
//! terms leave `f(δ)`, the one point's.
//!
//! Since `α_i` and `α_c` are stationary points of `g`, the envelope theorem
//! gives `−∂V/∂(pose) = Σ k δ_i^{3/2} ∂g(α_i)/∂pose − Σ k δ_c^{3/2}
//! ∂g(α_c)/∂pose`: a force `Q_i n_i` at each point and `−k δ_c^{3/2} n_c`
//! at each subtracted col. [`super::law`] applies the col's force
//! (elastic only: no damping, no friction) with the point it is attached to
//! (the minimum before it in angle).

use super::contact::{ContactPoint, MAX_CONTACTS, Pair, Saddle};
use super::search::minimum::wrap;
use nalgebra::SVector;
use std::f64::consts::TAU;

/// The maximum of `g` in `(lo, hi)` with `g′(lo) > 0 > g′(hi)`, when it
/// penetrates: Newton on `g′` with bisection on its sign. Returns the
/// angle (unwrapped) and the penetration `−g > 0` there, or `None` when
/// the col is out of contact.
///
/// Only a col that penetrates matters to the rule (one with `g ≥ 0` is
/// never subtracted), and every point of `(lo, hi)` has `g` at most the
/// maximum's: so a point of the arc with `g > 0` shows the col out of
/// contact, and its exact place is not needed. `apart(θ)` certifies
/// `g(θ) > 0` without the generated function (the search's profile,
/// [`super::search::Search::find`]); failing that, the first iterate with
/// `g > 0` ends the search. Where the col penetrates the iterates are the
/// full search's.
fn col(
    pair: Pair,
    x: &SVector<f64, 7>,
    p: &SVector<f64, 16>,
    (mut lo, mut hi): (f64, f64),
    apart: &impl Fn(f64) -> bool,
) -> Option<(f64, f64)> {
    let mut a = 0.5 * (lo + hi);
    if apart(wrap(a)) {
        return None;
    }
    for _ in 0..80 {
        let out = pair.eval(x, a, p);
        if out.gap > 0.0 {
            return None;
        }
        let (d1, d2) = (out.d1, out.d2);
        if d1 > 0.0 {
            lo = a;
        } else {
            hi = a;
        }
        let newton = a - d1 / d2;
        let next = if d2 < 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - a).abs() <= 1e-14 * (1.0 + a.abs()) || hi - lo <= 1e-14 {
            a = next;
            break;
        }
        a = next;
    }
    let depth = -pair.eval(x, a, p).gap;
    (depth > 0.0).then_some((a, depth))
}

/// Sets the [`ContactPoint::saddle`] of the points in `points` (the
/// penetrating, valid minima of one pair, in any order; sorted by angle on
/// return) by the inclusion–exclusion rule of this module: the col after
/// each point in angle, when it penetrates and is subtracted. `apart(θ)`
/// (angle in `[0, 2π)`) is true only where the gap is certainly positive
/// (it may always be false).
pub fn assign(
    pair: Pair,
    x: &SVector<f64, 7>,
    p: &SVector<f64, 16>,
    points: &mut [ContactPoint],
    apart: impl Fn(f64) -> bool,
) {
    // One pair has at most MAX_CONTACTS points (the search's minima).
    let n = points.len().min(MAX_CONTACTS);
    let points = &mut points[..n];
    if n < 2 {
        return;
    }
    points.sort_unstable_by(|a, b| a.angle.total_cmp(&b.angle));
    // The penetrating col between point k and point k+1 (cyclically).
    let mut cols = [None; MAX_CONTACTS];
    for (k, c) in cols.iter_mut().enumerate().take(n) {
        let lo = points[k].angle;
        let mut hi = points[(k + 1) % n].angle;
        if hi <= lo {
            hi += TAU;
        }
        *c = col(pair, x, p, (lo, hi), &apart);
    }
    let cols = &cols[..n];
    // One ring: keep the least penetrating col.
    let keep = if cols.iter().all(Option::is_some) {
        (0..n).min_by(|&a, &b| {
            let depth = |k: usize| cols[k].map_or(0.0, |c| c.1);
            depth(a).total_cmp(&depth(b))
        })
    } else {
        None
    };
    for (k, pt) in points.iter_mut().enumerate() {
        pt.saddle = None;
        if let Some((a, depth)) = cols[k]
            && keep != Some(k)
        {
            let a = wrap(a);
            let e = pair.eval(x, a, p);
            pt.saddle = Some(Saddle {
                angle: a,
                penetration: depth,
                gradient: e.grad,
                normal: e.normal,
                point: e.point,
            });
        }
    }
}
