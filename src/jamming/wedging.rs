//! Wedging (paper §4.2, Eqs. 81–86; Whitney 1982).
//!
//! A peg in two-point contact is *wedged* when the two contact forces can be
//! equal and opposite along the line joining the contacts, each inside its
//! own friction cone: the peg is then held with no applied load at all.
//!
//! In the peg's frame the edge contact sits at distance l along the axis and
//! d across from the tip contact, and the edge normal is perpendicular to the
//! axis, so the line of contacts makes the angle atan(l/d) with the edge
//! normal *exactly*, at any tilt (paper Eq. 82, tan α_A = l/d). Against the
//! wall normal it makes atan(l/d) − θ, which is smaller. Wedging is therefore
//! possible exactly when
//!
//! ```text
//! l ≤ μ d                                                   (paper Eq. 84; Whitney)
//! ```
//!
//! With the two-point geometry l sin θ + d cos θ = D, the depth l = μd is
//! reached at the critical tilt
//!
//! ```text
//! θ_c = atan μ − acos( D / (d √(1 + μ²)) )                  (paper Eq. 85, δ = 0)
//!     = c/μ + (1 + 2μ²) c² / (2μ³) + O(c³)
//! ```
//!
//! and wedging can occur when the tilt at two-point contact is at least θ_c.
//! The paper's small-clearance form Eq. 86, θ_c = μc, is wrong: the leading
//! term is Whitney's c/μ (see `docs/jamming.md`).

use super::geometry::contact_points;
use super::params::PegHole;

/// Exact critical wedging tilt θ_c (rad), or `None` when wedging is
/// impossible at any tilt (two-point contact cannot be as shallow as l = μd,
/// i.e. (1 − c)² (1 + μ²) < 1).
///
/// ```
/// use pegdyn::jamming::{PegHole, wedging::wedging_angle};
/// let p = PegHole::try_new(0.0125, 0.01, 0.3).unwrap();
/// let th = wedging_angle(&p).unwrap();
/// // at θ_c the two-point depth is exactly μ d
/// let l = pegdyn::jamming::geometry::depth_at_tilt(&p, th);
/// assert!((l - 0.3 * 0.025).abs() < 1e-12);
/// ```
pub fn wedging_angle(p: &PegHole) -> Option<f64> {
    let mu = p.mu();
    let x = p.hole_diameter() / (p.peg_diameter() * mu.hypot(1.0));
    if x > 1.0 {
        return None;
    }
    // acos(x) = atan2(√(1 − x²), x), accurate for x near 1.
    let s = ((1.0 - x) * (1.0 + x)).sqrt();
    Some(mu.atan() - s.atan2(x))
}

/// Two-term small-clearance series of θ_c: c/μ + (1 + 2μ²) c²/(2μ³).
pub fn wedging_angle_series(p: &PegHole) -> f64 {
    let (c, mu) = (p.c(), p.mu());
    c / mu + (1.0 + 2.0 * mu * mu) * c * c / (2.0 * mu.powi(3))
}

/// Whitney's small-clearance wedging angle c/μ.
pub fn wedging_angle_whitney(p: &PegHole) -> f64 {
    p.c() / p.mu()
}

/// The paper's Eq. 86 as printed, μc (wrong; kept for the comparison).
pub fn wedging_angle_paper_eq86(p: &PegHole) -> f64 {
    p.mu() * p.c()
}

/// Friction-cone margins (rad) of a self-equilibrated, compressive pair of
/// contact forces along the line of the two contacts at depth `l` (m) and
/// tilt `theta` (rad): `(α − angle at the tip contact, α − angle at the edge
/// contact)`, α = atan μ. Wedging is possible when both are ≥ 0.
///
/// Computed from the contact points and normals directly (not from l/d), so
/// it independently checks [`wedging_angle`].
pub fn wedge_cone_margins(p: &PegHole, l: f64, theta: f64) -> (f64, f64) {
    let alpha = p.mu().atan();
    let (tip, edge, _) = contact_points(p, l, theta);
    let ab = [edge[0] - tip[0], edge[1] - tip[1]];
    // inward normals (forces on the peg): wall +x; edge −(cosθ, sinθ)
    let n_tip = [1.0, 0.0];
    let n_edge = [-theta.cos(), -theta.sin()];
    let angle = |v: [f64; 2], n: [f64; 2]| {
        let cross = v[0] * n[1] - v[1] * n[0];
        let dot = v[0] * n[0] + v[1] * n[1];
        cross.abs().atan2(dot)
    };
    // force on the peg at the tip points towards the edge, and vice versa
    (
        alpha - angle(ab, n_tip),
        alpha - angle([-ab[0], -ab[1]], n_edge),
    )
}

/// True when a peg in two-point contact at depth `l` (m) can wedge: l ≤ μd.
pub fn can_wedge_at_depth(p: &PegHole, l: f64) -> bool {
    l <= p.mu() * p.peg_diameter()
}
