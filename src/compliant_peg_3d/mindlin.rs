//! The elastic tangential law of the compliant 3-D peg's contacts:
//! Mindlin's tangential stiffness, a tangential displacement `ξ` (m, a
//! 3-vector in the hole frame) per tracked contact, a Dahl rate law that
//! caps the spring force by Coulomb, and a damper on the stick motion.
//!
//! **Stiffness.** A circular Hertz contact of radius `a` has the normal
//! stiffness `k_n = dQ/dδ = 2 E* a` and, under a tangential load below
//! the slip limit, Mindlin's tangential stiffness `k_t = 8 G* a` (R. D.
//! Mindlin, "Compliance of elastic bodies in contact", *J. Appl. Mech.*
//! 16, 1949; K. L. Johnson, *Contact Mechanics*, 1985, ch. 7: tangential
//! loading of a circular contact), with
//!
//! ```text
//! 1/E* = Σ (1 − νᵢ²)/Eᵢ,   1/G* = Σ (2 − νᵢ)/Gᵢ,   Gᵢ = Eᵢ/(2(1 + νᵢ))
//! k_t = β k_n,   β = 4 G*/E*   (0.82 for steel on steel: 2(1 − ν)/(2 − ν))
//! ```
//!
//! The contact's radius is the circle of the same normal stiffness, so
//! `k_t` follows from the contact's own law without its ellipse:
//!
//! - a Hertz point `Q_e = s k δ^{3/2}`: `k_n = (3/2) s k δ^{1/2}`, i.e.
//!   `a = 3 k δ^{1/2}/(4 E*)` (exact for a circle, the equivalent radius of
//!   an ellipse), `k_t = (3/2) β s k δ^{1/2}`;
//! - the ring of the peg's bottom on a flat ([`super::face`]), a flat
//!   punch in full contact: `k_n = (1 − s) 2π ϱ k_ℓ` (with `k_ℓ = E*/π`
//!   the punch's `2 E* ϱ`), `k_t = β k_n` (the punch's `8 G* ϱ`), constant.
//!
//! **Cap.** The spring carries at most `μ Q_e`: the slip displacement is
//! `ξ_max = μ Q_e / k_t` (`(2μ/(3β)) δ` at a point). With `ξ_t = ξ − (n·ξ) n`
//! the tangential part, `v_t` the material point's tangential velocity,
//! `δ̇ = −n·v_c`, `e` the exponent of `k_t ∝ δ^e` (½ at a point, 0 on the
//! ring):
//!
//! ```text
//! ξ̇     = v_t − r ξ,   r = (|v_t| + |u|² max(−ξ̇_max, 0)) / ξ_max,   u = ξ_t/ξ_max
//! ξ̇_max = (μ/β − e ξ_max/δ) δ̇
//! F_t   = −k_t ξ_t − η (v_t − r ξ_t),   η = τ_t k_t
//! P     = ½ (∂k_t/∂δ) |ξ_t|² = e k_t |ξ_t|² / (2δ)     (along n)
//! E_t   = ½ k_t |ξ_t|²
//! Ṡ_t   = k_t r |ξ_t|² + η (v_t − r ξ_t)·v_t
//! ```
//!
//! Dahl's rate law (P. R. Dahl, "A solid friction model", 1968) in three
//! dimensions: at rest (`v_t = 0`) nothing changes, so a stuck contact
//! holds without creep; in steady sliding `ξ_t → ξ_max v_t/|v_t|` and the
//! spring force is `μ Q_e` against the slip; the unloading term scales the
//! displacement back to the cone as `ξ_max` shrinks, so `|u| ≤ 1`. The
//! normal part of `ξ` (the tangent plane turns with a curved contact) decays
//! at the same rate `r` and carries no force. `P` is the normal force of the
//! stored energy's growth with the depth (`E_t` at fixed `ξ`), which makes
//! `T + V + E_t − W + S` constant along solutions (exactly with a fixed
//! normal and a stiffness that does not vary with the pose otherwise: the
//! ring and points with a fixed Hertz stiffness outside the hand-over
//! window). A tracked contact that is not touching relaxes its displacement
//! to zero, `ξ̇ = −ξ/τ_d` ([`DROP_TIME`]).

use super::frame::{V3, dot, scale, sub};
use super::params::Peg3dParams;
use crate::hertz::{Material, contact_modulus};

/// Relaxation time `τ_d` (s) of the displacement of a tracked contact that
/// is not touching: its displacement is dropped within microseconds of the
/// separation (where the cap has already brought it to zero).
pub const DROP_TIME: f64 = 1e-6;

/// Shear modulus `G = E/(2(1 + ν))` (Pa).
pub fn shear_modulus(m: &Material) -> f64 {
    m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio))
}

/// Mindlin's tangential contact modulus `G* = [Σ (2 − νᵢ)/Gᵢ]⁻¹` (Pa).
pub fn tangential_modulus(a: &Material, b: &Material) -> f64 {
    1.0 / ((2.0 - a.poisson_ratio) / shear_modulus(a) + (2.0 - b.poisson_ratio) / shear_modulus(b))
}

/// The coefficients of the tangential law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mindlin {
    /// Ratio `β = 4 G*/E*` of the tangential to the normal stiffness.
    pub ratio: f64,
    /// Coulomb friction coefficient `μ`.
    pub friction: f64,
    /// Damping time `τ_t` (s) of the stick motion.
    pub damping_time: f64,
}

impl Mindlin {
    /// The coefficients of `prm`.
    pub fn of(prm: &Peg3dParams) -> Mindlin {
        let (a, b) = (&prm.peg_material, &prm.hole_material);
        Mindlin {
            ratio: 4.0 * tangential_modulus(a, b) / contact_modulus(a, b),
            friction: prm.friction,
            damping_time: prm.tangential_damping,
        }
    }
}

/// What the tangential law needs of a touching contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Touch {
    /// Unit force direction `n` on the peg, hole frame.
    pub normal: V3<f64>,
    /// Material point's velocity `v_c` (m/s).
    pub velocity: V3<f64>,
    /// Elastic normal force `Q_e` (N).
    pub elastic: f64,
    /// Normal stiffness `k_n` (N/m).
    pub normal_stiffness: f64,
    /// Exponent `e` of `k_t ∝ δ^e`: ½ at a Hertz point, 0 on the ring.
    pub exponent: f64,
    /// Penetration `δ` (m).
    pub penetration: f64,
}

/// What the tangential law gives at one tracked contact.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Spring {
    /// Friction force `F_t` on the peg, hole frame (N).
    pub force: V3<f64>,
    /// Normal force `P` of the stored energy (N), along `n`.
    pub normal: f64,
    /// Rate `ξ̇` of the displacement (m/s).
    pub rate: V3<f64>,
    /// Stored energy `E_t` (J).
    pub energy: f64,
    /// Dissipated power `Ṡ_t` (W).
    pub dissipation: f64,
    /// Tangential stiffness `k_t` (N/m).
    pub stiffness: f64,
    /// Slip displacement `ξ_max` (m).
    pub slip: f64,
}

/// The law of the module documentation at displacement `xi` of a tracked
/// contact `touch`, or [`dropped`] if the contact carries no load.
pub fn spring(law: &Mindlin, touch: &Touch, xi: &V3<f64>) -> Spring {
    let kt = law.ratio * touch.normal_stiffness;
    let xmax = law.friction * touch.elastic / kt;
    if !(touch.elastic > 0.0 && kt > 0.0 && xmax > 0.0 && xmax.is_finite()) {
        return dropped(xi);
    }
    let n = &touch.normal;
    let vc = &touch.velocity;
    let vt = sub(vc, &scale(n, dot(n, vc)));
    let xt = sub(xi, &scale(n, dot(n, xi)));
    let ddot = -dot(n, vc);
    let xt2 = dot(&xt, &xt);
    let dxmax = if touch.exponent > 0.0 {
        (law.friction / law.ratio - touch.exponent * xmax / touch.penetration) * ddot
    } else {
        law.friction / law.ratio * ddot
    };
    let r = (dot(&vt, &vt).sqrt() + xt2 / (xmax * xmax) * (-dxmax).max(0.0)) / xmax;
    let rate = sub(&vt, &scale(xi, r));
    let stick = sub(&vt, &scale(&xt, r));
    let eta = law.damping_time * kt;
    let force = sub(&scale(&xt, -kt), &scale(&stick, eta));
    let normal = if touch.exponent > 0.0 {
        touch.exponent * kt * xt2 / (2.0 * touch.penetration)
    } else {
        0.0
    };
    Spring {
        force,
        normal,
        rate,
        energy: 0.5 * kt * xt2,
        dissipation: kt * r * xt2 + eta * dot(&stick, &vt),
        stiffness: kt,
        slip: xmax,
    }
}

/// A tracked contact that is not touching: no force, `ξ̇ = −ξ/τ_d`.
pub fn dropped(xi: &V3<f64>) -> Spring {
    Spring {
        rate: scale(xi, -1.0 / DROP_TIME),
        ..Spring::default()
    }
}
