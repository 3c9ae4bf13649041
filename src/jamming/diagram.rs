//! The jamming diagram (paper §4.1.1, Fig. 6; Whitney 1982): the set of load
//! ratios (F_x/F_z, M/(r F_z)) under which a peg in two-point contact at
//! depth l slides in instead of jamming.
//!
//! For the reference tilt, the two-point sliding line runs between the two
//! load ratios where one contact force vanishes ([`super::forces`]):
//!
//! ```text
//! edge only (f_tip = 0):  P₁ = (k1/k2, (l + μr)/(r k2))     → Whitney (1/μ, 1 + 2λ)
//! tip only  (f_edge = 0): P₂ = (−1/μ, −k2/μ)                → Whitney (−1/μ, −1)
//! ```
//!
//! with k1 = cos θ − μ sin θ, k2 = sin θ + μ cos θ, λ = l/(2rμ). Above that
//! line (larger moment) the contacts hold the load inside their friction
//! cones: the peg jams. In one-point contact the load is stuck when the force
//! lies inside the single contact's friction cone: F_x/F_z < −1/μ at the tip
//! (wall normal +x), F_x/F_z > cot(θ + atan μ) = k1/k2 at the edge (normal
//! tilted by θ). The opposite tilt is the point reflection
//! (F_x, M) → (−F_x, −M). Intersecting the two tilts leaves the parallelogram
//!
//! ```text
//! −P₁,  Q = (P₁ₓ, y₂(P₁ₓ)),  P₁,  −Q          (counter-clockwise)
//! ```
//!
//! bounded by the two two-point lines and the edge-contact cone limits
//! |F_x/F_z| = k1/k2 (y₂ is the mirrored two-point line). Inside: no jamming;
//! on the edges: equilibrium sliding; outside: jamming. At θ = 0, Q = −P₂ and
//! this is Whitney's parallelogram ([`whitney_parallelogram`]); at finite θ the
//! tip-only ends ±P₂ of the two-point lines lie outside it
//! ([`two_point_segment`]).

use super::error::ParamError;
use super::geometry::two_point_tilt;
use super::params::PegHole;
use crate::scalar::Real;

/// A point of the diagram: (F_x/F_z, M/(r F_z)), moment about the peg tip.
pub type Ratio = [f64; 2];

/// The no-jamming parallelogram, corners counter-clockwise starting at the
/// mirrored edge-only corner: `[−P₁, Q, P₁, −Q]` (Whitney: `[−P₁, −P₂, P₁, P₂]`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parallelogram {
    /// Corners (F_x/F_z, M/(r F_z)), counter-clockwise.
    pub corners: [Ratio; 4],
    /// Tilt θ (rad) the corners were computed at (0 for Whitney's).
    pub theta: f64,
}

impl Parallelogram {
    /// Edges as (start, end) pairs, counter-clockwise: the mirrored two-point
    /// line, the right side (edge cone limit), the reference two-point line,
    /// the left side.
    pub fn edges(&self) -> [(Ratio, Ratio); 4] {
        [0, 1, 2, 3].map(|i| (self.corners[i], self.corners[(i + 1) % 4]))
    }

    /// Signed distance (in ratio units) from `q` to the nearest edge line:
    /// positive strictly inside, zero on the boundary, negative outside.
    pub fn margin(&self, q: Ratio) -> f64 {
        margin_of(&self.corners, q).0
    }

    /// True when the load ratio `q` is strictly inside: the peg does not jam.
    pub fn avoids_jamming(&self, q: Ratio) -> bool {
        self.margin(q) > 0.0
    }

    /// Slope and intercept of the reference two-point line M/(rF_z) =
    /// slope·F_x/F_z + intercept (the mirrored line has the opposite intercept).
    pub fn two_point_line(&self) -> (f64, f64) {
        let [_, _, p1, p2] = self.corners;
        let slope = (p1[1] - p2[1]) / (p1[0] - p2[0]);
        (slope, p1[1] - slope * p1[0])
    }
}

/// Whitney's small-angle parallelogram at depth `l` (m): corners
/// (−1/μ, −1 − 2λ), (1/μ, 1), (1/μ, 1 + 2λ), (−1/μ, −1), λ = l/(2rμ);
/// two-point lines M/(rF_z) = ±λ + μ(1 + λ) F_x/F_z.
///
/// ```
/// use pegdyn::jamming::{PegHole, diagram::whitney_parallelogram};
/// let p = PegHole::try_new(0.0125, 0.01, 0.25).unwrap();
/// let g = whitney_parallelogram(&p, 0.01).unwrap(); // λ = 1.6
/// let p1 = g.corners[2];
/// assert!((p1[0] - 4.0).abs() < 1e-12 && (p1[1] - 4.2).abs() < 1e-12);
/// let (slope, icpt) = g.two_point_line();
/// assert!((slope - 0.25 * 2.6).abs() < 1e-12 && (icpt - 1.6).abs() < 1e-12);
/// ```
pub fn whitney_parallelogram(p: &PegHole, l: f64) -> Result<Parallelogram, ParamError> {
    let l = PegHole::check_depth(l)?;
    Ok(Parallelogram {
        corners: whitney_corners(p.mu(), p.r(), l),
        theta: 0.0,
    })
}

/// The corners of [`whitney_parallelogram`] of friction `mu` and peg
/// radius `r` (m) at depth `l` (m), at any scalar: the edge-only corner
/// `P₁ = (1/μ, 1 + 2λ)` and the two-point lines' slope `μ (1 + λ)`,
/// `λ = l/(2rμ)`.
pub fn whitney_corners<T: Real>(mu: T, r: T, l: T) -> [[T; 2]; 4] {
    let (one, two) = (T::from_f64(1.0), T::from_f64(2.0));
    let lam = l / (two * r * mu);
    corners_of([one / mu, one + two * lam], mu * (one + lam))
}

/// The exact finite-angle parallelogram at depth `l` (m), tilt from the exact
/// two-point geometry; `Ok(None)` when two-point contact is impossible
/// (l < √(D² − d²)).
pub fn exact_parallelogram(p: &PegHole, l: f64) -> Result<Option<Parallelogram>, ParamError> {
    Ok(two_point_tilt(p, l)?.map(|theta| exact_parallelogram_at_tilt(p, l, theta)))
}

/// Ends of the reference two-point sliding segment at depth `l` (m) and tilt
/// `theta` (rad): `(P₂, P₁)`, tip-only and edge-only.
pub fn two_point_segment(p: &PegHole, l: f64, theta: f64) -> (Ratio, Ratio) {
    segment_of(p.mu(), p.r(), l, theta)
}

/// [`two_point_segment`] of friction `mu` and peg radius `r` (m), at any
/// scalar.
pub fn segment_of<T: Real>(mu: T, r: T, l: T, theta: T) -> ([T; 2], [T; 2]) {
    let one = T::from_f64(1.0);
    let (k1, k2, _) = super::forces::k_factors(mu, theta);
    (
        [-(one / mu), -(k2 / mu)],
        [k1 / k2, (l + mu * r) / (r * k2)],
    )
}

/// The finite-angle parallelogram for a given depth `l` (m) and tilt `theta`
/// (rad), without checking that they are geometrically compatible.
pub fn exact_parallelogram_at_tilt(p: &PegHole, l: f64, theta: f64) -> Parallelogram {
    Parallelogram {
        corners: exact_corners(p.mu(), p.r(), l, theta),
        theta,
    }
}

/// The corners of [`exact_parallelogram_at_tilt`] of friction `mu` and peg
/// radius `r` (m), at any scalar.
pub fn exact_corners<T: Real>(mu: T, r: T, l: T, theta: T) -> [[T; 2]; 4] {
    let (p2, p1) = segment_of(mu, r, l, theta);
    let slope = (p1[1] - p2[1]) / (p1[0] - p2[0]);
    corners_of(p1, slope)
}

/// The corners `[−P₁, Q, P₁, −Q]` from the reference edge-only corner `p1`
/// and the reference two-point line's slope: the right side is the
/// vertical through `p1`, `Q` on the mirrored two-point line through `−P₁`
/// with the same slope.
fn corners_of<T: Real>(p1: [T; 2], slope: T) -> [[T; 2]; 4] {
    let two = T::from_f64(2.0);
    let q = [p1[0], -p1[1] + two * slope * p1[0]];
    [[-p1[0], -p1[1]], q, p1, [-q[0], -q[1]]]
}

/// The signed distances from `q` to the four edge lines of the
/// parallelogram with `corners` (counter-clockwise), at any scalar: edge
/// `i` runs from corner `i` to corner `i + 1`; positive inside.
pub fn edge_distances<T: Real>(corners: &[[T; 2]; 4], q: [T; 2]) -> [T; 4] {
    std::array::from_fn(|i| {
        let (a, b) = (corners[i], corners[(i + 1) % 4]);
        let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
        (ex * (q[1] - a[1]) - ey * (q[0] - a[0])) / ex.hypot(ey)
    })
}

/// The least of [`edge_distances`] (the signed distance to the nearest
/// edge line, positive strictly inside) and the index of its edge (the
/// first of equals).
pub fn margin_of<T: Real>(corners: &[[T; 2]; 4], q: [T; 2]) -> (T, usize) {
    let e = edge_distances(corners, q);
    let k = nearest(&e);
    (e[k], k)
}

/// The index of the least of four edge distances (the first of equals).
pub fn nearest<T: Real>(e: &[T; 4]) -> usize {
    (1..4).fold(0, |k, i| if e[i].to_f64() < e[k].to_f64() { i } else { k })
}

/// A Whitney-frame load ratio `q` = (F_x/F_z, M_tip/(r F_z)) of the
/// reference lean at tilt `theta` (rad), seen in the paper's plane (Fig. 6,
/// Eqs. 75–80): (f₂/f₁, M_C/(r f₁)) with f₁, f₂ along and across the peg and
/// M_C about the centre of mass, `l_c` (m) above the tip; `r` is the peg
/// radius (m). The map is projective (f₁ depends on F_x), so lines stay lines
/// but the parallelogram is not one in the paper's plane.
pub fn to_paper_plane(q: Ratio, r: f64, theta: f64, l_c: f64) -> Ratio {
    let w = super::forces::Wrench {
        fx: q[0],
        fz: 1.0,
        m: q[1] * r,
    };
    let (f1, f2, m_c) = super::forces::to_paper_frame(&w, theta, l_c);
    [f2 / f1, m_c / (r * f1)]
}
