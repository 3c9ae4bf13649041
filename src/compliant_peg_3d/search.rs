//! The contact search: for each pair, the local minima of the gap `g(α)`
//! along the edge circle (the local maxima of penetration).
//!
//! Each minimum solves `g′(α) = 0` with `g″(α) > 0`, by Newton's method on
//! the generated derivatives, safeguarded by bisection on the sign of `g′`
//! inside a bracket. Two sources of starting points:
//!
//! 1. warm starts — the minima found at the previous call, bracket
//!    `α ± Δ` with `Δ = 2π/N`;
//! 2. a scan of `g` at `N` equally spaced angles: every discrete local
//!    minimum below a margin `s Δ²` (`s` the circle's radius, a bound on how
//!    far `g` dips between samples) not already covered by a warm start is
//!    refined in the bracket of its two neighbours.
//!
//! Minima closer than `10⁻⁹` rad are one. So points appear (a new dip
//! crosses zero), merge (two minima and the maximum between them meet: the
//! refinements converge to one angle) and split again without bookkeeping.
//! Only penetrating minima (`g < 0`) on the part of each surface that
//! exists (see [`Pair::valid`]) become contacts.

use super::contact::{ContactPoint, Pair, axis_of};
use super::merge;
use super::params::Peg3dParams;
use nalgebra::SVector;
use std::f64::consts::TAU;

/// The radius of the pair's edge circle (m): the scale of `g″`.
fn scale(pair: Pair, prm: &Peg3dParams) -> f64 {
    match pair {
        Pair::EdgeSide => prm.bore_radius() + prm.mouth_fillet,
        _ => prm.peg_radius(),
    }
}

/// Number of scan samples per circle.
pub const SAMPLES: usize = 48;

fn wrap(a: f64) -> f64 {
    let w = a.rem_euclid(TAU);
    if w >= TAU { 0.0 } else { w }
}

fn angle_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// Minimum of `g` in `[lo, hi]` from `a`: Newton on `g′`, bisection
/// whenever the Newton step leaves the bracket or `g″ ≤ 0`. Returns the
/// angle when `|g′|` has converged and `g″ > 0`.
fn refine(
    pair: Pair,
    x: &SVector<f64, 7>,
    p: &SVector<f64, 16>,
    mut a: f64,
    mut lo: f64,
    mut hi: f64,
) -> Option<f64> {
    for _ in 0..60 {
        let out = pair.eval(x, a, p);
        let (d1, d2) = (out.d1, out.d2);
        if d1 > 0.0 {
            hi = a;
        } else {
            lo = a;
        }
        let newton = a - d1 / d2;
        let next = if d2 > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - a).abs() <= 1e-13 * (1.0 + a.abs()) || hi - lo <= 1e-13 {
            let out = pair.eval(x, next, p);
            let (d1, d2) = (out.d1, out.d2);
            let tol = 1e-9 * pair_scale_hint(d2);
            return (d2 > 0.0 && d1.abs() <= tol.max(1e-15)).then_some(next);
        }
        a = next;
    }
    None
}

fn pair_scale_hint(d2: f64) -> f64 {
    d2.abs().max(1e-12)
}

/// The contact search of one pair with its warm starts.
#[derive(Clone, Debug, Default)]
pub struct Search {
    warm: Vec<f64>,
}

impl Search {
    /// The angles of every local minimum of `pair`'s gap at pose `x` (unit
    /// quaternion) found from the warm starts and the scan, unfiltered.
    pub fn minima(
        &mut self,
        pair: Pair,
        prm: &Peg3dParams,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
    ) -> Vec<f64> {
        let step = TAU / SAMPLES as f64;
        let margin = scale(pair, prm) * step * step;
        let mut minima: Vec<f64> = Vec::with_capacity(4);
        let push = |minima: &mut Vec<f64>, a: f64| {
            let a = wrap(a);
            if minima.iter().all(|&m| angle_distance(m, a) > 1e-9) {
                minima.push(a);
            }
        };
        for &a in &self.warm {
            if let Some(m) = refine(pair, x, p, a, a - step, a + step) {
                push(&mut minima, m);
            }
        }
        let mut gaps = [0.0; SAMPLES];
        for (k, g) in gaps.iter_mut().enumerate() {
            *g = pair.eval(x, k as f64 * step, p).gap;
        }
        for k in 0..SAMPLES {
            let prev = gaps[(k + SAMPLES - 1) % SAMPLES];
            let next = gaps[(k + 1) % SAMPLES];
            let g = gaps[k];
            if g < margin && g <= prev && g <= next {
                let a = k as f64 * step;
                if minima.iter().any(|&m| angle_distance(m, a) < step) {
                    continue;
                }
                if let Some(m) = refine(pair, x, p, a, a - step, a + step) {
                    push(&mut minima, m);
                }
            }
        }
        self.warm.clear();
        for &a in &minima {
            if pair.eval(x, a, p).gap < margin {
                self.warm.push(a);
            }
        }
        minima
    }

    /// The penetrating, valid local minima of `pair`'s gap at pose `x`
    /// (unit quaternion), appended to `out`; the warm starts are updated to
    /// every minimum found below the scan margin.
    pub fn find(
        &mut self,
        pair: Pair,
        prm: &Peg3dParams,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
        out: &mut Vec<ContactPoint>,
    ) {
        let minima = self.minima(pair, prm, x, p);
        let axis = axis_of(x);
        let first = out.len();
        for &a in &minima {
            let e = pair.eval(x, a, p);
            if e.gap < 0.0
                && pair.valid(prm, &axis, &e.normal, &e.point, e.axial)
                && pair.rim_faces_out(x, &e.normal, &e.point)
            {
                out.push(ContactPoint {
                    pair,
                    angle: a,
                    penetration: -e.gap,
                    gradient: e.grad,
                    normal: e.normal,
                    point: e.point,
                    saddle: None,
                    ring: false,
                });
            }
        }
        merge::assign(pair, x, p, &mut out[first..]);
    }
}
