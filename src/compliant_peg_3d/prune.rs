//! Which contact pairs can touch at a pose: cheap bounds, evaluated before
//! a pair's scan of the edge circle, so that a pose pays only for the pairs
//! it can meet (a peg inside the bore scans neither the top face nor, far
//! from it, the bore bottom; a peg above the block scans only the top face
//! and the mouth).
//!
//! The rim's tube-centre circle is `c(β) = c_r + (r−ρ_p)(cos β e₁ + sin β
//! e₂)` with centre `c_r = p + (ρ_p − L/2) a` and the body axes `e₁`, `e₂`,
//! `a` in the hole frame. Its height lies in `c_r,z ± (r−ρ_p) s`,
//! `s = √(1 − a_z²)` (since `e₁,z² + e₂,z² = 1 − a_z²`), its distance from
//! the hole's axis is at most `|c_r,xy| + (r−ρ_p)`, and its distance from
//! any point differs from `c_r`'s by at most `r−ρ_p` (the distance is
//! 1-Lipschitz). A pair is skipped when one of these bounds shows that
//! every point of its circle is either apart (`g > 0`) or outside the part
//! of the surfaces that exists ([`Pair::valid`]); the contacts found are
//! then exactly those of a full scan.

use super::contact::{Pair, axis_of};
use super::params::Peg3dParams;
use nalgebra::{SVector, Vector3};

/// Whether `pair` can have a valid penetrating contact at pose `x` (unit
/// quaternion); `false` only when a bound excludes it.
pub fn can_touch(pair: Pair, prm: &Peg3dParams, x: &SVector<f64, 7>) -> bool {
    let a = axis_of(x);
    let p = Vector3::new(x[0], x[1], x[2]);
    let rr = prm.peg_radius() - prm.rim_fillet;
    let (rho_p, rho_h) = (prm.rim_fillet, prm.mouth_fillet);
    let s = (1.0 - a.z * a.z).max(0.0).sqrt();
    let cr = p + a * (rho_p - 0.5 * prm.length);
    let low = cr.z - rr * s;
    let out = cr.xy().norm() + rr;
    match pair {
        // Gap c_z − ρ_p ≥ low − ρ_p; a point on the face needs radius ≥ R + ρ_h.
        Pair::RimTop => low - rho_p <= 0.0 && out >= prm.bore_radius() + rho_h,
        // Gap c_z − ρ_p + h_b.
        Pair::RimBottom => low - rho_p + prm.bore_depth <= 0.0,
        // Gap R − ρ_p − ρ_c ≥ R − ρ_p − out; the wall needs c_z ≤ −ρ_h.
        Pair::RimWall => prm.bore_radius() - rho_p - out <= 0.0 && low <= -rho_h,
        // Gap ≥ |c_r − mouth circle| − (r−ρ_p) − ρ_p − ρ_h.
        Pair::RimEdge => {
            let dr = cr.xy().norm() - prm.bore_radius() - rho_h;
            let dz = cr.z + rho_h;
            dr.hypot(dz) - rr - rho_p - rho_h <= 0.0
        }
        // The mouth fillet lies in z ≤ 0: a peg whose lowest point (on the
        // bottom face's circle of radius r) is more than ρ_h above the top
        // face meets it, if at all, below its bottom (an invalid point).
        // And the distance from the mouth circle to the axis is at least
        // the distance of the circle's centre (0, 0, −ρ_h) from the axis
        // less R + ρ_h.
        // A valid contact point lies at or above the mouth's tube circle
        // (`z ≥ −ρ_h`: `n_z ≥ 0`) and on the peg's side within half a
        // penetration (below ρ_h), so a peg whose highest point is below
        // `−2ρ_h` (deep in the bore) cannot meet it either.
        Pair::EdgeSide => {
            let peg_high = p.z + 0.5 * prm.length * a.z.abs() + prm.peg_radius() * s;
            if peg_high < -2.0 * rho_h {
                return false;
            }
            let peg_low = p.z - 0.5 * prm.length * a.z.abs() - prm.peg_radius() * s;
            let o = Vector3::new(0.0, 0.0, -rho_h) - p;
            let to_axis = (o - a * o.dot(&a)).norm();
            let gap_low = to_axis - prm.bore_radius() - rho_h - prm.peg_radius() - rho_h;
            peg_low <= rho_h && gap_low <= 0.0
        }
    }
}

/// Whether the distributed ring of a plane pair ([`super::face`]) applies
/// at pose `x`: the tilt below the hand-over window's end (checked first,
/// so a tilted peg pays one product), the peg upright and its rim circle
/// over the flat's existing part, and its lowest rim point within the
/// flat's reach (`c_r,z − ϱ sin γ − ρ_p ≤ z₀`).
pub fn ring_applies(pair: Pair, prm: &Peg3dParams, x: &SVector<f64, 7>) -> bool {
    let Some(z0) = super::face::plane(pair, prm) else {
        return false;
    };
    if !super::face::applies(pair, prm, x) {
        return false;
    }
    let a = axis_of(x);
    let rr = prm.peg_radius() - prm.rim_fillet;
    let s = (1.0 - a.z * a.z).max(0.0).sqrt();
    let low = x[2] + a.z * (prm.rim_fillet - 0.5 * prm.length) - rr * s;
    low - prm.rim_fillet <= z0
}
