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
//! `φ′ = d ln k/d ln r` at fixed `A + B` follows from the derivatives of
//! the complete elliptic integrals in closed form ([`log_slope`]); within
//! `m = e² < 10⁻²` of the circle, where those terms cancel, it is taken by
//! differences ([`log_slope_by_differences`]: central, step [`LOG_STEP`]
//! in `ln r`, one-sided of second order next to `r = 1`; the elliptic
//! solve gives `ln k` to a few ulps, so the rounding error is about
//! `4·10⁻¹⁶/(2h) ≈ 10⁻¹¹` and the truncation error `h² φ‴/6 ≈ 10⁻¹⁰`).
//!
//! `A` and `B` are differentiated exactly: the contact's gap, force
//! direction and point come from the generated pair function in [`Dual`]
//! numbers seeded with the centre of mass `p` and a small rotation `φ` of
//! the peg about it (hole frame, `q → (1, φ/2) ⊗ q`), the stationary angle
//! eliminated by `dα*/d(pose) = −(∂g′/∂(pose))/g″`
//! ([`Pair::at_stationary`]) as in the exact Jacobian
//! ([`super::jacobian`]). The gradient in `(p, φ)` is directly a
//! force through the centre of mass and a moment:
//! `F = −(2/5) δ^{5/2} ∂k/∂p`, `T = −(2/5) δ^{5/2} ∂k/∂φ` (a rotation about
//! the centre keeps the quaternion unit to first order, so no constraint
//! force enters).

use super::contact::{ContactPoint, Pair, axis_of};
use super::curvature;
use super::frame::axis;
use super::params::Peg3dParams;
use crate::hertz::{
    Curvatures, Ellipticity, EllipticityMethod, HertzContact, HertzError, Material,
};
use crate::scalar::Dual;
use nalgebra::{SVector, Vector3};

/// The dual numbers of [`gradient`]: `p`, `φ` in the first six slots, the
/// edge angle in the last.
type D = Dual<16>;

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
/// `el` the ellipticity of the contact, as in the module documentation:
/// `φ′` in closed form ([`log_slope`]) away from the circle, by
/// differences ([`log_slope_by_differences`]) within `m = e² <`
/// [`NEAR_CIRCLE`] of it.
///
/// # Errors
/// As [`HertzContact::try_new`] (only near the circle).
pub fn log_partials(
    a: f64,
    b: f64,
    el: &Ellipticity,
    m1: &Material,
    m2: &Material,
) -> Result<(f64, f64), HertzError> {
    let s = a + b;
    let slope = match log_slope(el) {
        Some(v) => v,
        None => log_slope_by_differences(a, b, m1, m2)?,
    };
    Ok((-0.5 / s - slope / a, -0.5 / s + slope / b))
}

/// Below this `m = e² = 1 − (b/a)²` of the contact ellipse [`log_slope`]
/// leaves `φ′` to differences (its terms cancel as `O(m)`: relative
/// rounding error `ε/m`).
pub const NEAR_CIRCLE: f64 = 1e-2;

/// `φ′ = d ln k / d ln r` at fixed `A + B` in closed form, from the
/// ellipse's integrals (`K`, `E`, `B_u = (K − E)/m`, `C_u = (E − m_c K)/m`,
/// `m_c = 1 − m = 1/κ²`), with `dK/dm = C_u/(2 m_c)`, `dE/dm = −B_u/2`
/// (DLMF 19.4.1 with `m = k²`):
///
/// ```text
/// r = B/A = C_u / (m_c B_u),   δ* = 2K/(π m_a),   m_a = (2 E/(π m_c))^{1/3}
/// d ln δ*/dm = C_u/(2 m_c K) + B_u/(6E) − 1/(3 m_c)
/// d ln r/dm  = (K − B_u/2 − 3C_u/2)/(m C_u) + 1/m_c − (C_u − m_c B_u)/(2 m m_c B_u)
/// φ′ = −(3/2) (d ln δ*/dm) / (d ln r/dm)        (k ∝ δ*^{−3/2})
/// ```
///
/// `None` below [`NEAR_CIRCLE`].
pub fn log_slope(el: &Ellipticity) -> Option<f64> {
    let k2 = el.kappa * el.kappa;
    let mc = 1.0 / k2;
    let m = (el.kappa - 1.0) * (el.kappa + 1.0) / k2;
    if m.is_nan() || m < NEAR_CIRCLE {
        return None;
    }
    let (k, e, bu, cu) = (el.k, el.e, el.k_minus_e_over_m, el.e_minus_mc_k_over_m);
    let dln_delta = cu / (2.0 * mc * k) + bu / (6.0 * e) - 1.0 / (3.0 * mc);
    let dln_r =
        (k - 0.5 * bu - 1.5 * cu) / (m * cu) + 1.0 / mc - (cu - mc * bu) / (2.0 * m * mc * bu);
    Some(-1.5 * dln_delta / dln_r)
}

/// `φ′` by differences of `ln k` in `ln r` at fixed `A + B`: central with
/// step [`LOG_STEP`], one-sided of second order within two steps of the
/// circle `r = 1`.
///
/// # Errors
/// As [`HertzContact::try_new`].
pub fn log_slope_by_differences(
    a: f64,
    b: f64,
    m1: &Material,
    m2: &Material,
) -> Result<f64, HertzError> {
    let s = a + b;
    let l = (b / a).ln();
    let h = LOG_STEP;
    let ln_k = |lr: f64| -> Result<f64, HertzError> {
        let r = lr.exp();
        Ok(of_relative(s / (1.0 + r), s * r / (1.0 + r), m1, m2)?.ln())
    };
    Ok(if l >= 2.0 * h {
        (ln_k(l + h)? - ln_k(l - h)?) / (2.0 * h)
    } else {
        (-3.0 * ln_k(l)? + 4.0 * ln_k(l + h)? - ln_k(l + 2.0 * h)?) / (2.0 * h)
    })
}

/// `(∂k/∂p, ∂k/∂φ)` of the stiffness `k` (N/m^{3/2}) of `pair`'s contact at
/// its stationary angle `angle` at pose `x` (centre of mass, unit
/// quaternion), `hertz` the contact's Hertz setup there, `p` the generated
/// functions' parameter vector: `∂k/∂p` in
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
    hertz: &HertzContact,
) -> Result<(Vector3<f64>, Vector3<f64>), HertzError> {
    let k = hertz.stiffness();
    let c = D::constant;
    let phi = [
        D::variable(0.0, 3),
        D::variable(0.0, 4),
        D::variable(0.0, 5),
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
        D::variable(x[0], 0),
        D::variable(x[1], 1),
        D::variable(x[2], 2),
        q[0],
        q[1],
        q[2],
        q[3],
    ];
    let xd = SVector::<D, 7>::from(xs);
    let pd = p.map(D::constant);
    let at = pair.at_stationary(&xd, angle, &pd);
    let centre = [xs[0], xs[1], xs[2]];
    let (a, b) = curvature::relative(
        prm,
        pair,
        &at.point,
        &at.normal,
        at.penetration,
        &centre,
        &axis(&xs),
    );
    let (m1, m2) = match pair {
        Pair::EdgeSide => (&prm.hole_material, &prm.peg_material),
        _ => (&prm.peg_material, &prm.hole_material),
    };
    let (la, lb) = log_partials(a.v, b.v, &hertz.ellipticity, m1, m2)?;
    let g = |i: usize| k * (la * a.d[i] + lb * b.d[i]);
    Ok((
        Vector3::new(g(0), g(1), g(2)),
        Vector3::new(g(3), g(4), g(5)),
    ))
}

/// The Hertz setup from the curvatures at contact `c` at pose `x`
/// ([`curvature::at`]; body 1 the hole for [`Pair::EdgeSide`], the peg
/// otherwise).
///
/// # Errors
/// As [`HertzContact::try_new`].
pub fn hertz_at(
    prm: &Peg3dParams,
    c: &ContactPoint,
    x: &SVector<f64, 7>,
) -> Result<HertzContact, HertzError> {
    let centre = Vector3::new(x[0], x[1], x[2]);
    let curv = curvature::at(prm, c, &centre, &axis_of(x));
    let (m1, m2) = match c.pair {
        Pair::EdgeSide => (&prm.hole_material, &prm.peg_material),
        _ => (&prm.peg_material, &prm.hole_material),
    };
    HertzContact::try_new(&curv, m1, m2, EllipticityMethod::Exact)
}

/// The stiffness `k` (N/m^{3/2}) from the curvatures at contact `c` (a
/// point or a col, at its stationary angle) at pose `x`, with the force
/// `−(2/5) δ^{5/2} ∂k/∂p` (N) and moment `−(2/5) δ^{5/2} ∂k/∂φ` (N·m) of
/// [`gradient`], `δ` the contact's penetration.
///
/// # Errors
/// As [`HertzContact::try_new`].
pub fn with_term(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    c: &ContactPoint,
    x: &SVector<f64, 7>,
) -> Result<(f64, Vector3<f64>, Vector3<f64>), HertzError> {
    let hz = hertz_at(prm, c, x)?;
    let (gp, gphi) = gradient(prm, p, c.pair, c.angle, x, &hz)?;
    let d = c.penetration;
    let e = -0.4 * d * d * d.sqrt();
    Ok((hz.stiffness(), gp * e, gphi * e))
}
