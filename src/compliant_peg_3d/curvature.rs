//! Principal curvatures at a contact point of the compliant 3-D peg, for
//! Hertz's elliptical contact ([`crate::hertz::Curvatures`], convex > 0).
//!
//! A torus is a surface of revolution: at a point with outward normal `N`
//! at distance `ρ` from its axis, with `ê_ρ` the outward radial unit vector,
//! its principal curvatures are `1/ρ_t` (`ρ_t` the tube radius) along the
//! meridian and `(N·ê_ρ)/ρ` along the parallel (Meusnier), whose direction
//! is `ê_θ = axis × ê_ρ`. The mouth fillet turns about the hole's axis `e_z`,
//! the rim fillet about the peg's axis `a`. The peg's side is a convex
//! cylinder `(1/r, 0)`, the bore wall a concave one `(−1/R, 0)` (zero
//! curvature along the cylinder's axis), the top face and the bore bottom are
//! flat. The angle `ω` of [`Curvatures`] is the angle between the direction
//! of body 1's first curvature and that of body 2's first curvature.

use super::params::Peg3dParams;
use super::search::{ContactPoint, Pair};
use crate::hertz::Curvatures;
use nalgebra::Vector3;

/// `(κ_parallel, κ_meridian, ê_θ)` of a torus turning about the axis through
/// `origin` along `axis`, at surface point `x` with outward normal `n`.
fn torus(
    origin: &Vector3<f64>,
    axis: &Vector3<f64>,
    x: &Vector3<f64>,
    n: &Vector3<f64>,
    tube: f64,
) -> (f64, f64, Vector3<f64>) {
    let rel = x - origin;
    let radial = rel - axis * rel.dot(axis);
    let rho = radial.norm();
    let e_rho = radial / rho;
    (n.dot(&e_rho) / rho, 1.0 / tube, axis.cross(&e_rho))
}

fn angle_between(t: &Vector3<f64>, u: &Vector3<f64>) -> f64 {
    let c = (t.dot(u) / (t.norm() * u.norm())).abs().min(1.0);
    c.acos()
}

/// Body 1 is the hole (mouth fillet) for [`Pair::EdgeSide`] and the peg
/// (rim fillet) for the others; `centre` and `axis` are the peg's centre of
/// mass and axis.
pub fn at(
    prm: &Peg3dParams,
    c: &ContactPoint,
    centre: &Vector3<f64>,
    axis: &Vector3<f64>,
) -> Curvatures {
    let ez = Vector3::z();
    match c.pair {
        Pair::EdgeSide => {
            // The mouth fillet's surface point, half the penetration from
            // the midway contact point along the force direction on the peg
            // (the fillet's outward normal there).
            let n = c.normal;
            let surface = c.point + n * (0.5 * c.penetration);
            let (kp, km, t) = torus(&Vector3::zeros(), &ez, &surface, &n, prm.mouth_fillet);
            Curvatures {
                body1: [kp, km],
                body2: [0.0, 1.0 / prm.peg_radius()],
                angle: angle_between(&t, axis),
            }
        }
        Pair::RimEdge => {
            // Rim fillet (body 1, outward normal −n) against the mouth
            // fillet (body 2, outward normal n), each surface point half
            // the penetration from the midway point.
            let n = c.normal;
            let rim = c.point - n * (0.5 * c.penetration);
            let mouth = c.point + n * (0.5 * c.penetration);
            let (kp1, km1, t1) = torus(centre, axis, &rim, &(-n), prm.rim_fillet);
            let (kp2, km2, t2) = torus(&Vector3::zeros(), &ez, &mouth, &n, prm.mouth_fillet);
            Curvatures {
                body1: [kp1, km1],
                body2: [kp2, km2],
                angle: angle_between(&t1, &t2),
            }
        }
        Pair::RimWall | Pair::RimTop | Pair::RimBottom => {
            let n = -c.normal;
            let surface = c.point + n * (0.5 * c.penetration);
            let (kp, km, t) = torus(centre, axis, &surface, &n, prm.rim_fillet);
            let body2 = if c.pair == Pair::RimWall {
                [0.0, -1.0 / prm.bore_radius()]
            } else {
                [0.0, 0.0]
            };
            Curvatures {
                body1: [kp, km],
                body2,
                angle: angle_between(&t, &ez),
            }
        }
    }
}
