//! The pose derivative of the curvature stiffness ([`super::HertzMode::Curvature`]):
//! the term `−(2/5) δ^{5/2} ∂k/∂(pose)` that makes the contact force the
//! full negative gradient of `V = (2/5) k δ^{5/2}`.
//!
//! The stiffness depends on the pose only through the relative curvatures
//! `(A, B)` at the contact ([`curvature::relative`]): with `Σρ = 2(A + B)`
//! and `δ*` a function of the ratio `r = B/A` alone ([`HertzContact`]),
//!
//! ```text
//! k = (2E*/3) √(8 / (δ*(r)³ Σρ)),   ln k = const − ½ ln(A + B) + φ(ln r)
//! ∂ln k/∂A = −1/(2(A + B)) − φ′/A,   ∂ln k/∂B = −1/(2(A + B)) + φ′/B
//! ```
//!
//! `φ′ = d ln k/d ln r` at fixed `A + B` is the one number taken by
//! differences: central, step [`LOG_STEP`] in `ln r` (one-sided of second
//! order within two steps of the circle `r = 1`, where `k` is even in
//! `ln r`). The elliptic solve gives `ln k` to a few ulps, so the
//! rounding error is about `4·10⁻¹⁶ / (2h) ≈ 10⁻¹¹` and the truncation
//! error `h² φ‴/6 ≈ 10⁻¹⁰ φ‴` (`φ‴` of order one): a relative error of
//! about `10⁻¹⁰` in a term that is itself a fraction of a per cent of the
//! Hertz force.
//!
//! `A` and `B` are differentiated exactly: the contact's gap, force
//! direction and point come from the generated pair function in [`Dual`]
//! numbers seeded with the centre of mass `p` and a small rotation `φ` of
//! the peg about it (hole frame, `q → (1, φ/2) ⊗ q`), the stationary angle
//! eliminated by `dα*/d(pose) = −(∂g′/∂(pose))/g″`
//! ([`super::jacobian::at_stationary`]). The gradient in `(p, φ)` is
//! directly a force through the centre of mass and a moment:
//! `F = −(2/5) δ^{5/2} ∂k/∂p`, `T = −(2/5) δ^{5/2} ∂k/∂φ` (a rotation about
//! the centre keeps the quaternion unit to first order, so no constraint
//! force enters).

use super::curvature;
use super::dual::Dual;
use super::face;
use super::jacobian;
use super::params::Peg3dParams;
use super::search::Pair;
use crate::hertz::{Curvatures, EllipticityMethod, HertzContact, HertzError, Material};
use nalgebra::{SVector, Vector3};

/// Step in `ln(B/A)` of the difference quotient of `d ln k/d ln r`.
pub const LOG_STEP: f64 = 2e-5;

/// The Hertz stiffness `k` (N/m^{3/2}) of relative curvatures `0 < a ≤ b`
/// (1/m) and materials `m1`, `m2` (the aligned bodies `[2a, 2b]` on a flat
/// have exactly these relative curvatures).
///
/// # Errors
/// As [`HertzContact::try_new`].
pub fn of_relative(a: f64, b: f64, m1: &Material, m2: &Material) -> Result<f64, HertzError> {
    let curv = Curvatures::aligned([2.0 * a, 2.0 * b], [0.0, 0.0]);
    Ok(HertzContact::try_new(&curv, m1, m2, EllipticityMethod::Exact)?.stiffness())
}

/// `(∂ln k/∂A, ∂ln k/∂B)` (m) at relative curvatures `0 < a ≤ b` (1/m),
/// as in the module documentation.
///
/// # Errors
/// As [`HertzContact::try_new`].
pub fn log_partials(
    a: f64,
    b: f64,
    m1: &Material,
    m2: &Material,
) -> Result<(f64, f64), HertzError> {
    let s = a + b;
    let l = (b / a).ln();
    let h = LOG_STEP;
    let ln_k = |lr: f64| -> Result<f64, HertzError> {
        let r = lr.exp();
        Ok(of_relative(s / (1.0 + r), s * r / (1.0 + r), m1, m2)?.ln())
    };
    let slope = if l >= 2.0 * h {
        (ln_k(l + h)? - ln_k(l - h)?) / (2.0 * h)
    } else {
        (-3.0 * ln_k(l)? + 4.0 * ln_k(l + h)? - ln_k(l + 2.0 * h)?) / (2.0 * h)
    };
    Ok((-0.5 / s - slope / a, -0.5 / s + slope / b))
}

/// `(∂k/∂p, ∂k/∂φ)` of the stiffness `k` (N/m^{3/2}) of `pair`'s contact at
/// its stationary angle `angle` at pose `x` (centre of mass, unit
/// quaternion), `p` the generated functions' parameter vector: `∂k/∂p` in
/// N/m^{5/2}, `∂k/∂φ` per radian of rotation about the centre of mass (hole
/// frame).
///
/// # Errors
/// As [`HertzContact::try_new`] at the contact's relative curvatures.
pub fn gradient(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    pair: Pair,
    angle: f64,
    x: &SVector<f64, 7>,
    k: f64,
) -> Result<(Vector3<f64>, Vector3<f64>), HertzError> {
    let c = Dual::constant;
    let phi = [
        Dual::variable(0.0, 3),
        Dual::variable(0.0, 4),
        Dual::variable(0.0, 5),
    ];
    let (w, u) = (c(x[3]), [c(x[4]), c(x[5]), c(x[6])]);
    let half = c(0.5);
    // q + ½ (0, φ) ⊗ q = q + ½ (−φ·u, w φ + φ × u).
    let q = [
        w - half * (phi[0] * u[0] + phi[1] * u[1] + phi[2] * u[2]),
        u[0] + half * (w * phi[0] + phi[1] * u[2] - phi[2] * u[1]),
        u[1] + half * (w * phi[1] + phi[2] * u[0] - phi[0] * u[2]),
        u[2] + half * (w * phi[2] + phi[0] * u[1] - phi[1] * u[0]),
    ];
    let xs = [
        Dual::variable(x[0], 0),
        Dual::variable(x[1], 1),
        Dual::variable(x[2], 2),
        q[0],
        q[1],
        q[2],
        q[3],
    ];
    let xd = SVector::<Dual, 7>::from_column_slice(&xs);
    let pd = p.map(Dual::constant);
    let (gap, n, pt) = jacobian::at_stationary(pair, &xd, angle, &pd);
    let centre = [xs[0], xs[1], xs[2]];
    let axis = face::axis(&xs);
    let (a, b) = curvature::relative(prm, pair, &pt, &n, -gap, &centre, &axis);
    let (m1, m2) = match pair {
        Pair::EdgeSide => (&prm.hole_material, &prm.peg_material),
        _ => (&prm.peg_material, &prm.hole_material),
    };
    let (la, lb) = log_partials(a.v, b.v, m1, m2)?;
    let g = |i: usize| k * (la * a.d[i] + lb * b.d[i]);
    Ok((
        Vector3::new(g(0), g(1), g(2)),
        Vector3::new(g(3), g(4), g(5)),
    ))
}
