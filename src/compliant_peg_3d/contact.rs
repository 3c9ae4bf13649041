//! The contact types of the compliant 3-D peg, below the search, the
//! merge rule, the pruning bounds and the law that use them: the pairs
//! and their generated functions ([`Pair::eval`], the one place they are
//! called), a contact point and its col, where and how deep a contact is
//! at any scalar ([`Geometry`]), a contact followed through its stationary
//! angle in dual numbers ([`Pair::at_stationary`]), and the peg's axis.

use super::frame;
use super::params::Peg3dParams;
use crate::generated::compliant_peg_3d as generated;
use crate::scalar::{Dual, Real};
use nalgebra::{SVector, Vector1, Vector3};

/// The contact pairs (the generator's own definition).
#[path = "../../equations/src/models/compliant_peg_3d/pair.rs"]
mod pair;
pub use pair::Pair;

/// The outputs of one generated pair function at pose `x` and edge angle
/// `α` (the generated struct: gap, `g′`, `g″`, pose gradient, force
/// direction, contact point, axial coordinate).
pub type PairOut<T> = generated::PairGeometry<T>;

impl Pair {
    /// The pair's index in [`Pair::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// The generated function of this pair at pose `x` (unit quaternion),
    /// edge angle `a` (rad) and parameter vector `p`
    /// ([`Peg3dParams::vector`]), at any scalar.
    pub fn eval<T: Real>(self, x: &SVector<T, 7>, a: T, p: &SVector<T, 16>) -> PairOut<T> {
        let a = Vector1::new(a);
        match self {
            Pair::EdgeSide => generated::edge_side(x, &a, p),
            Pair::RimWall => generated::rim_wall(x, &a, p),
            Pair::RimTop => generated::rim_top(x, &a, p),
            Pair::RimBottom => generated::rim_bottom(x, &a, p),
            Pair::RimEdge => generated::rim_edge(x, &a, p),
        }
    }

    /// Gap, force direction and point of this pair at its stationary angle
    /// `angle` (rad), as dual numbers in the pose `x` alone: the generated
    /// function is evaluated with the angle seeded in the last slot
    /// `N − 1`, then that slot is eliminated by the implicit-function
    /// theorem on `g′(α*(x), x) = 0`,
    ///
    /// ```text
    /// dα*/dx = −(∂g′/∂x) / g″,   do/dx = ∂o/∂x + ∂o/∂α · dα*/dx
    /// ```
    ///
    /// (for the gap the second term vanishes: the envelope theorem). The
    /// returned penetration is `−g`.
    pub fn at_stationary<const N: usize>(
        self,
        x: &SVector<Dual<N>, 7>,
        angle: f64,
        p: &SVector<Dual<N>, 16>,
    ) -> Geometry<Dual<N>> {
        let out = self.eval(x, Dual::variable(angle, N - 1), p);
        let curv = out.d1.d[N - 1];
        let mut slope = [0.0; N];
        for (k, s) in slope.iter_mut().enumerate().take(N - 1) {
            *s = -out.d1.d[k] / curv;
        }
        let total = |o: Dual<N>| {
            let mut d = o.d;
            let da = d[N - 1];
            for k in 0..N - 1 {
                d[k] += da * slope[k];
            }
            d[N - 1] = 0.0;
            Dual { v: o.v, d }
        };
        Geometry {
            normal: [
                total(out.normal[0]),
                total(out.normal[1]),
                total(out.normal[2]),
            ],
            point: [
                total(out.point[0]),
                total(out.point[1]),
                total(out.point[2]),
            ],
            penetration: -total(out.gap),
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
        let axis = axis_of(x);
        let rel = pt - Vector3::new(x[0], x[1], x[2]);
        let radial = rel - axis * rel.dot(&axis);
        -n.dot(&radial) >= 0.0
    }
}

/// The peg's axis `a = R(q) e_z` of a pose `(p, q)`, `q = (w, i, j, k)`
/// a unit quaternion: [`frame::axis`] at `f64`.
pub fn axis_of(x: &SVector<f64, 7>) -> Vector3<f64> {
    let xs: [f64; 7] = (*x).into();
    Vector3::from(frame::axis(&xs))
}

/// Where and how deep a contact (or its col) is, at any scalar: what the
/// contact law ([`super::law`]) needs of the geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry<T> {
    /// Unit direction of the contact force on the peg, hole frame.
    pub normal: frame::V3<T>,
    /// Contact point, hole frame (m).
    pub point: frame::V3<T>,
    /// Penetration `δ = −g` (m).
    pub penetration: T,
}

/// The most contact points of one state: at most two minima of each
/// trigonometric profile of degree two (the mouth edge on the side, the rim
/// on the wall), one of each rim–plane sinusoid, the search's
/// [`super::search::MAX_MINIMA`] of the rim on the mouth, and a ring per
/// flat.
pub const MAX_CONTACTS: usize = 16;

/// The contact points of one state, in a fixed-capacity array (no
/// allocation in the right-hand side).
pub type Contacts = arrayvec::ArrayVec<ContactPoint, MAX_CONTACTS>;

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

impl ContactPoint {
    /// The point's [`Geometry`] at `f64`.
    pub fn geometry(&self) -> Geometry<f64> {
        Geometry {
            normal: self.normal.into(),
            point: self.point.into(),
            penetration: self.penetration,
        }
    }
}

/// A col attached to a contact point: the penetrating maximum of the gap
/// between it and the next minimum of the same pair, whose overlap is
/// subtracted once ([`super::merge::assign`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Saddle {
    /// Angle along the pair's edge circle (rad, in `[0, 2π)`).
    pub angle: f64,
    /// Penetration at the col `δ_col > 0` (m).
    pub penetration: f64,
    /// Gradient of the gap in the pose `(p, q)` at the col.
    pub gradient: SVector<f64, 7>,
    /// Unit force direction at the col, hole frame.
    pub normal: Vector3<f64>,
    /// The col's contact point, hole frame (m).
    pub point: Vector3<f64>,
}

impl Saddle {
    /// The col's [`Geometry`] at `f64`.
    pub fn geometry(&self) -> Geometry<f64> {
        Geometry {
            normal: self.normal.into(),
            point: self.point.into(),
            penetration: self.penetration,
        }
    }
}
