//! The peg's bottom against a flat (the block's top face `z₀ = 0`, the bore
//! bottom `z₀ = −h_b`) at small tilt: the rim circle as a distributed line
//! contact, handed over to the rim's Hertz point contact as the tilt grows.
//!
//! **The ring.** The rim's tube-centre circle `c(θ) = c_r + ϱ (cos θ e₁ +
//! sin θ e₂)` (`ϱ = r − ρ_p`, `c_r = p + h a`, `h = ρ_p − L/2`) has the
//! local penetration `δ(θ) = z₀ + ρ_p − c_z(θ)` into the flat, which at zero
//! tilt is also the penetration of the flat face's boundary. With the
//! centre's penetration `δ₀ = z₀ + ρ_p − c_r,z` and `A = ϱ sin γ`
//! (`sin²γ = a_x² + a_y² = u`) it is a pure sinusoid, `δ = δ₀ + A cos φ`
//! (`φ` from the lowest rim point). With a linear law per unit length of
//! rim, `q = k_ℓ δ` (N/m per m of penetration), the contact potential is
//!
//! ```text
//! V = k_ℓ ϱ ∫₀^{2π} ½ (δ₀ + A cos φ)₊² dφ = k_ℓ ϱ Î(δ₀, A)
//! Î = π δ₀² + (π/2) A²                                   (A ≤ δ₀: all round)
//! Î = A² (ρ² φ₀ + 2ρ s₀ + ½ (φ₀ − ρ s₀))                  (|ρ| < 1: an arc)
//! ρ = δ₀/A,  φ₀ = arccos(−ρ),  s₀ = sin φ₀ = √(1 − ρ²)
//! ```
//!
//! and the wrench is its exact negative gradient (the integral in closed
//! form: no quadrature, no division by `sin γ`):
//!
//! ```text
//! P = k_ℓ ϱ ∂Î/∂δ₀ = k_ℓ ϱ P̂,   P̂ = 2π δ₀  or  A (2ρ φ₀ + 2 s₀)
//! F = P e_z,   T = (P h + k_ℓ ϱ³ G a_z) (a × e_z),   G = π  or  φ₀ + ρ s₀
//! ```
//!
//! (`∂Î/∂A = A G`; `δ₀` moves by `−h δφ·(a × e_z)` and `u` by
//! `−2 a_z δφ·(a × e_z)` under a small rotation `δφ`). The force acts
//! along `e_z` through the centre of pressure `p + λ a` (horizontally),
//! `λ = (P h + k_ℓ ϱ³ G a_z)/P`, which lies within the rim circle. In full
//! contact the vertical stiffness is `2π ϱ k_ℓ`: with `k_ℓ = E*/π` it is the
//! rigid flat punch's `2 a E*` (Sneddon; Johnson, *Contact Mechanics*,
//! §3.8), so an aligned peg of weight `m g` rests `δ₀ = m g / (2 ϱ E*)`
//! deep. The rocking stiffness `π k_ℓ ϱ³ = E* ϱ³` is ¾ of the tilted
//! punch's `(4/3) E* a³`: a ring of independent springs cannot carry the
//! punch's moment for its force (see `docs/formula-departures.md`).
//!
//! **Hand-over.** For a short arc (`ρ → −1`) the ring is a point contact
//! `P ≈ (4√2/3) k_ℓ √(ϱ/sin γ) δ_m^{3/2}`, `δ_m = δ₀ + A` the deepest rim
//! penetration, i.e. Hertz-like with a stiffness growing as the tilt
//! vanishes. Between the tilts [`BLEND_START`] and [`BLEND_END`] the
//! potential is `(1 − s) V_ring + s V_point` with the C¹ weight
//! `s = 3t² − 2t³`, `t = (u − u₁)/(u₂ − u₁)` clamped to `[0, 1]`, in
//! `u = sin²γ` (a polynomial in the quaternion: regular at `γ = 0`). Its
//! gradient adds the pure moment `2 a_z s′(u) (V_point − V_ring) (a × e_z)`
//! ([`blend_moment`]), so the forces stay `−∂V/∂(pose)`. Below
//! [`BLEND_START`] the point search of the plane pair is skipped (it has no
//! isolated minimum at `γ = 0`).
//!
//! **Stiffness.** With [`HertzMode::Curvature`] `k_ℓ = E*/π` (the punch);
//! with [`HertzMode::Fixed`]`(k)` `k_ℓ` matches the ring's short-arc law
//! to `k δ_m^{3/2}` at the window's geometric-mean tilt `γ_m`:
//! `k_ℓ = (3/(4√2)) k √(sin γ_m/ϱ)`.
//!
//! The ring is applied only while the peg is upright (`a_z > 0`) and its
//! whole rim circle lies over the flat's existing part (radius at least
//! `R + ρ_h` for the top face, at most `R` for the bore bottom); otherwise
//! the plane pair is the point contact alone.
//!
//! Units: SI.

use super::contact::Pair;
use super::frame::{V3, axis};
use super::params::{HertzMode, Peg3dParams};
use crate::hertz::contact_modulus;
use crate::scalar::Real;
use nalgebra::{SVector, Vector3};
use std::f64::consts::PI;

/// Tilt (rad) below which the flat carries the peg by the ring alone.
pub const BLEND_START: f64 = 1e-3;

/// Tilt (rad) above which the flat carries the peg by the rim's Hertz point
/// contact alone.
pub const BLEND_END: f64 = 3e-3;

/// Below this ratio `ε = δ_m/A` of the deepest rim penetration to the
/// rim's height amplitude the ring's short-arc leading term replaces the
/// closed form (which cancels there).
const SHORT_ARC: f64 = 1e-4;

/// The plane `z₀` (m) of a plane pair: 0 for [`Pair::RimTop`], `−h_b` for
/// [`Pair::RimBottom`]; `None` for the other pairs.
pub fn plane(pair: Pair, prm: &Peg3dParams) -> Option<f64> {
    match pair {
        Pair::RimTop => Some(0.0),
        Pair::RimBottom => Some(-prm.bore_depth),
        _ => None,
    }
}

/// The ring's stiffness per unit length `k_ℓ` (N/m²) of the module
/// documentation.
pub fn line_stiffness(prm: &Peg3dParams) -> f64 {
    match prm.hertz {
        HertzMode::Curvature => contact_modulus(&prm.peg_material, &prm.hole_material) / PI,
        HertzMode::Fixed(k) => {
            let mid = (BLEND_START * BLEND_END).sqrt().sin();
            3.0 / (4.0 * 2f64.sqrt()) * k * (mid / (prm.peg_radius() - prm.rim_fillet)).sqrt()
        }
    }
}

/// The hand-over weight `s(u)` of the point contact and `ds/du`, at
/// `u = sin²γ`.
pub fn blend<T: Real>(u: T) -> (T, T) {
    let (u1, u2) = (BLEND_START.sin().powi(2), BLEND_END.sin().powi(2));
    let uf = u.to_f64();
    if uf <= u1 {
        (T::from_f64(0.0), T::from_f64(0.0))
    } else if uf >= u2 {
        (T::from_f64(1.0), T::from_f64(0.0))
    } else {
        let w = 1.0 / (u2 - u1);
        let t = (u - T::from_f64(u1)) * T::from_f64(w);
        let three = T::from_f64(3.0);
        let two = T::from_f64(2.0);
        let s = t * t * (three - two * t);
        let ds = T::from_f64(6.0 * w) * t * (T::from_f64(1.0) - t);
        (s, ds)
    }
}

/// Whether the ring of `pair` applies at pose `x`: a plane pair, the peg
/// upright, its tilt below [`BLEND_END`], its whole rim circle over the
/// flat's existing part.
pub fn applies(pair: Pair, prm: &Peg3dParams, x: &SVector<f64, 7>) -> bool {
    if plane(pair, prm).is_none() {
        return false;
    }
    let xs: [f64; 7] = (*x).into();
    let a = axis(&xs);
    if a[2] <= 0.0 || a[0] * a[0] + a[1] * a[1] >= BLEND_END.sin().powi(2) {
        return false;
    }
    let rr = prm.peg_radius() - prm.rim_fillet;
    let h = prm.rim_fillet - 0.5 * prm.length;
    let centre = Vector3::new(x[0] + h * a[0], x[1] + h * a[1], 0.0).norm();
    match pair {
        Pair::RimTop => centre - rr >= prm.bore_radius() + prm.mouth_fillet,
        _ => centre + rr <= prm.bore_radius(),
    }
}

/// The ring's elastic load at a pose, unweighted.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ring<T> {
    /// Vertical force `P` on the peg (N).
    pub force: T,
    /// `M = P h + k_ℓ ϱ³ G a_z` (N·m): the moment is `M (a × e_z)`.
    pub moment: T,
    /// Potential `V = k_ℓ ϱ Î` (J).
    pub potential: T,
    /// The peg's axis.
    pub axis: [T; 3],
    /// `u = sin²γ`.
    pub u: T,
    /// Deepest rim penetration `δ_m = δ₀ + A` (m).
    pub depth: f64,
    /// Body angle of the deepest rim point (rad; 0 at zero tilt).
    pub angle: f64,
}

/// The ring's geometry and stiffness, at any scalar (so that a dual
/// number can carry a parameter's derivative through [`ring_of`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RingShape<T> {
    /// Radius `ϱ = r − ρ_p` of the rim's tube-centre circle (m).
    pub radius: T,
    /// Axial offset `h = ρ_p − L/2` of the circle's centre from the centre
    /// of mass (m).
    pub offset: T,
    /// `z₀ + ρ_p` (m): the centre's penetration is `δ₀ = z₀ + ρ_p − c_r,z`.
    pub reach: T,
    /// Line stiffness `k_ℓ` (N/m²).
    pub line_stiffness: T,
}

impl<T: Real> RingShape<T> {
    /// The shape of the peg of `prm` on the plane `z0` (m) with line
    /// stiffness `kl` (N/m²), as constants of `T`.
    pub fn of(prm: &Peg3dParams, z0: f64, kl: f64) -> RingShape<T> {
        let c = T::from_f64;
        RingShape {
            radius: c(prm.peg_radius()) - c(prm.rim_fillet),
            offset: c(prm.rim_fillet) - c(0.5) * c(prm.length),
            reach: c(z0) + c(prm.rim_fillet),
            line_stiffness: c(kl),
        }
    }
}

/// The ring of the module documentation on the plane `z0` at pose `x`
/// (centre of mass, unit quaternion), with line stiffness `kl`; `None`
/// when no rim point penetrates. [`ring_of`] with [`RingShape::of`].
pub fn ring<T: Real>(prm: &Peg3dParams, z0: f64, kl: f64, x: &[T; 7]) -> Option<Ring<T>> {
    ring_of(&RingShape::of(prm, z0, kl), x)
}

/// The ring of the module documentation of `shape` at pose `x` (centre of
/// mass, unit quaternion); `None` when no rim point penetrates.
pub fn ring_of<T: Real>(shape: &RingShape<T>, x: &[T; 7]) -> Option<Ring<T>> {
    let c = T::from_f64;
    let (rr, h, kl) = (shape.radius, shape.offset, shape.line_stiffness);
    let a = axis(x);
    let u = a[0] * a[0] + a[1] * a[1];
    let d0 = shape.reach - x[2] - h * a[2];
    let (d0f, uf) = (d0.to_f64(), u.to_f64().max(0.0));
    let amp = rr.to_f64() * uf.sqrt();
    let depth = d0f + amp;
    if depth <= 0.0 {
        return None;
    }
    let (ihat, phat, g) = if d0f >= amp {
        let pi = c(PI);
        (
            pi * d0 * d0 + c(0.5 * PI) * rr * rr * u,
            c(2.0 * PI) * d0,
            pi,
        )
    } else if depth < SHORT_ARC * amp {
        // A short arc, ε = δ_m/A ≪ 1: the closed form cancels to ε^{3/2}
        // (ρ φ₀ + s₀ = (2ε/3)√(2ε) + …); its leading term instead,
        // Î = (8√2/15) A^{−1/2} δ_m^{5/2} (relative error O(ε)), with its
        // own exact derivatives P̂ = (4√2/3) A^{−1/2} δ_m^{3/2} and
        // A G = ∂Î/∂A = (8√2/15) (5/2 ε^{3/2} − ½ ε^{5/2}) A.
        let big_a = rr * u.sqrt();
        let dm = d0 + big_a;
        let eps = dm / big_a;
        let k0 = c(8.0 * 2f64.sqrt() / 15.0);
        let root = eps.sqrt();
        let ihat = k0 * big_a * big_a * eps * eps * root;
        let phat = c(4.0 * 2f64.sqrt() / 3.0) * big_a * eps * root;
        let g = k0 * (c(2.5) * eps * root - c(0.5) * eps * eps * root);
        (ihat, phat, g)
    } else {
        let big_a = rr * u.sqrt();
        let rho = d0 / big_a;
        let phi = (-rho).acos();
        let s0 = (c(1.0) - rho * rho).max0().sqrt();
        let ihat =
            big_a * big_a * (rho * rho * phi + c(2.0) * rho * s0 + c(0.5) * (phi - rho * s0));
        (ihat, c(2.0) * big_a * (rho * phi + s0), phi + rho * s0)
    };
    let force = kl * rr * phat;
    let moment = force * h + kl * rr * rr * rr * g * a[2];
    // The deepest rim point: body direction of −e_z projected on the rim
    // plane, R(q)ᵀ(−e_z) = −(row 3 of R) = (2(wj − ik), −2(jk + wi), ·).
    let (w, i, j, k) = (x[3].to_f64(), x[4].to_f64(), x[5].to_f64(), x[6].to_f64());
    let angle = if uf > 0.0 {
        (-2.0 * (j * k + w * i))
            .atan2(2.0 * (w * j - i * k))
            .rem_euclid(std::f64::consts::TAU)
    } else {
        0.0
    };
    Some(Ring {
        force,
        moment,
        potential: kl * rr * ihat,
        axis: a,
        u,
        depth,
        angle,
    })
}

/// The centre of pressure of a ring on the plane `z0`: `p + λ a`
/// horizontally, `λ = M/P`, at height `z0` (m).
pub fn centre_of_pressure<T: Real>(x: &[T; 7], ring: &Ring<T>, z0: f64) -> [T; 3] {
    let lambda = ring.moment / ring.force;
    [
        x[0] + lambda * ring.axis[0],
        x[1] + lambda * ring.axis[1],
        T::from_f64(z0),
    ]
}

/// The hand-over's pure moment `2 a_z s′(u) (V_point − V_ring) (a × e_z)`
/// (N·m, hole frame), `v_point` the plane pair's point-contact potential
/// and `v_ring` the ring's, both unweighted (J).
pub fn blend_moment<T: Real>(axis: &V3<T>, u: T, v_point: T, v_ring: T) -> V3<T> {
    let (_, ds) = blend(u);
    let m = T::from_f64(2.0) * axis[2] * ds * (v_point - v_ring);
    [m * axis[1], -m * axis[0], T::from_f64(0.0)]
}
