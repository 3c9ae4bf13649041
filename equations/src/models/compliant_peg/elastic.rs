//! Stick-capable friction of the compliant planar peg: Hertz–Mindlin
//! tangential compliance capped by Coulomb, written as a smooth ODE (a Dahl
//! rate law on the tangential spring). Derivation in `docs/compliant.md`.
//!
//! Per contact, with penetration `δ` (m), slip velocity `v` (m/s) of the
//! peg's material point along the tangent, Hertz stiffness `k`
//! (N/m^{3/2}) and elastic normal force `N = k δ₊^{3/2}` (N):
//!
//! - tangential stiffness (Mindlin) `k_t = 8 G* a` (N/m) with `a = √(ab)`
//!   the equivalent radius of the Hertz ellipse; since
//!   `a, b ∝ (1.5 N/(Σρ E*))^{1/3}` this is `k_t = C_t δ₊^{1/2}` with
//!   `C_t = 8 G* √(m_a m_b) (1.5 k/(Σρ E*))^{1/3}` (N/m^{3/2});
//! - tangential spring `ξ` (m), its Coulomb limit `ξ_max = μN/k_t =
//!   μ k δ / C_t`; the state is the utilisation `u = ξ/ξ_max` (–);
//! - friction force on the peg along the tangent `F_t = −k_t ξ = −μ N u` (N);
//! - Dahl rate `ξ̇ = v − |v| u`: the spring follows the contact point
//!   (`ξ̇ = v`) while `|u| < 1` is far from the limit and saturates at
//!   `u = sign v` in sliding, where `F_t = −μ N sign v`; at `v = 0` nothing
//!   moves (no creep);
//! - normal unloading at rest shrinks `ξ_max ∝ δ` under a fixed `ξ`; so
//!   that `|u| ≤ 1` holds (the force never leaves the cone), the part of
//!   the spring beyond the shrinking cone slips: `ξ̇` gains
//!   `−u³ ξ_max δ̇₋/δ` with `δ̇₋ = max(−δ̇, 0)` (dissipative). In `u`:
//!   `u̇ = [C_t (v − |v| u)/(μ k) − u (δ̇_f + u² max(−δ̇_f, 0))] / δ_f`
//!   with `δ_f = √(δ² + δ_0²)` (`= δ` to a relative `(δ_0/δ)²/2` in
//!   contact; the floor `δ_0` keeps the rate finite and smooth at `δ = 0`;
//!   out of contact `N = 0` and `u` does not act);
//! - tangential damping of the spring's stick motion: the force
//!   `−η (v − |v| u)` with `η = τ_t k_t` (N·s/m), `k_t` written
//!   `C_t δ₊^{3/2}/δ_f` (= `C_t δ^{1/2}` for `δ ≥ δ_0`, smooth at `δ = 0`)
//!   and `τ_t` (s) the damping time; it vanishes in steady sliding
//!   (`u = sign v`) and at rest (no creep), dissipating
//!   `η v (v − |v| u) ≥ 0`;
//! - stored energy `E_t = ½ k_t ξ² = μ² k² u² δ₊^{5/2} / (2 C_t)` (J); at
//!   fixed `ξ` it grows with `δ`, which adds the normal force
//!   `P = ∂E_t/∂δ|_ξ = μ² k u² N / (4 C_t)` (N) along the contact normal;
//! - dissipation rate `μ N u² |v| + (μ² k / C_t) N u⁴ δ̇₋ +
//!   η v (v − |v| u) ≥ 0` (W), so
//!   that `T + V + E_t − W + S` is constant (for `δ ≥ δ_0`).

use super::geometry::ContactKinematics;
use crate::expr::Expr;
use crate::models::hertz::HertzCoefficients;

/// Per-contact terms of the elastic (stick-capable) friction law.
#[derive(Clone, Copy, Debug)]
pub struct Tangential<'g> {
    /// Friction force on the peg along the tangent,
    /// `F_t = −μ N u − η (v − |v| u)` (N).
    pub force: Expr<'g>,
    /// Extra normal force `P = μ² k u² N / (4 C_t)` (N), from the
    /// δ-dependence of the stored tangential energy.
    pub normal_extra: Expr<'g>,
    /// Rate `u̇` of the utilisation state (1/s).
    pub rate: Expr<'g>,
    /// Stored tangential energy `E_t` (J).
    pub energy: Expr<'g>,
    /// Dissipation rate `μ N u² |v| + (μ² k / C_t) N u⁴ δ̇₋ + η v (v − |v| u)` (W).
    pub dissipation: Expr<'g>,
}

/// Inputs of one contact's tangential law.
pub struct TangentialInputs<'g, 'a> {
    /// Penetration and slip of the contact.
    pub kin: &'a ContactKinematics<'g>,
    /// Time derivative of the floored penetration `δ_f` (m/s).
    pub floor_rate: Expr<'g>,
    /// Floored penetration `δ_f = √(δ² + δ_0²)` (m).
    pub floored: Expr<'g>,
    /// Utilisation state `u` (–).
    pub u: Expr<'g>,
    /// Hertz stiffness `k` (N/m^{3/2}).
    pub k: Expr<'g>,
    /// Elastic normal force `N = k δ₊^{3/2}` (N).
    pub normal: Expr<'g>,
    /// Hertz coefficients of the contact.
    pub coeffs: &'a HertzCoefficients<'g>,
    /// Friction coefficient `μ > 0`.
    pub mu: Expr<'g>,
    /// Tangential damping time `τ_t` (s).
    pub tau: Expr<'g>,
    /// Effective shear modulus `G*` (Pa), `1/G* = Σ (2 − νᵢ)/Gᵢ`.
    pub g_star: Expr<'g>,
}

/// The Mindlin constant `C_t = 8 G* √(m_a m_b) (1.5 k/(Σρ E*))^{1/3}`
/// (N/m^{3/2}) of `k_t = C_t δ^{1/2}`.
pub fn mindlin_constant<'g>(k: Expr<'g>, c: &HertzCoefficients<'g>, g_star: Expr<'g>) -> Expr<'g> {
    8.0 * g_star
        * (c.m_a * c.m_b).sqrt()
        * (1.5 * k / (c.sum_curvature * c.contact_modulus)).powf(1.0 / 3.0)
}

/// The terms of [`Tangential`] for one contact (see the module documentation).
pub fn tangential<'g>(i: &TangentialInputs<'g, '_>) -> Tangential<'g> {
    let ct = mindlin_constant(i.k, i.coeffs, i.g_star);
    let (u, v, mu, k, n) = (i.u, i.kin.slip, i.mu, i.k, i.normal);
    let mu2k = mu.square() * k / ct;
    let stick = v - v.abs() * u;
    let eta = i.tau * ct * i.kin.delta.max0().powf(1.5) / i.floored;
    Tangential {
        force: -mu * n * u - eta * stick,
        normal_extra: 0.25 * mu2k * u.square() * n,
        rate: (ct / (mu * k) * stick - u * (i.floor_rate + u.square() * (-i.floor_rate).max0()))
            / i.floored,
        energy: 0.5 * mu2k * k * u.square() * i.kin.delta.max0().powf(2.5),
        dissipation: mu * n * u.square() * v.abs()
            + mu2k * n * u.square().square() * (-i.floor_rate).max0()
            + eta * v * stick,
    }
}
