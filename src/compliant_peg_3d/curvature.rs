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

use super::contact::{ContactPoint, Pair};
use super::frame::{V3, add, cross, dot, scale, sub};
use super::params::Peg3dParams;
use crate::hertz::Curvatures;
use crate::scalar::Real;
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

/// [`torus`] in any [`Real`] scalar: `(κ_parallel, κ_meridian, ê_θ)`, with
/// `ê_θ = axis × ê_ρ` left unnormalized (`|ê_θ| = |axis|`).
fn torus_generic<T: Real>(
    origin: &V3<T>,
    axis: &V3<T>,
    x: &V3<T>,
    n: &V3<T>,
    tube: f64,
) -> (T, T, V3<T>) {
    let rel = sub(x, origin);
    let radial = sub(&rel, &scale(axis, dot(&rel, axis)));
    let rho = dot(&radial, &radial).sqrt();
    let e_rho = scale(&radial, T::from_f64(1.0) / rho);
    (
        dot(n, &e_rho) / rho,
        T::from_f64(1.0 / tube),
        cross(axis, &e_rho),
    )
}

/// `cos 2ω = 2 (t·u)² / (|t|² |u|²) − 1` of the angle `ω` between two
/// directions (smooth where `ω` itself, through `acos`, is not: at 0).
fn cos_twice<T: Real>(t: &V3<T>, u: &V3<T>) -> T {
    let c = dot(t, u);
    T::from_f64(2.0) * c * c / (dot(t, t) * dot(u, u)) - T::from_f64(1.0)
}

/// The relative curvatures `(A, B)` (1/m) of the contact of [`at`] in any
/// [`Real`] scalar, from the same surfaces and points: `point`, `normal`,
/// `penetration` of the contact, `centre` and `axis` of the peg, and
///
/// ```text
/// A + B = ½ Σκ,   B − A = ½ √((κ₁₁ − κ₁₂)² + (κ₂₁ − κ₂₂)² + 2(κ₁₁ − κ₁₂)(κ₂₁ − κ₂₂) cos 2ω)
/// ```
///
/// ([`crate::hertz::Curvatures::relative`], written with `cos 2ω` of the
/// two directions so that dual numbers carry its derivative through
/// `ω = 0`). Evaluated at dual numbers of the pose, it gives the exact
/// derivatives of `A` and `B` (`super::stiffness`). Where the radicand
/// vanishes (a circular contact) `B − A` is held at zero (its derivative
/// is not defined there).
pub fn relative<T: Real>(
    prm: &Peg3dParams,
    pair: Pair,
    point: &V3<T>,
    normal: &V3<T>,
    penetration: T,
    centre: &V3<T>,
    axis: &V3<T>,
) -> (T, T) {
    let c = T::from_f64;
    let zero = [c(0.0), c(0.0), c(0.0)];
    let ez = [c(0.0), c(0.0), c(1.0)];
    let half = penetration * c(0.5);
    let (k1, k2, cos2) = match pair {
        Pair::EdgeSide => {
            let surface = add(point, &scale(normal, half));
            let (kp, km, t) = torus_generic(&zero, &ez, &surface, normal, prm.mouth_fillet);
            (
                [kp, km],
                [c(0.0), c(1.0 / prm.peg_radius())],
                cos_twice(&t, axis),
            )
        }
        Pair::RimEdge => {
            let out = scale(normal, c(-1.0));
            let rim = add(point, &scale(&out, half));
            let mouth = add(point, &scale(normal, half));
            let (kp1, km1, t1) = torus_generic(centre, axis, &rim, &out, prm.rim_fillet);
            let (kp2, km2, t2) = torus_generic(&zero, &ez, &mouth, normal, prm.mouth_fillet);
            ([kp1, km1], [kp2, km2], cos_twice(&t1, &t2))
        }
        Pair::RimWall | Pair::RimTop | Pair::RimBottom => {
            let out = scale(normal, c(-1.0));
            let surface = add(point, &scale(&out, half));
            let (kp, km, t) = torus_generic(centre, axis, &surface, &out, prm.rim_fillet);
            let body2 = if pair == Pair::RimWall {
                [c(0.0), c(-1.0 / prm.bore_radius())]
            } else {
                [c(0.0), c(0.0)]
            };
            ([kp, km], body2, cos_twice(&t, &ez))
        }
    };
    let (d1, d2) = (k1[0] - k1[1], k2[0] - k2[1]);
    let half_sum = (k1[0] + k1[1] + k2[0] + k2[1]) * c(0.25);
    let radicand = d1 * d1 + d2 * d2 + c(2.0) * d1 * d2 * cos2;
    let half_diff = if radicand.to_f64() > 0.0 {
        radicand.sqrt() * c(0.25)
    } else {
        c(0.0)
    };
    (half_sum - half_diff, half_sum + half_diff)
}
