//! Elementary functions of [`Dd`] and its [`Real`] implementation.
//!
//! Method (accuracy target: a few 1e-32 relative, checked in
//! `tests/generator/scalar_dd.rs` against values computed independently at 300 bits):
//! - `exp`, `exp_m1`: `x = k ln2 + r` (ln 2 in three parts), `r/2¹⁰` by its
//!   Taylor series for `e^r − 1`, then ten doublings `s ← s(s + 2)`, which
//!   keep the relative accuracy of `e^r − 1` (no cancellation near 0);
//! - `ln`, `ln_1p`: `x = 2^k m`, `m ∈ [√½, √2)`, `ln m = 2 atanh(z)` with
//!   `z = (m − 1)/(m + 1)` (`|z| ≤ 0.172`) by its series; `ln_1p` uses
//!   `z = x/(2 + x)` directly for small `x`, so both are accurate near 1;
//! - `sin`, `cos`: `x = k π/2 + r` (π/2 in three parts, exact products),
//!   Taylor series on `|r| ≤ π/4`; accurate for `|x| < 2²⁰`;
//! - `atan2` (and `atan`, `asin`, `acos` through it): two Newton steps on
//!   `sin z = y/ρ` or `cos z = x/ρ` from the `f64` `atan2`;
//! - `tanh` from `exp_m1`; `powf = exp(e ln x)`; `powi` by squaring.

use super::Real;
use super::dd::{Dd, two_prod};

/// ln 2 in three parts (their sum is ln 2 to 160 bits).
const LN2: [f64; 3] = [
    std::f64::consts::LN_2,
    2.3190468138462996e-17,
    5.707708438416212e-34,
];
/// π/2 in three parts.
const PI_2: [f64; 3] = [
    std::f64::consts::FRAC_PI_2,
    6.123233995736766e-17,
    -1.4973849048591698e-33,
];
/// π/2 as a double-double.
const PI_2_DD: Dd = Dd::from_parts(PI_2[0], PI_2[1]);

/// `x − k·(c₀ + c₁ + c₂)` for an integer-valued `k`, with exact products.
fn reduce(x: Dd, k: f64, c: [f64; 3]) -> Dd {
    let (p0, e0) = two_prod(k, c[0]);
    let (p1, e1) = two_prod(k, c[1]);
    x - Dd::new(p0, e0) - Dd::new(p1, e1) - Dd::from(k * c[2])
}

/// `e^r − 1` for `|r| ≤ ln2/2`: series on `r/2¹⁰`, then doublings.
fn expm1_reduced(r: Dd) -> Dd {
    const HALVINGS: i32 = 10;
    let r = r.mul_pow2(-HALVINGS);
    let mut term = r;
    let mut sum = r;
    for n in 2..30 {
        term = term * r / Dd::from(f64::from(n));
        sum = sum + term;
        if term.hi().abs() <= 1e-36 * sum.hi().abs() {
            break;
        }
    }
    for _ in 0..HALVINGS {
        sum = sum * (sum + Dd::from(2.0));
    }
    sum
}

/// `2 atanh(z) = ln((1 + z)/(1 − z))` for `|z| ≤ 0.2`, by its series.
fn two_atanh(z: Dd) -> Dd {
    let z2 = z.square();
    let mut power = z;
    let mut sum = z;
    for n in 1..60 {
        power = power * z2;
        let term = power / Dd::from(f64::from(2 * n + 1));
        sum = sum + term;
        if term.hi().abs() <= 1e-36 * sum.hi().abs() {
            break;
        }
    }
    sum.mul_pow2(1)
}

/// `(sin r, cos r)` for `|r| ≤ π/4`, by their Taylor series.
fn sin_cos_reduced(r: Dd) -> (Dd, Dd) {
    let r2 = r.square();
    let (mut s_term, mut s) = (r, r);
    let (mut c_term, mut c) = (Dd::ONE, Dd::ONE);
    for n in 1..40 {
        let k = f64::from(2 * n);
        s_term = -(s_term * r2) / Dd::from(k * (k + 1.0));
        c_term = -(c_term * r2) / Dd::from(k * (k - 1.0));
        s = s + s_term;
        c = c + c_term;
        if c_term.hi().abs() <= 1e-36 && s_term.hi().abs() <= 1e-36 * s.hi().abs() {
            break;
        }
    }
    (s, c)
}

impl Dd {
    /// `(sin x, cos x)`.
    pub fn sin_cos(self) -> (Dd, Dd) {
        if !self.is_finite() {
            return (Dd::from(f64::NAN), Dd::from(f64::NAN));
        }
        let k = (self.hi() / PI_2[0]).round();
        let r = reduce(self, k, PI_2);
        let (s, c) = sin_cos_reduced(r);
        match (k.rem_euclid(4.0)) as u8 {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }

    /// `e^x`.
    pub fn exp(self) -> Dd {
        if self.hi() > 709.8 {
            return Dd::from(f64::INFINITY);
        }
        if self.hi() < -745.2 {
            return Dd::ZERO;
        }
        if self.hi().is_nan() {
            return self;
        }
        let k = (self.hi() / LN2[0]).round();
        let s = expm1_reduced(reduce(self, k, LN2));
        (s + Dd::ONE).mul_pow2(k as i32)
    }

    /// `e^x − 1`.
    pub fn exp_m1(self) -> Dd {
        if self.hi().abs() <= 0.5 * LN2[0] {
            expm1_reduced(self)
        } else {
            self.exp() - Dd::ONE
        }
    }

    /// Natural logarithm.
    pub fn ln(self) -> Dd {
        let x = self.hi();
        if x.is_nan() || x <= 0.0 || x == f64::INFINITY {
            return Dd::from(x.ln());
        }
        // x = 2^k m with m in [√½, √2).
        let mut k = x.log2().round();
        let mut m = self.mul_pow2(-(k as i32));
        if m.hi() >= std::f64::consts::SQRT_2 {
            m = m.mul_pow2(-1);
            k += 1.0;
        } else if m.hi() < std::f64::consts::FRAC_1_SQRT_2 {
            m = m.mul_pow2(1);
            k -= 1.0;
        }
        let z = (m - Dd::ONE) / (m + Dd::ONE);
        two_atanh(z) + reduce(Dd::ZERO, -k, LN2)
    }

    /// `ln(1 + x)`.
    pub fn ln_1p(self) -> Dd {
        if self.hi().abs() < 0.25 {
            two_atanh(self / (Dd::from(2.0) + self))
        } else {
            (Dd::ONE + self).ln()
        }
    }

    /// `atan2(self, x)` with `f64`'s conventions at zeros and infinities.
    pub fn atan2(self, x: Dd) -> Dd {
        let y = self;
        if y.hi() == 0.0 || !y.is_finite() || !x.is_finite() || x.hi() == 0.0 {
            let z = y.hi().atan2(x.hi());
            // Exact multiples of π/2 where the f64 result is one.
            return match z {
                _ if z == std::f64::consts::FRAC_PI_2 => PI_2_DD,
                _ if z == -std::f64::consts::FRAC_PI_2 => -PI_2_DD,
                _ if z == std::f64::consts::PI => PI_2_DD.mul_pow2(1),
                _ if z == -std::f64::consts::PI => -PI_2_DD.mul_pow2(1),
                _ => Dd::from(z),
            };
        }
        let rho = y.hypot(x);
        let (xx, yy) = (x / rho, y / rho);
        let mut z = Dd::from(y.hi().atan2(x.hi()));
        for _ in 0..2 {
            let (s, c) = z.sin_cos();
            if xx.hi().abs() > yy.hi().abs() {
                z = z + (yy - s) / c;
            } else {
                z = z - (xx - c) / s;
            }
        }
        z
    }

    /// `hypot(self, y)`.
    pub fn hypot(self, y: Dd) -> Dd {
        let (a, b) = (self.abs(), y.abs());
        let (big, small) = if a >= b { (a, b) } else { (b, a) };
        if big.hi() == 0.0 || !big.is_finite() || small.hi().is_nan() {
            return Dd::from(self.hi().hypot(y.hi()));
        }
        let q = small / big;
        big * (Dd::ONE + q.square()).sqrt()
    }

    /// `|x|`.
    pub fn abs(self) -> Dd {
        if self.hi() < 0.0 { -self } else { self }
    }

    /// `x^n` by binary powering.
    pub fn powi(self, n: i32) -> Dd {
        let mut base = self;
        let mut e = n.unsigned_abs();
        let mut acc = Dd::ONE;
        while e > 0 {
            if e & 1 == 1 {
                acc = acc * base;
            }
            base = base.square();
            e >>= 1;
        }
        if n < 0 { Dd::ONE / acc } else { acc }
    }

    /// `x^e = exp(e ln x)`; `f64`'s conventions for `x ≤ 0`.
    pub fn powf(self, e: Dd) -> Dd {
        let x = self.hi();
        if x == 0.0 || !self.is_finite() || !e.is_finite() {
            return Dd::from(x.powf(e.hi()));
        }
        if x < 0.0 {
            if e.hi().fract() != 0.0 || e.lo() != 0.0 {
                return Dd::from(f64::NAN);
            }
            let r = (-self).powf(e);
            return if e.hi().rem_euclid(2.0) == 1.0 { -r } else { r };
        }
        (e * self.ln()).exp()
    }
}

impl Real for Dd {
    fn from_f64(v: f64) -> Dd {
        Dd::from(v)
    }
    fn to_f64(self) -> f64 {
        self.hi()
    }
    fn sin(self) -> Dd {
        self.sin_cos().0
    }
    fn cos(self) -> Dd {
        self.sin_cos().1
    }
    fn tan(self) -> Dd {
        let (s, c) = self.sin_cos();
        s / c
    }
    fn asin(self) -> Dd {
        if self.hi().abs() > 1.0 {
            return Dd::from(f64::NAN);
        }
        self.atan2(((Dd::ONE - self) * (Dd::ONE + self)).sqrt())
    }
    fn acos(self) -> Dd {
        if self.hi().abs() > 1.0 {
            return Dd::from(f64::NAN);
        }
        ((Dd::ONE - self) * (Dd::ONE + self)).sqrt().atan2(self)
    }
    fn atan(self) -> Dd {
        self.atan2(Dd::ONE)
    }
    fn atan2(self, x: Dd) -> Dd {
        Dd::atan2(self, x)
    }
    fn exp(self) -> Dd {
        Dd::exp(self)
    }
    fn exp_m1(self) -> Dd {
        Dd::exp_m1(self)
    }
    fn ln(self) -> Dd {
        Dd::ln(self)
    }
    fn ln_1p(self) -> Dd {
        Dd::ln_1p(self)
    }
    fn sqrt(self) -> Dd {
        Dd::sqrt(self)
    }
    fn cbrt(self) -> Dd {
        Dd::cbrt(self)
    }
    fn sin_cos(self) -> (Dd, Dd) {
        Dd::sin_cos(self)
    }
    fn powi(self, n: i32) -> Dd {
        Dd::powi(self, n)
    }
    fn powf(self, e: Dd) -> Dd {
        Dd::powf(self, e)
    }
    fn hypot(self, y: Dd) -> Dd {
        Dd::hypot(self, y)
    }
    fn abs(self) -> Dd {
        Dd::abs(self)
    }
    fn tanh(self) -> Dd {
        if self.hi().abs() > 40.0 {
            return Dd::from(self.hi().signum());
        }
        let t = self.mul_pow2(1).exp_m1();
        t / (t + Dd::from(2.0))
    }
    fn sign(self) -> Dd {
        Dd::from(self.hi().sign())
    }
    fn max0(self) -> Dd {
        if self.hi() > 0.0 || self.hi().is_nan() {
            self
        } else {
            Dd::ZERO
        }
    }
    fn step(self) -> Dd {
        Dd::from(self.hi().step())
    }
    fn is_nan(self) -> bool {
        self.hi().is_nan()
    }
}
