//! Building blocks for contact models, as expressions: unilateral contact,
//! Hertz and linear penalty laws, Hunt–Crossley damping, regularized
//! Coulomb friction, and the peg/hole geometry of pegdyn's own models.
//!
//! ```
//! use pegdyn_equations::{Graph, blocks};
//! let g = Graph::new();
//! let (k, d) = (g.param("k"), g.var("d"));
//! // Hertz: Q = k max(δ, 0)^{3/2}, and its potential (2/5) k max(δ, 0)^{5/2},
//! // whose derivative is the load (times the unit step, 1 where max0 > 0).
//! assert_eq!(blocks::hertz_load(k, d).to_string(), "k*max0(d)^1.5");
//! assert_eq!(blocks::hertz_potential(k, d).diff(d).to_string(), "k*max0(d)^1.5*step(d)");
//! ```

use crate::expr::Expr;

/// Contact geometry of the compliant planar peg: penetrations (exact signed
/// circle–line distances) and sliding velocities of the four peg/hole
/// contacts as expressions of the peg's coordinates `x, z, theta`.
pub use crate::models::compliant_peg::geometry::{Contact, ContactKinematics, PegFrame};
pub use crate::models::hertz::{
    HertzCoefficients, HertzState, load as hertz_load, potential as hertz_potential,
    state as hertz_state, stiffness as hertz_stiffness,
};
/// Geometry of the rigid three-point peg (peg and hole frames, the three
/// contact points, vector helpers).
pub use crate::models::rigid_peg::geometry as rigid_peg_geometry;

/// The unilateral part `max(δ, 0)` of a penetration `δ` (m): zero when the
/// bodies are apart, `δ` when they overlap.
pub fn unilateral(delta: Expr<'_>) -> Expr<'_> {
    delta.max0()
}

/// Linear penalty contact: the load `Q = k max(δ, 0)` (N) for stiffness
/// `k` (N/m) at penetration `δ` (m).
pub fn penalty_load<'g>(k: Expr<'g>, delta: Expr<'g>) -> Expr<'g> {
    k * delta.max0()
}

/// The potential of [`penalty_load`]: `½ k max(δ, 0)²` (J); its derivative
/// in `δ` is the load.
pub fn penalty_potential<'g>(k: Expr<'g>, delta: Expr<'g>) -> Expr<'g> {
    0.5 * k * delta.max0().square()
}

/// Hunt–Crossley normal force `f = Q max(0, 1 + α δ̇)` (N) from the
/// elastic load `Q` (N), damping coefficient `α` (s/m) and approach rate
/// `δ̇` (m/s): dissipative on approach and rebound, never pulling.
pub fn hunt_crossley<'g>(elastic: Expr<'g>, alpha: Expr<'g>, delta_rate: Expr<'g>) -> Expr<'g> {
    elastic * (1.0 + alpha * delta_rate).max0()
}

/// Regularized Coulomb friction `f_t = −μ f_n s / √(s² + v_s²)` (N) against
/// the slip velocity `s` (m/s), for normal force `f_n ≥ 0` (N), friction
/// coefficient `μ` and velocity scale `v_s > 0` (m/s): `|f_t| → μ f_n` for
/// `|s| ≫ v_s`, smooth (linear in `s`) through `s = 0`.
pub fn regularized_friction<'g>(
    mu: Expr<'g>,
    normal: Expr<'g>,
    slip: Expr<'g>,
    v_s: Expr<'g>,
) -> Expr<'g> {
    -mu * normal * slip / slip.hypot(v_s)
}
