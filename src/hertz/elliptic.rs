//! Complete elliptic integrals through Carlson's symmetric forms.
//!
//! Hertz's elliptical contact needs `K(e)` and `E(e)` of the ellipse's
//! eccentricity `e` (parameter `m = e²`), and — for very elongated ellipses,
//! `1 − m` down to `1e-14` — the differences `K − E` and `E − (1 − m) K`
//! without cancellation. Carlson's forms give all of them directly
//! (DLMF 19.25.1):
//!
//! - `K(m) = R_F(0, 1 − m, 1)`
//! - `K(m) − E(m) = (m/3) R_D(0, 1 − m, 1)`
//! - `E(m) − (1 − m) K(m) = (m (1 − m)/3) R_D(0, 1, 1 − m)`
//!
//! `R_F` and `R_D` are computed by Carlson's duplication algorithm (B. C.
//! Carlson, *Numerical computation of real or complex elliptic integrals*,
//! Numer. Algorithms 10 (1995) 13–26) to a relative error of about `1e-16`.

/// Largest relative spread of the arguments at which the duplication stops
/// and the fifth-order series takes over; the truncation error is of order
/// `TOL⁶ ≈ 1e-18`.
const TOL: f64 = 1e-3;

/// Iteration cap of the duplication loops. Each duplication divides the
/// relative spread of the arguments by about 4, so valid arguments (finite,
/// at most one zero, ratios within the f64 range) converge in fewer than 40
/// steps; arguments outside the domain return NaN at the cap instead of
/// looping forever.
pub const MAX_DUPLICATIONS: usize = 100;

/// Whether `(x, y, z)` lies in the domain of `R_F` (all finite and `≥ 0`,
/// at most one of them zero).
fn rf_domain(x: f64, y: f64, z: f64) -> bool {
    let zeros = [x, y, z].iter().filter(|v| **v == 0.0).count();
    [x, y, z].iter().all(|v| v.is_finite() && *v >= 0.0) && zeros <= 1
}

/// Carlson's symmetric integral
/// `R_F(x, y, z) = ½ ∫₀^∞ dt / √((t + x)(t + y)(t + z))`,
/// for `x, y, z ≥ 0` with at most one of them zero.
///
/// Returns NaN outside that domain (negative, non-finite, or two zero
/// arguments) and if the duplication does not settle within
/// [`MAX_DUPLICATIONS`] steps; it never loops unboundedly.
pub fn carlson_rf(x: f64, y: f64, z: f64) -> f64 {
    if !rf_domain(x, y, z) {
        return f64::NAN;
    }
    let (mut x, mut y, mut z) = (x, y, z);
    for _ in 0..MAX_DUPLICATIONS {
        let a = (x + y + z) / 3.0;
        let (dx, dy, dz) = (1.0 - x / a, 1.0 - y / a, 1.0 - z / a);
        if dx.abs().max(dy.abs()).max(dz.abs()) < TOL {
            let e2 = dx * dy - dz * dz;
            let e3 = dx * dy * dz;
            let series = 1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0;
            return series / a.sqrt();
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * sy + sx * sz + sy * sz;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
    }
    f64::NAN
}

/// Carlson's symmetric integral of the second kind
/// `R_D(x, y, z) = (3/2) ∫₀^∞ dt / (√((t + x)(t + y)) (t + z)^{3/2})`,
/// for `x, y ≥ 0` (not both zero) and `z > 0`.
///
/// Returns NaN outside that domain and if the duplication does not settle
/// within [`MAX_DUPLICATIONS`] steps.
pub fn carlson_rd(x: f64, y: f64, z: f64) -> f64 {
    if !(rf_domain(x, y, z) && z > 0.0) {
        return f64::NAN;
    }
    let (mut x, mut y, mut z) = (x, y, z);
    let mut sum = 0.0;
    let mut fac = 1.0;
    for _ in 0..MAX_DUPLICATIONS {
        let a = (x + y + 3.0 * z) / 5.0;
        let (dx, dy, dz) = (1.0 - x / a, 1.0 - y / a, 1.0 - z / a);
        if dx.abs().max(dy.abs()).max(dz.abs()) < TOL {
            let xy = dx * dy;
            let z2 = dz * dz;
            let e2 = xy - 6.0 * z2;
            let e3 = (3.0 * xy - 8.0 * z2) * dz;
            let e4 = 3.0 * (xy - z2) * z2;
            let e5 = xy * z2 * dz;
            let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
                - 3.0 * e4 / 22.0
                - 9.0 * e2 * e3 / 52.0
                + 3.0 * e5 / 26.0;
            return 3.0 * sum + fac * series / (a * a.sqrt());
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * sy + sx * sz + sy * sz;
        sum += fac / (sz * (z + lambda));
        fac *= 0.25;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
    }
    f64::NAN
}

/// The complete elliptic integrals of one parameter, with the two
/// differences Hertz theory needs, each free of cancellation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompleteIntegrals {
    /// `K(m) = ∫₀^{π/2} dφ / √(1 − m sin²φ)`.
    pub k: f64,
    /// `E(m) = ∫₀^{π/2} √(1 − m sin²φ) dφ`.
    pub e: f64,
    /// `(K − E)/m`, finite (`π/4`) at `m = 0`.
    pub k_minus_e_over_m: f64,
    /// `(E − (1 − m) K)/m`, finite (`π/4`) at `m = 0`.
    pub e_minus_mc_k_over_m: f64,
}

/// `K`, `E` and the two differences at parameter `m = e²` given through its
/// complement `mc = 1 − m` (pass the complement so that `m` close to 1 keeps
/// its digits). Requires `0 < mc ≤ 1`; outside it (or for NaN) every
/// field is NaN.
///
/// ```
/// use pegdyn::hertz::elliptic::complete_integrals;
/// let i = complete_integrals(0.5);
/// assert!((i.k - 1.854_074_677_301_372).abs() < 1e-15);
/// assert!((i.e - 1.350_643_881_047_675_5).abs() < 1e-15);
/// ```
pub fn complete_integrals(mc: f64) -> CompleteIntegrals {
    if !(mc > 0.0 && mc <= 1.0) {
        return CompleteIntegrals {
            k: f64::NAN,
            e: f64::NAN,
            k_minus_e_over_m: f64::NAN,
            e_minus_mc_k_over_m: f64::NAN,
        };
    }
    let m = 1.0 - mc;
    let k = carlson_rf(0.0, mc, 1.0);
    let k_minus_e_over_m = carlson_rd(0.0, mc, 1.0) / 3.0;
    let e_minus_mc_k_over_m = mc * carlson_rd(0.0, 1.0, mc) / 3.0;
    CompleteIntegrals {
        k,
        e: k - m * k_minus_e_over_m,
        k_minus_e_over_m,
        e_minus_mc_k_over_m,
    }
}
