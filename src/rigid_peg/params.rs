//! Parameters and loads of the rigid three-point peg leaning on the hole edge.
//!
//! All quantities in SI units (m, kg, s, N, N·m, rad).

use crate::generated::rigid_peg as generated;
use crate::rigid_peg::RigidError;

/// Dimensions, mass and friction of the peg and the hole.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PegParams {
    /// Hole diameter `D` (m).
    pub hole_diameter: f64,
    /// Peg diameter `d` (m), `d < D`.
    pub peg_diameter: f64,
    /// Peg height `H` (m).
    pub height: f64,
    /// Peg mass `m` (kg).
    pub mass: f64,
    /// Gravitational acceleration `g` (m/s²), acting along −z.
    pub gravity: f64,
    /// Coulomb friction coefficient `f` (same at K, B1, B2).
    pub friction: f64,
}

/// Applied loads: the generalized moments and the assembly force at the
/// centre of mass (paper's `M_γ`, `M_ψ`, `F^as`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Loads {
    /// Generalized force conjugate to γ (N·m); positive drives γ up.
    pub m_gamma: f64,
    /// Generalized force conjugate to ψ (N·m): moment about +z (the hole axis).
    pub m_psi: f64,
    /// Assembly force at the centre of mass, fixed-frame components (N).
    pub force: [f64; 3],
}

impl PegParams {
    /// The paper's Fig. 9 peg: D = 50 mm, d = 49.95 mm, H = 70 mm, m = 1 kg,
    /// g = 9.81 m/s², f = 0.2.
    pub fn fig9() -> PegParams {
        PegParams {
            hole_diameter: 0.050,
            peg_diameter: 0.04995,
            height: 0.070,
            mass: 1.0,
            gravity: 9.81,
            friction: 0.2,
        }
    }

    /// Checks that the parameters describe a peg that can lean on the hole
    /// edge at three points: `0 < d < D`, `H > 0`, `m > 0`, `g ≥ 0`, `f ≥ 0`,
    /// all finite.
    pub fn validate(&self) -> Result<(), RigidError> {
        let checks: [(&'static str, f64, bool, &'static str); 6] = [
            (
                "hole_diameter",
                self.hole_diameter,
                self.hole_diameter > 0.0,
                "must be > 0",
            ),
            (
                "peg_diameter",
                self.peg_diameter,
                self.peg_diameter > 0.0,
                "must be > 0",
            ),
            ("height", self.height, self.height > 0.0, "must be > 0"),
            ("mass", self.mass, self.mass > 0.0, "must be > 0"),
            ("gravity", self.gravity, self.gravity >= 0.0, "must be >= 0"),
            (
                "friction",
                self.friction,
                self.friction >= 0.0,
                "must be >= 0",
            ),
        ];
        for (field, value, ok, reason) in checks {
            if !value.is_finite() || !ok {
                return Err(RigidError::Param {
                    field,
                    value,
                    reason,
                });
            }
        }
        if self.peg_diameter >= self.hole_diameter {
            return Err(RigidError::Param {
                field: "peg_diameter",
                value: self.peg_diameter,
                reason: "must be smaller than hole_diameter (a peg with d >= D cannot enter the hole)",
            });
        }
        Ok(())
    }

    /// γ0 = arccos(d/D) (rad), where B1 and B2 merge and three-point contact
    /// ends. Computed as 2·asin(√((D − d)/(2D))), which keeps full relative
    /// accuracy for a small clearance (acos near 1 loses it).
    pub fn gamma0(&self) -> f64 {
        let (dh, dp) = (self.hole_diameter, self.peg_diameter);
        2.0 * ((dh - dp) / (2.0 * dh)).sqrt().asin()
    }

    /// Peg radius r = d/2 (m).
    pub fn radius(&self) -> f64 {
        0.5 * self.peg_diameter
    }

    /// Transverse central moment of inertia I_ε = m(3r² + H²)/12 (kg·m²).
    pub fn inertia_transverse(&self) -> f64 {
        let r = self.radius();
        self.mass * (3.0 * r * r + self.height * self.height) / 12.0
    }

    /// Axial central moment of inertia I_ζ = m r²/2 (kg·m²).
    pub fn inertia_axial(&self) -> f64 {
        let r = self.radius();
        0.5 * self.mass * r * r
    }

    /// The parameter vector the generated functions take
    /// ([`generated::Params`], γ0 from [`PegParams::gamma0`]).
    pub fn to_vector(&self) -> nalgebra::SVector<f64, 7> {
        generated::Params::from(self).into()
    }
}

impl Loads {
    /// The load vector the generated 2-DOF functions take
    /// ([`generated::Loads`]).
    pub fn to_vector(&self) -> nalgebra::SVector<f64, 5> {
        generated::Loads::from(self).into()
    }
}

impl From<&PegParams> for generated::Params<f64> {
    /// The generated model's parameters, with γ0 = arccos(d/D) computed
    /// once here ([`PegParams::gamma0`]; the generated code trusts it).
    fn from(p: &PegParams) -> Self {
        generated::Params {
            D_hole: p.hole_diameter,
            d_peg: p.peg_diameter,
            H: p.height,
            m: p.mass,
            g: p.gravity,
            f: p.friction,
            gamma0: p.gamma0(),
        }
    }
}

impl From<&Loads> for generated::Loads<f64> {
    /// The loads of the 2-DOF variants: both moments and the fixed-frame
    /// force.
    fn from(l: &Loads) -> Self {
        let [fx, fy, fz] = l.force;
        generated::Loads {
            M_gamma: l.m_gamma,
            M_psi: l.m_psi,
            F_x: fx,
            F_y: fy,
            F_z: fz,
        }
    }
}
