//! The ellipticity of a Hertz contact from its curvature ratio, and the
//! deformation coefficients of the paper's (9)–(13) that follow from it.
//!
//! Write the initial gap between the bodies as `h = A x² + B y²` with
//! `0 < A ≤ B` (the relative curvatures: `A + B = Σρ/2`). Hertz's pressure
//! `p₀ √(1 − x²/a² − y²/b²)` on the ellipse with semi-axes `a ≥ b` (`a` along
//! `x`, the direction of the *smaller* curvature) fits this gap exactly when
//! (Johnson, *Contact Mechanics*, §4.2, eqs. 4.39–4.41), with `m = e² = 1 − b²/a²`,
//!
//! ```text
//! B / A = [E/(1 − m) − K] / [K − E] = R_D(0, 1, 1 − m) / R_D(0, 1 − m, 1)
//! ```
//!
//! which increases monotonically from 1 (`m = 0`, a circle) to ∞ (`m → 1`).
//! [`solve`] inverts it by a bracketed Illinois iteration on `s = ln(a/b)`;
//! [`hamrock_brewe`] is the cheaper curve fit.

use super::elliptic::{CompleteIntegrals, carlson_rd, complete_integrals};
use super::error::HertzError;
use std::f64::consts::PI;

/// The largest curvature ratio `B/A` [`try_solve`] accepts. At `B/A = 10¹²`
/// the ellipse's axis ratio `a/b` is about `10⁷` and `1 − m ≈ 10⁻¹⁴`: beyond
/// it the contact is a line contact and `1 − m` underflows the digits the
/// integrals need.
pub const MAX_RATIO: f64 = 1e12;

/// Iteration cap of the bracketed root search in [`try_solve`] (the Illinois
/// iteration needs about 10 steps to reach rounding).
pub const MAX_ITERATIONS: usize = 200;

/// The shape of the contact ellipse and the elliptic integrals at its
/// eccentricity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipticity {
    /// `κ = a/b ≥ 1`, the ratio of the semi-axes.
    pub kappa: f64,
    /// `K(e)`, complete elliptic integral of the first kind.
    pub k: f64,
    /// `E(e)`, complete elliptic integral of the second kind.
    pub e: f64,
    /// `(K − E)/e²` (the paper's `B` of (12)); `π/4` for a circle.
    pub k_minus_e_over_m: f64,
    /// `(E − (1 − e²)K)/e²` (the paper's `C` of (12)); `π/4` for a circle.
    pub e_minus_mc_k_over_m: f64,
}

/// `B/A` as a function of `s = ln(a/b)`, as `ln(B/A)`.
fn log_ratio(s: f64) -> f64 {
    let mc = (-2.0 * s).exp();
    (carlson_rd(0.0, 1.0, mc) / carlson_rd(0.0, mc, 1.0)).ln()
}

fn from_log_kappa(s: f64) -> Ellipticity {
    let CompleteIntegrals {
        k,
        e,
        k_minus_e_over_m,
        e_minus_mc_k_over_m,
    } = complete_integrals((-2.0 * s).exp());
    Ellipticity {
        kappa: s.exp(),
        k,
        e,
        k_minus_e_over_m,
        e_minus_mc_k_over_m,
    }
}

/// The exact ellipticity for the curvature ratio `ratio = B/A ≥ 1`.
///
/// Values in `(0, 1]` are treated as 1 (a circle); callers order `A ≤ B`.
/// Input [`try_solve`] refuses (NaN, `≤ 0`, above [`MAX_RATIO`]) gives an
/// all-NaN result; use [`try_solve`] to learn why.
/// The result satisfies `B/A` to a relative error of a few ulps.
///
/// ```
/// use pegdyn::hertz::ellipticity::solve;
/// assert_eq!(solve(1.0).kappa, 1.0);
/// // Timoshenko & Goodier, §140: cos θ = (B − A)/(A + B) = 0.5 → a/b = 1.486/0.717
/// let el = solve(3.0);
/// assert!((el.kappa - 1.486 / 0.717).abs() < 0.01);
/// ```
pub fn solve(ratio: f64) -> Ellipticity {
    match try_solve(ratio) {
        Ok(el) => el,
        Err(_) => Ellipticity {
            kappa: f64::NAN,
            k: f64::NAN,
            e: f64::NAN,
            k_minus_e_over_m: f64::NAN,
            e_minus_mc_k_over_m: f64::NAN,
        },
    }
}

/// [`solve`] with its failures typed: the exact ellipticity for the
/// curvature ratio `ratio = B/A`, `1 ≤ ratio ≤` [`MAX_RATIO`] (values in
/// `(0, 1]` mean a circle).
///
/// # Errors
/// [`HertzError::Invalid`] (field `curvature_ratio`) for NaN or a ratio
/// `≤ 0`; [`HertzError::LineContact`] above [`MAX_RATIO`] (including +inf);
/// [`HertzError::NoConvergence`] if the root search does not settle within
/// [`MAX_ITERATIONS`] steps.
///
/// ```
/// use pegdyn::hertz::ellipticity::try_solve;
/// assert!(try_solve(3.0).is_ok());
/// assert!(try_solve(f64::NAN).is_err());
/// assert!(try_solve(1e200).is_err());
/// ```
pub fn try_solve(ratio: f64) -> Result<Ellipticity, HertzError> {
    if ratio.is_nan() || ratio <= 0.0 {
        return Err(HertzError::Invalid {
            field: "curvature_ratio".to_owned(),
            value: ratio,
            reason: "must be a positive number",
        });
    }
    if ratio > MAX_RATIO {
        return Err(HertzError::LineContact {
            ratio,
            limit: MAX_RATIO,
        });
    }
    // ratio ≤ 1 means "circle"; callers order A ≤ B.
    if ratio <= 1.0 {
        return Ok(from_log_kappa(0.0));
    }
    let no_convergence = HertzError::NoConvergence {
        kernel: "ellipticity solve",
        input: ratio,
        iterations: MAX_ITERATIONS,
    };
    let target = ratio.ln();
    let h = |s: f64| log_ratio(s) - target;
    // ln(B/A) grows about 1.5 times as fast as ln(a/b): the bracket [0, ln ratio]
    // holds the root whenever ratio > 1; widen it only as a safeguard, a
    // bounded number of times.
    let (mut lo, mut hi) = (0.0_f64, target.max(1e-300));
    let (mut f_lo, mut f_hi) = (h(lo), h(hi));
    let mut widenings = 0;
    while f_hi < 0.0 {
        widenings += 1;
        if widenings > 60 {
            return Err(no_convergence);
        }
        lo = hi;
        f_lo = f_hi;
        hi *= 2.0;
        f_hi = h(hi);
    }
    if !(f_lo.is_finite() && f_hi.is_finite()) {
        return Err(no_convergence);
    }
    // Illinois (modified regula falsi): superlinear, never leaves the bracket.
    let mut side = 0i8;
    let mut converged = false;
    for _ in 0..MAX_ITERATIONS {
        if hi - lo <= 4.0 * f64::EPSILON * hi {
            converged = true;
            break;
        }
        let s = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        let s = if s > lo && s < hi { s } else { 0.5 * (lo + hi) };
        let f = h(s);
        if f == 0.0 {
            return Ok(from_log_kappa(s));
        }
        if f.is_nan() {
            return Err(no_convergence);
        }
        if f < 0.0 {
            lo = s;
            f_lo = f;
            if side == -1 {
                f_hi *= 0.5;
            }
            side = -1;
        } else {
            hi = s;
            f_hi = f;
            if side == 1 {
                f_lo *= 0.5;
            }
            side = 1;
        }
    }
    let s = if f_lo.abs() < f_hi.abs() { lo } else { hi };
    let el = from_log_kappa(s);
    // Without convergence the bracket is still a valid answer if it has
    // shrunk to a few ulps of the root's function value.
    if !converged
        && f_lo.abs().min(f_hi.abs()).partial_cmp(&1e-12) != Some(std::cmp::Ordering::Less)
    {
        return Err(no_convergence);
    }
    if [
        el.kappa,
        el.k,
        el.e,
        el.k_minus_e_over_m,
        el.e_minus_mc_k_over_m,
    ]
    .iter()
    .all(|v| v.is_finite())
    {
        Ok(el)
    } else {
        Err(no_convergence)
    }
}

/// The Hamrock–Brewe curve fits (B. J. Hamrock, D. Brewe, *Simplified
/// solution for stresses and deformations*, J. Lubr. Technol. 105 (1983)
/// 171–177) for `ratio = B/A ≥ 1`:
/// `κ ≈ 1.0339 ratio^0.6360`, `E ≈ 1.0003 + 0.5968/ratio`,
/// `K ≈ 1.5277 + 0.6023 ln ratio`.
///
/// The published accuracy is a few per cent on `κ` and better on `E` and
/// `K` for `1 ≤ ratio ≤ 100`; `tests/compliant_peg/hertz.rs` measures the worst relative
/// error of `κ`, `E`, `K` and of the resulting stiffness against [`solve`]
/// and `docs/contact-geometry.md` quotes it. The two differences of
/// [`Ellipticity`] are derived from the fitted `K`, `E` and `κ`.
pub fn hamrock_brewe(ratio: f64) -> Ellipticity {
    let ratio = if ratio.is_nan() { 1.0 } else { ratio.max(1.0) };
    let kappa = 1.0339 * ratio.powf(0.6360);
    let e = 1.0003 + 0.5968 / ratio;
    let k = 1.5277 + 0.6023 * ratio.ln();
    let m = 1.0 - 1.0 / (kappa * kappa);
    // At kappa ≈ 1 the differences are 0/0: fall back to the circle's π/4.
    let (kme, emk) = if m > 1e-6 {
        ((k - e) / m, (e - (1.0 - m) * k) / m)
    } else {
        (PI / 4.0, PI / 4.0)
    };
    Ellipticity {
        kappa,
        k,
        e,
        k_minus_e_over_m: kme,
        e_minus_mc_k_over_m: emk,
    }
}

/// The deformation coefficients of the paper's (9), (10), (12) and (13).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coefficients {
    /// `m_a = (2κ²E/π)^{1/3}` of (9).
    pub m_a: f64,
    /// `m_b = (2E/(πκ))^{1/3}` of (10).
    pub m_b: f64,
    /// The approach coefficient the paper calls `K` in (13):
    /// `2K(e)/(π m_a)`; 1 for a circle.
    pub delta_star: f64,
    /// `A` of (12): `K(e)`.
    pub a_u: f64,
    /// `B` of (12): `(K − E)/e²`.
    pub b_u: f64,
    /// `C` of (12): `(E − (1 − e²)K)/e²`.
    pub c_u: f64,
}

impl Coefficients {
    /// The coefficients of an ellipticity.
    pub fn of(el: &Ellipticity) -> Coefficients {
        let m_a = (2.0 * el.kappa * el.kappa * el.e / PI).cbrt();
        let m_b = (2.0 * el.e / (PI * el.kappa)).cbrt();
        Coefficients {
            m_a,
            m_b,
            delta_star: 2.0 * el.k / (PI * m_a),
            a_u: el.k,
            b_u: el.k_minus_e_over_m,
            c_u: el.e_minus_mc_k_over_m,
        }
    }
}
