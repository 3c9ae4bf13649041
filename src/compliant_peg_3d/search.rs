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

use super::merge::{self, Saddle};
use super::params::Peg3dParams;
use crate::generated::compliant_peg_3d as generated;
use nalgebra::{SVector, Vector1, Vector3};
use std::f64::consts::TAU;

/// The contact pairs (the generator's own definition).
#[path = "../../equations/src/models/compliant_peg_3d/pair.rs"]
mod pair;
pub use pair::Pair;

impl Pair {
    /// The generated function of this pair at pose `x` and angle `a`: gap,
    /// `g′`, `g″`, gradient in the pose, force direction, contact point,
    /// axial coordinate.
    pub fn eval(
        self,
        x: &SVector<f64, 7>,
        a: f64,
        p: &SVector<f64, 16>,
    ) -> generated::PairGeometry<f64> {
        let a = Vector1::new(a);
        match self {
            Pair::EdgeSide => generated::edge_side(x, &a, p),
            Pair::RimWall => generated::rim_wall(x, &a, p),
            Pair::RimTop => generated::rim_top(x, &a, p),
            Pair::RimBottom => generated::rim_bottom(x, &a, p),
            Pair::RimEdge => generated::rim_edge(x, &a, p),
        }
    }

    /// The radius of the pair's edge circle (m): the scale of `g″`.
    fn scale(self, prm: &Peg3dParams) -> f64 {
        match self {
            Pair::EdgeSide => prm.bore_radius() + prm.mouth_fillet,
            _ => prm.peg_radius(),
        }
    }

    /// Whether a stationary point lies on surfaces that exist: the mouth
    /// fillet is the quarter torus facing up and inwards (force direction
    /// `n` on the peg with `n_z ≥ 0`) and touches the peg's side above the
    /// rim fillet; the rim fillet is the quarter facing down and outwards
    /// (`n·a ≥ 0`: the pushed direction has no component down the axis);
    /// the bore wall spans `−h_b ≤ z ≤ −ρ_h`; the top face lies outside
    /// radius `R + ρ_h`, the bore bottom inside `R`; the rim against the
    /// mouth needs both quarters: `n_z ≥ 0`, `n` pointing inwards
    /// (`n·(x, y) ≤ 0` at the point) and `n·a ≥ 0` (the rim's outward
    /// half is checked by [`Pair::rim_faces_out`], which needs the pose).
    pub fn valid(
        self,
        prm: &Peg3dParams,
        axis: &Vector3<f64>,
        n: &Vector3<f64>,
        pt: &Vector3<f64>,
        axial: f64,
    ) -> bool {
        let radial = pt.xy().norm();
        match self {
            Pair::EdgeSide => {
                n.z >= 0.0
                    && axial >= prm.rim_fillet - 0.5 * prm.length
                    && axial <= 0.5 * prm.length
            }
            Pair::RimWall => {
                n.dot(axis) >= 0.0 && pt.z <= -prm.mouth_fillet && pt.z >= -prm.bore_depth
            }
            Pair::RimTop => axis.z >= 0.0 && radial >= prm.bore_radius() + prm.mouth_fillet,
            Pair::RimBottom => axis.z >= 0.0 && radial <= prm.bore_radius(),
            Pair::RimEdge => n.z >= 0.0 && n.xy().dot(&pt.xy()) <= 0.0 && n.dot(axis) >= 0.0,
        }
    }

    /// Whether the rim fillet's surface point of a contact at `pt` lies on
    /// the rim's outer half (the torus's inner half is the flat bottom
    /// face): the outward normal `−n` of the rim has a non-negative
    /// component along the outward radial direction from the peg's axis,
    /// `−n·((pt − p) − ((pt − p)·a) a) ≥ 0`. True for the pairs that do not
    /// involve the rim against a torus.
    pub fn rim_faces_out(self, x: &SVector<f64, 7>, n: &Vector3<f64>, pt: &Vector3<f64>) -> bool {
        if self != Pair::RimEdge {
            return true;
        }
        let axis = super::system::axis_of(x);
        let rel = pt - Vector3::new(x[0], x[1], x[2]);
        let radial = rel - axis * rel.dot(&axis);
        -n.dot(&radial) >= 0.0
    }
}

/// One contact point: a penetrating local minimum of a pair's gap.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPoint {
    /// The pair.
    pub pair: Pair,
    /// Angle along the pair's edge circle (rad, in `[0, 2π)`).
    pub angle: f64,
    /// Penetration `δ = −g > 0` (m).
    pub penetration: f64,
    /// Gradient of the gap in the pose `(p, q)`.
    pub gradient: SVector<f64, 7>,
    /// Unit direction of the contact force on the peg, hole frame.
    pub normal: Vector3<f64>,
    /// Contact point, hole frame (m).
    pub point: Vector3<f64>,
    /// The col between this point and the next point of the same pair
    /// (in angle) when the overlap between them is connected: its overlap
    /// is subtracted once ([`super::merge`]); `None` otherwise.
    pub saddle: Option<Saddle>,
    /// True for the distributed ring of the peg's bottom on a flat
    /// ([`super::face`]): then `angle` is the body angle of the deepest rim
    /// point, `penetration` its depth `δ₀ + A`, `gradient` the gap's there,
    /// `normal` is `e_z` and `point` the centre of pressure on the flat.
    pub ring: bool,
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
        let g = pair.eval(x, a, p);
        let (d1, d2) = (g.d1, g.d2);
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
            let g = pair.eval(x, next, p);
            let (d1, d2) = (g.d1, g.d2);
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
        let margin = pair.scale(prm) * step * step;
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
        let axis = super::system::axis_of(x);
        let first = out.len();
        for &a in &minima {
            let g = pair.eval(x, a, p);
            if g.gap < 0.0
                && pair.valid(prm, &axis, &g.normal, &g.point, g.axial)
                && pair.rim_faces_out(x, &g.normal, &g.point)
            {
                out.push(ContactPoint {
                    pair,
                    angle: a,
                    penetration: -g.gap,
                    gradient: g.grad,
                    normal: g.normal,
                    point: g.point,
                    saddle: None,
                    ring: false,
                });
            }
        }
        merge::assign(pair, x, p, &mut out[first..]);
    }
}
