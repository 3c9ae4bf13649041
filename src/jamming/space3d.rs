//! Three-dimensional no-jamming space (paper §4.1.2, Eqs. 81–82, Figs. 7–8).
//!
//! The applied force is given in spherical form (F, β, γ): magnitude F (N),
//! angle β from the insertion direction (+z, into the hole) and azimuth γ of
//! its lateral part from the x axis; the applied moment (M_x, M_y, M_z) is
//! taken about the peg tip (N·m), right-handed (x, y, z).
//!
//! For a round peg the two-point contacts lie in the tilt plane, spanned by
//! the lateral unit vector e_φ and z. In that plane the planar diagram holds
//! with F_x = F_lat·e_φ and planar moment τ = −M·(z × e_φ), so with
//!
//! ```text
//! a = F_lat / F_z = tan β (cos γ, sin γ),     m = (−M_y, M_x) / (r F_z)
//! q(φ) = (a·e_φ, m·e_φ)
//! ```
//!
//! Writing the (centrally symmetric) parallelogram as |u₁·q| < 1, |u₂·q| < 1,
//! the load avoids jamming for *every* tilt azimuth φ iff
//!
//! ```text
//! F_z > 0,   ‖u₁ₓ a + u₁ₘ m‖ < 1,   ‖u₂ₓ a + u₂ₘ m‖ < 1
//! ```
//!
//! (the supremum over φ of |w·e_φ| is ‖w‖). M_z is not constrained for a
//! rotationally symmetric peg (paper: "the limitation of z directional moment
//! can be ignored"). [`resultant`] evaluates Eqs. 81–82 for any contacts, which
//! tests use to check these inequalities against vector equilibrium.

use nalgebra::Vector3;

use super::diagram::{Parallelogram, Ratio};
use super::error::{ParamError, check};

/// Applied force in spherical form (paper Fig. 7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphericalForce {
    f: f64,
    beta: f64,
    gamma: f64,
}

impl SphericalForce {
    /// Check and build: `F ≥ 0` (N), `0 ≤ β ≤ π`, γ finite (rad).
    pub fn try_new(f: f64, beta: f64, gamma: f64) -> Result<Self, ParamError> {
        let f = check("F", f, |v| v >= 0.0, "force magnitude must be >= 0 (N)")?;
        let beta = check(
            "beta",
            beta,
            |v| (0.0..=std::f64::consts::PI).contains(&v),
            "polar angle from the insertion axis must lie in [0, pi]",
        )?;
        let gamma = check("gamma", gamma, |_| true, "")?;
        Ok(Self { f, beta, gamma })
    }

    /// Cartesian components (N), z into the hole.
    pub fn vector(&self) -> Vector3<f64> {
        let (sb, cb) = self.beta.sin_cos();
        let (sg, cg) = self.gamma.sin_cos();
        self.f * Vector3::new(sb * cg, sb * sg, cb)
    }

    /// From Cartesian components (N); `None` for a zero or non-finite vector.
    pub fn from_vector(v: &Vector3<f64>) -> Option<Self> {
        let f = v.norm();
        (f > 0.0 && f.is_finite()).then(|| Self {
            f,
            beta: (v.z / f).clamp(-1.0, 1.0).acos(),
            gamma: v.y.atan2(v.x),
        })
    }
}

/// The no-jamming set of one parallelogram as rotation-invariant inequalities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NoJamSpace {
    /// Covectors u₁ (two-point lines) and u₂ (one-point sides).
    pub u: [Ratio; 2],
    /// Peg radius r (m) used to scale moments.
    pub r: f64,
}

fn covector_through(a: Ratio, b: Ratio) -> Ratio {
    // u·a = 1, u·b = 1
    let det = a[0] * b[1] - a[1] * b[0];
    [(b[1] - a[1]) / det, (a[0] - b[0]) / det]
}

impl NoJamSpace {
    /// From a planar parallelogram (corners `[−P₁, Q, P₁, −Q]`) and the peg
    /// radius `r` (m).
    pub fn new(par: &Parallelogram, r: f64) -> Self {
        let [_, m2, p1, p2] = par.corners;
        Self {
            u: [covector_through(p1, p2), covector_through(m2, p1)],
            r,
        }
    }

    fn ratios(&self, f: &SphericalForce, m: &Vector3<f64>) -> Option<(Ratio, Ratio)> {
        let v = f.vector();
        (v.z > 0.0).then(|| {
            let a = [v.x / v.z, v.y / v.z];
            let mm = [-m.y / (self.r * v.z), m.x / (self.r * v.z)];
            (a, mm)
        })
    }

    /// The two inequality values ‖uₓ a + uₘ m‖ (each must be < 1), or `None`
    /// when F_z ≤ 0 (not an insertion force).
    pub fn values(&self, f: &SphericalForce, m: &Vector3<f64>) -> Option<[f64; 2]> {
        let (a, mm) = self.ratios(f, m)?;
        Some(
            self.u
                .map(|u| (u[0] * a[0] + u[1] * mm[0]).hypot(u[0] * a[1] + u[1] * mm[1])),
        )
    }

    /// True when the load avoids jamming whatever the tilt azimuth.
    pub fn avoids_jamming(&self, f: &SphericalForce, m: &Vector3<f64>) -> bool {
        self.values(f, m).is_some_and(|v| v[0] < 1.0 && v[1] < 1.0)
    }

    /// The planar diagram point q(φ) for a known tilt azimuth `phi` (rad), or
    /// `None` when F_z ≤ 0.
    pub fn in_plane(&self, f: &SphericalForce, m: &Vector3<f64>, phi: f64) -> Option<Ratio> {
        let (a, mm) = self.ratios(f, m)?;
        let (s, c) = phi.sin_cos();
        Some([a[0] * c + a[1] * s, mm[0] * c + mm[1] * s])
    }
}

/// One contact of Eqs. 81–82: position `at` relative to the tip (m), unit
/// inward normal, unit velocity of the peg relative to the hole there, and
/// the normal force magnitude `f` (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact3 {
    /// Contact point relative to the peg tip (m).
    pub at: Vector3<f64>,
    /// Unit normal pushing on the peg.
    pub normal: Vector3<f64>,
    /// Unit sliding velocity of the peg at the contact.
    pub velocity: Vector3<f64>,
    /// Normal force (N).
    pub f: f64,
}

/// Resultant force and moment about the tip (Eqs. 82 and 81):
/// ΣF = F_ext + Σ(fᵢnᵢ − μfᵢvᵢ), ΣM = M_ext + Σ Rᵢ × (fᵢnᵢ − μfᵢvᵢ).
pub fn resultant(
    mu: f64,
    contacts: &[Contact3],
    f_ext: &Vector3<f64>,
    m_ext: &Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    contacts.iter().fold((*f_ext, *m_ext), |(sf, sm), k| {
        let force = k.f * (k.normal - mu * k.velocity);
        (sf + force, sm + k.at.cross(&force))
    })
}
