//! Two-point contact geometry of a tilted peg in its hole (Whitney 1982;
//! the paper's Eq. 24 with the contact deformations δ set to zero).
//!
//! Reference configuration ("tilt +"), hole frame: x lateral, z along the
//! hole axis pointing *into* the hole, hole walls at x = 0 and x = D, hole
//! mouth at z = 0. The peg axis is tilted by θ > 0 with its top towards +x;
//! its tip corner touches the wall x = 0 (the *tip contact*) and its side
//! rests on the hole's mouth edge (D, 0) (the *edge contact*). The insertion
//! depth l is measured along the peg axis from the tip face to the edge
//! contact. Closing the loop across the hole gives, exactly,
//!
//! ```text
//! l sin θ + d cos θ = D                                   (paper Eq. 24, δ = 0)
//! ```
//!
//! whose small-angle form is Whitney's θ ≈ cD/l.

use super::error::ParamError;
use super::params::PegHole;
use crate::scalar::Real;

/// Smallest depth at which two-point contact exists: l_min = √(D² − d²) (m).
///
/// Below it the tip corner would be above the hole mouth; at it the corner
/// sits exactly at the mouth (θ = atan(l_min/d)).
pub fn min_two_point_depth(p: &PegHole) -> f64 {
    let (d, big_d) = (p.peg_diameter(), p.hole_diameter());
    ((big_d - d) * (big_d + d)).sqrt()
}

/// Exact tilt θ (rad) of two-point contact at depth `l` (m), the small root of
/// `l sin θ + d cos θ = D`; `Ok(None)` when two-point contact is geometrically
/// impossible (`l < l_min`, too shallow).
///
/// ```
/// use pegdyn::jamming::{PegHole, geometry::two_point_tilt};
/// let p = PegHole::try_new(0.0125, 0.01, 0.3).unwrap();
/// let th = two_point_tilt(&p, 0.005).unwrap().unwrap();
/// let (d, big_d) = (p.peg_diameter(), p.hole_diameter());
/// assert!((0.005 * th.sin() + d * th.cos() - big_d).abs() < 1e-15);
/// assert_eq!(two_point_tilt(&p, 0.001).unwrap(), None); // l_min = 3.55 mm
/// ```
pub fn two_point_tilt(p: &PegHole, l: f64) -> Result<Option<f64>, ParamError> {
    let l = PegHole::check_depth(l)?;
    let (d, big_d) = (p.peg_diameter(), p.hole_diameter());
    if l.hypot(d) < big_d {
        return Ok(None);
    }
    Ok(Some(tilt_of(d, big_d, l)))
}

/// The two-point tilt (rad) of a peg of diameter `d` in a hole of diameter
/// `big_d` at depth `l` (m), at any scalar, unchecked (`√(l² + d²) ≥ D`):
/// `l sin θ + d cos θ = ρ cos(θ − ψ)`, `ψ = atan(l/d)`, so
/// `θ = ψ − acos(D/ρ)`, written as an atan2 difference to keep accuracy
/// when θ is tiny: `θ = atan2(l, d) − atan2(√(ρ² − D²), D)`.
pub fn tilt_of<T: Real>(d: T, big_d: T, l: T) -> T {
    let rho = l.hypot(d);
    let s = ((rho - big_d) * (rho + big_d)).sqrt();
    l.atan2(d) - s.atan2(big_d)
}

/// Whitney's small-angle tilt θ ≈ cD/l (rad) at depth `l` (m).
pub fn small_angle_tilt(p: &PegHole, l: f64) -> f64 {
    p.c() * p.hole_diameter() / l
}

/// Depth (m) at which two-point contact has tilt `theta` (rad), inverse of
/// [`two_point_tilt`]: l = (D − d cos θ)/sin θ.
pub fn depth_at_tilt(p: &PegHole, theta: f64) -> f64 {
    (p.hole_diameter() - p.peg_diameter() * theta.cos()) / theta.sin()
}

/// Contact points of the reference configuration in the hole frame (m):
/// `(tip_contact, edge_contact, tip_centre)` as `[x, z]`.
pub fn contact_points(p: &PegHole, l: f64, theta: f64) -> ([f64; 2], [f64; 2], [f64; 2]) {
    let (r, d, big_d) = (p.r(), p.peg_diameter(), p.hole_diameter());
    let (s, c) = theta.sin_cos();
    let tip_centre = [r * c, l * c - r * s];
    let tip_contact = [0.0, l * c - d * s];
    (tip_contact, [big_d, 0.0], tip_centre)
}
