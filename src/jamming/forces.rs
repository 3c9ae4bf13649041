//! Quasi-static two-point contact forces in Whitney's frame (hole frame,
//! applied load reduced to the peg tip), exact in the tilt θ.
//!
//! Reference configuration as in [`super::geometry`]. Forces *on the peg*
//! while it slides into the hole (tip corner moves along +z, the peg slides
//! down its own axis past the edge), friction at the kinetic limit:
//!
//! ```text
//! tip contact  (wall x = 0, normal +x):        f_t (1, −μ)
//! edge contact (normal −n, n = (cosθ, sinθ)):  f_e (−cosθ + μ sinθ, −sinθ − μ cosθ)
//! ```
//!
//! The applied wrench (F_x, F_z, M), with M about the tip centre and positive
//! in the sense τ = Δx F_z − Δz F_x, balances them:
//!
//! ```text
//! F_x = −f_t + k1 f_e          k1 = cosθ − μ sinθ
//! F_z =  μ f_t + k2 f_e        k2 = sinθ + μ cosθ
//! M   = −r k2 f_t + (l + μr) f_e
//! ```
//!
//! The edge normal is perpendicular to the peg axis at distance l from the
//! tip, and the edge friction runs along the peg side at distance r, so the
//! edge moment arm is exactly l + μr at any θ. These are the paper's
//! Eqs. 51–52 with accelerations zero, mirrored and with the moment taken
//! about the tip instead of the centre of mass (see [`super::quasi_static`]).

use super::error::SlidingIndeterminate;
use super::params::PegHole;
use crate::scalar::Real;

/// A planar load applied to the peg, reduced to the tip centre: forces
/// F_x, F_z (N) and moment M about the tip (N·m), hole frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wrench {
    /// Lateral force F_x (N), positive towards the edge-contact wall.
    pub fx: f64,
    /// Axial force F_z (N), positive into the hole.
    pub fz: f64,
    /// Moment about the tip centre (N·m), τ = Δx F_z − Δz F_x.
    pub m: f64,
}

/// Normal contact forces of two-point contact (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForces {
    /// At the tip corner against the wall (Whitney's f₂).
    pub tip: f64,
    /// At the hole-mouth edge against the peg side (Whitney's f₁).
    pub edge: f64,
}

/// The friction-dependent factors (k1, k2, k3 = k2 + μ k1) of the paper's
/// Eq. 52 at tilt `theta`.
pub fn k_factors<T: Real>(mu: T, theta: T) -> (T, T, T) {
    let (s, c) = theta.sin_cos();
    let k1 = c - mu * s;
    let k2 = s + mu * c;
    (k1, k2, k2 + mu * k1)
}

/// Contact forces that balance the applied forces `fx`, `fz` (N) while the
/// peg slides in two-point contact at tilt `theta` (rad).
///
/// Both must be non-negative for two-point sliding to be possible.
///
/// Unchecked: divides by k3 (Eq. 52), so it returns ±∞ or NaN where k3 = 0
/// (θ = −2 atan μ mod π, which lies in (0, π/2) when μ > 1). Inputs that
/// come from a user go through [`try_sliding_contact_forces`]. No scene or
/// CLI path calls this form (the jamming diagram, sweep and wedging use
/// k1/k2 only, and k2 = sin θ + μ cos θ > 0 for 0 < θ < π/2, μ > 0); it is
/// kept as the plain closed form that tests and benches compare against.
pub fn sliding_contact_forces(p: &PegHole, theta: f64, fx: f64, fz: f64) -> ContactForces {
    eq52(p.mu(), k_factors(p.mu(), theta), fx, fz)
}

/// Eq. 52's division for given factors, unchecked.
fn eq52(mu: f64, (k1, k2, k3): (f64, f64, f64), fx: f64, fz: f64) -> ContactForces {
    ContactForces {
        tip: (k1 * fz - k2 * fx) / k3,
        edge: (fz + mu * fx) / k3,
    }
}

/// The k-factors of Eq. 52 at `theta`, or [`SlidingIndeterminate`] when
/// `|k3|` is within its rounding error `8 u (1 + μ)²` of 0 (u = 2⁻⁵³).
pub fn checked_k_factors(mu: f64, theta: f64) -> Result<(f64, f64, f64), SlidingIndeterminate> {
    check_k3(mu, theta, k_factors(mu, theta))
}

/// The check of [`checked_k_factors`] on given factors (also NaN k3).
fn check_k3(
    mu: f64,
    theta: f64,
    (k1, k2, k3): (f64, f64, f64),
) -> Result<(f64, f64, f64), SlidingIndeterminate> {
    let bound = 4.0 * f64::EPSILON * (1.0 + mu).powi(2);
    if k3.is_nan() || k3.abs() <= bound {
        return Err(SlidingIndeterminate { theta, k3 });
    }
    Ok((k1, k2, k3))
}

/// Eq. 52's division for given factors, checked.
#[doc(hidden)]
pub fn forces_from_factors(
    mu: f64,
    theta: f64,
    k: (f64, f64, f64),
    fx: f64,
    fz: f64,
) -> Result<ContactForces, SlidingIndeterminate> {
    Ok(eq52(mu, check_k3(mu, theta, k)?, fx, fz))
}

/// [`sliding_contact_forces`], or why they are not determined.
///
/// # Errors
/// [`SlidingIndeterminate`] when `|k3|` is within its rounding error
/// `8 u (1 + μ)²` of 0 (u = 2⁻⁵³): there the forces would be ±∞ or NaN,
/// or finite but all rounding.
pub fn try_sliding_contact_forces(
    p: &PegHole,
    theta: f64,
    fx: f64,
    fz: f64,
) -> Result<ContactForces, SlidingIndeterminate> {
    let mu = p.mu();
    forces_from_factors(mu, theta, k_factors(mu, theta), fx, fz)
}

/// [`sliding_moment`], or why it is not determined.
///
/// # Errors
/// [`SlidingIndeterminate`] as [`try_sliding_contact_forces`].
pub fn try_sliding_moment(
    p: &PegHole,
    l: f64,
    theta: f64,
    fx: f64,
    fz: f64,
) -> Result<f64, SlidingIndeterminate> {
    Ok(sliding_wrench(p, l, theta, try_sliding_contact_forces(p, theta, fx, fz)?).m)
}

/// The applied wrench that holds the peg in equilibrium sliding for given
/// contact forces (N) at depth `l` (m) and tilt `theta` (rad).
pub fn sliding_wrench(p: &PegHole, l: f64, theta: f64, f: ContactForces) -> Wrench {
    let (mu, r) = (p.mu(), p.r());
    let (k1, k2, _) = k_factors(mu, theta);
    Wrench {
        fx: -f.tip + k1 * f.edge,
        fz: mu * f.tip + k2 * f.edge,
        m: -r * k2 * f.tip + (l + mu * r) * f.edge,
    }
}

/// Moment about the tip (N·m) needed for equilibrium sliding under `fx`,
/// `fz` (N): the two-point contact line of the jamming diagram. Unchecked
/// (±∞ or NaN at k3 = 0, see [`sliding_contact_forces`]); the checked form
/// is [`try_sliding_moment`].
pub fn sliding_moment(p: &PegHole, l: f64, theta: f64, fx: f64, fz: f64) -> f64 {
    sliding_wrench(p, l, theta, sliding_contact_forces(p, theta, fx, fz)).m
}

/// Whitney's small-angle form (θ → 0): F_x = f₁ − f₂, F_z = μ(f₁ + f₂),
/// M = f₁ l + μ r (f₁ − f₂), with f₁ at the edge and f₂ at the tip.
pub fn whitney_sliding_wrench(p: &PegHole, l: f64, f: ContactForces) -> Wrench {
    let (mu, r) = (p.mu(), p.r());
    Wrench {
        fx: f.edge - f.tip,
        fz: mu * (f.edge + f.tip),
        m: f.edge * l + mu * r * (f.edge - f.tip),
    }
}

/// The same load in the paper's frame (Fig. 5; the mirror image of
/// Whitney's): `(f₁, f₂, M_C)` with f₁ along the peg axis towards the tip,
/// f₂ across it (N), and the moment about the centre of mass C, which lies
/// `l_c` (m) above the tip face, in the sense of θ (N·m). `w` is in
/// Whitney's frame with the moment about the tip; `theta` (rad) is the tilt.
pub fn to_paper_frame(w: &Wrench, theta: f64, l_c: f64) -> (f64, f64, f64) {
    let (s, c) = theta.sin_cos();
    let (x, y) = (-w.fx, w.fz);
    (
        x * s + y * c,
        x * c - y * s,
        w.m - l_c * (w.fz * s + w.fx * c),
    )
}
