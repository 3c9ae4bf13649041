//! Contact geometry of a filleted cylindrical peg in a filleted round hole:
//! the principal curvatures at each contact, from which [`crate::hertz`]
//! computes the Hertz stiffness. The derivation is in
//! `docs/contact-geometry.md`.
//!
//! Two kinds of contact occur (each with its mirror image on the other side):
//!
//! - **edge contact** (the paper's A): the peg's cylindrical side (radius `r`)
//!   against the hole's top edge, a torus of tube radius `ρ_h` (the edge
//!   fillet) around the hole's axis;
//! - **wall contact** (the paper's B): the peg's bottom edge, a torus of tube
//!   radius `ρ_p` around the peg's axis, against the hole's wall, a concave
//!   cylinder of radius `D/2`.
//!
//! In both, one principal direction lies in the plane of the tilt (where the
//! fillet's curvature `1/ρ` dominates) and the other runs around the hole,
//! where a convex radius ≈ `r` meets a concave radius `D/2`: the relative
//! curvature there is `≈ 1/r − 2/D = c/(r(1 − c))·…`, tiny, so the contact
//! ellipse is very long around the circumference and the contact is one to
//! two orders of magnitude stiffer than a fillet sphere on a flat.

use crate::hertz::{Curvatures, EllipticityMethod, HertzContact, HertzError, Material};

/// Default fillet radius of the peg's bottom edge and the hole's top edge (m).
pub const DEFAULT_FILLET: f64 = 0.2e-3;

/// Dimensions of the peg and hole that the contact curvatures depend on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PegHoleGeometry {
    /// Hole diameter `D` (m).
    pub hole_diameter: f64,
    /// Peg radius `r` (m), `r < D/2`.
    pub peg_radius: f64,
    /// Fillet radius `ρ_p` of the peg's bottom edge (m).
    pub peg_fillet: f64,
    /// Fillet radius `ρ_h` of the hole's top edge (m).
    pub hole_fillet: f64,
}

fn invalid(field: &str, value: f64, reason: &'static str) -> HertzError {
    HertzError::Invalid {
        field: field.to_owned(),
        value,
        reason,
    }
}

impl PegHoleGeometry {
    /// A checked geometry: all lengths finite and positive, `r < D/2`, each
    /// fillet smaller than the peg radius. Errors name the field
    /// (`hole_diameter`, `peg_radius`, `peg_fillet`, `hole_fillet`).
    pub fn try_new(
        hole_diameter: f64,
        peg_radius: f64,
        peg_fillet: f64,
        hole_fillet: f64,
    ) -> Result<PegHoleGeometry, HertzError> {
        let pos = |f: &str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(v)
            } else {
                Err(invalid(f, v, "must be finite and > 0"))
            }
        };
        pos("hole_diameter", hole_diameter)?;
        pos("peg_radius", peg_radius)?;
        pos("peg_fillet", peg_fillet)?;
        pos("hole_fillet", hole_fillet)?;
        if peg_radius >= 0.5 * hole_diameter {
            return Err(invalid(
                "peg_radius",
                peg_radius,
                "must be smaller than hole_diameter / 2",
            ));
        }
        if peg_fillet >= peg_radius {
            return Err(invalid(
                "peg_fillet",
                peg_fillet,
                "must be smaller than peg_radius",
            ));
        }
        if hole_fillet >= peg_radius {
            return Err(invalid(
                "hole_fillet",
                hole_fillet,
                "must be smaller than peg_radius",
            ));
        }
        Ok(PegHoleGeometry {
            hole_diameter,
            peg_radius,
            peg_fillet,
            hole_fillet,
        })
    }

    /// The clearance ratio `c = (D − 2r)/D`.
    pub fn clearance_ratio(&self) -> f64 {
        (self.hole_diameter - 2.0 * self.peg_radius) / self.hole_diameter
    }

    /// Curvatures at the edge contact (peg side against hole top edge) at
    /// tilt `theta` (rad). Body 1 is the peg, body 2 the hole; index 0 is the
    /// direction in the plane of tilt (along the peg's axis), index 1 the
    /// direction around the hole.
    ///
    /// Peg side: `[0, 1/r]`. Hole edge (torus, centre circle radius
    /// `D/2 + ρ_h`, tube `ρ_h`, normal at `θ` to the horizontal):
    /// `[1/ρ_h, −cos θ / (D/2 + ρ_h (1 − cos θ))]`.
    pub fn edge_curvatures(&self, theta: f64) -> Curvatures {
        let (r, rh, half_d) = (self.peg_radius, self.hole_fillet, 0.5 * self.hole_diameter);
        let ct = theta.cos();
        Curvatures::aligned([0.0, 1.0 / r], [1.0 / rh, -ct / (half_d + rh * (1.0 - ct))])
    }

    /// Curvatures at the wall contact (peg bottom edge against hole wall) at
    /// tilt `theta` (rad); indices as in [`edge_curvatures`](Self::edge_curvatures).
    ///
    /// Peg bottom edge (torus, centre circle radius `r − ρ_p`, tube `ρ_p`,
    /// normal at `θ` to its equatorial plane):
    /// `[1/ρ_p, cos θ / (r − ρ_p (1 − cos θ))]`. Wall: `[0, −2/D]`.
    pub fn wall_curvatures(&self, theta: f64) -> Curvatures {
        let (r, rp) = (self.peg_radius, self.peg_fillet);
        let ct = theta.cos();
        Curvatures::aligned(
            [1.0 / rp, ct / (r - rp * (1.0 - ct))],
            [0.0, -2.0 / self.hole_diameter],
        )
    }

    /// The tilt (rad) at which the wall contact splits in two: where the
    /// peg's bottom edge, seen along the normal, becomes flatter around the
    /// hole than the wall (`cos θ / (r − ρ_p(1 − cos θ)) = 2/D`):
    /// `θ_split = acos((r − ρ_p)/(D/2 − ρ_p)) ≈ √(2c)`.
    pub fn wall_split_tilt(&self) -> f64 {
        let rp = self.peg_fillet;
        ((self.peg_radius - rp) / (0.5 * self.hole_diameter - rp)).acos()
    }
}

/// Hertz contacts of the edge and the wall contact, set up at a reference
/// tilt (their stiffness enters the dynamics as a constant parameter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPair {
    /// Peg side against hole top edge (the paper's A and its mirror).
    pub edge: HertzContact,
    /// Peg bottom edge against hole wall (the paper's B and its mirror).
    pub wall: HertzContact,
}

impl ContactPair {
    /// Sets up both contacts at tilt `theta` (rad) for a peg and hole of the
    /// given materials. Fails if `theta` is at or past the wall contact's
    /// split tilt ([`HertzError::NotPointContact`]).
    pub fn try_new(
        geometry: &PegHoleGeometry,
        peg: &Material,
        hole: &Material,
        theta: f64,
        method: EllipticityMethod,
    ) -> Result<ContactPair, HertzError> {
        Ok(ContactPair {
            edge: HertzContact::try_new(&geometry.edge_curvatures(theta), peg, hole, method)?,
            wall: HertzContact::try_new(&geometry.wall_curvatures(theta), peg, hole, method)?,
        })
    }
}
