//! [`Dd`]: double-double arithmetic, an unevaluated sum `hi + lo` of two
//! `f64` with `|lo| ≤ ulp(hi)/2`, about 106 significant bits (unit
//! roundoff ≈ 2⁻¹⁰⁶ ≈ 1.2e-32).
//!
//! The field operations are built from error-free transformations (Knuth's
//! two-sum, Dekker's fast two-sum, and the exact product `a·b − p` from one
//! fused multiply-add): `+` and `−` have relative error ≤ 2u, `×` ≤ 4u, `÷`
//! and `sqrt` a few u (Joldes, Muller & Popescu, "Tight and rigorous error
//! bounds for basic building blocks of double-word arithmetic", ACM TOMS
//! 2017). Non-finite values propagate as in `f64` (`hi` carries the
//! infinity or NaN, `lo` is 0). The elementary functions are in
//! `dd_elementary.rs`.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A double-double number `hi + lo`.
#[derive(Clone, Copy, Debug, Default)]
pub struct Dd {
    hi: f64,
    lo: f64,
}

/// `s + e = a + b` exactly, `s = fl(a + b)` (Knuth).
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `s + e = a + b` exactly for `|a| ≥ |b|` (Dekker).
#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `p + e = a·b` exactly (one fused multiply-add).
#[inline]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Dd {
    /// Zero.
    pub const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };
    /// One.
    pub const ONE: Dd = Dd { hi: 1.0, lo: 0.0 };

    /// `hi + lo`, normalized (exact: the pair is renormalized by a two-sum).
    pub fn new(hi: f64, lo: f64) -> Dd {
        let (s, e) = two_sum(hi, lo);
        Dd::renorm(s, e)
    }

    /// A pair already normalized (`|lo| ≤ ulp(hi)/2`); for constants.
    pub(crate) const fn from_parts(hi: f64, lo: f64) -> Dd {
        Dd { hi, lo }
    }

    /// The leading part (the nearest `f64` to the value).
    pub fn hi(self) -> f64 {
        self.hi
    }

    /// The trailing part.
    pub fn lo(self) -> f64 {
        self.lo
    }

    /// `s + e` with `|s| ≥ |e|`, or the non-finite `s` alone.
    #[inline]
    fn renorm(s: f64, e: f64) -> Dd {
        if !s.is_finite() {
            return Dd { hi: s, lo: 0.0 };
        }
        let (hi, lo) = quick_two_sum(s, e);
        Dd { hi, lo }
    }

    /// `self · x` for an `f64` `x`.
    #[inline]
    pub fn mul_f64(self, x: f64) -> Dd {
        let (p, e) = two_prod(self.hi, x);
        Dd::renorm(p, e + self.lo * x)
    }

    /// `self · 2^k`, exact (barring overflow or underflow).
    pub fn mul_pow2(self, k: i32) -> Dd {
        let s = 2f64.powi(k);
        Dd {
            hi: self.hi * s,
            lo: self.lo * s,
        }
    }

    /// `self²`.
    #[inline]
    pub fn square(self) -> Dd {
        self * self
    }

    /// True when both parts are finite.
    pub fn is_finite(self) -> bool {
        self.hi.is_finite()
    }

    /// Square root, Newton-corrected from the `f64` root.
    pub fn sqrt(self) -> Dd {
        if self.hi <= 0.0 || !self.hi.is_finite() {
            // 0, -0, negative (NaN), +inf and NaN as f64 does.
            return Dd::from(self.hi.sqrt());
        }
        let y = self.hi.sqrt();
        let (p, e) = two_prod(y, y);
        let r = (self - Dd { hi: p, lo: e }).hi;
        Dd::renorm(y, r / (2.0 * y))
    }

    /// Cube root (real, odd: `cbrt(−x) = −cbrt(x)`), Newton-corrected from
    /// the `f64` root: one step `y + (x − y³)/(3y²)` doubles the 53 bits.
    pub fn cbrt(self) -> Dd {
        if self.hi == 0.0 || !self.hi.is_finite() {
            return Dd::from(self.hi.cbrt());
        }
        let y = Dd::from(self.hi.cbrt());
        let r = self - y.square() * y;
        y + r / (y.square() * Dd::from(3.0))
    }
}

impl From<f64> for Dd {
    fn from(v: f64) -> Dd {
        Dd { hi: v, lo: 0.0 }
    }
}

impl From<Dd> for f64 {
    fn from(v: Dd) -> f64 {
        v.hi
    }
}

impl PartialEq for Dd {
    fn eq(&self, other: &Dd) -> bool {
        self.hi == other.hi && self.lo == other.lo
    }
}

impl PartialOrd for Dd {
    fn partial_cmp(&self, other: &Dd) -> Option<Ordering> {
        match self.hi.partial_cmp(&other.hi)? {
            Ordering::Equal => self.lo.partial_cmp(&other.lo),
            o => Some(o),
        }
    }
}

impl fmt::Display for Dd {
    /// `hi + lo` with both parts in full (e.g. `3.141592653589793e0 + 1.2246467991473532e-16`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:e} + {:e}", self.hi, self.lo)
    }
}

impl Neg for Dd {
    type Output = Dd;
    #[inline]
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Add for Dd {
    type Output = Dd;
    /// The accurate ("IEEE-style") double-double sum: relative error ≤ 3u².
    #[inline]
    fn add(self, b: Dd) -> Dd {
        let (s1, s2) = two_sum(self.hi, b.hi);
        if !s1.is_finite() {
            return Dd::from(s1);
        }
        let (t1, t2) = two_sum(self.lo, b.lo);
        let (s1, s2) = quick_two_sum(s1, s2 + t1);
        Dd::renorm(s1, s2 + t2)
    }
}

impl Sub for Dd {
    type Output = Dd;
    #[inline]
    fn sub(self, b: Dd) -> Dd {
        self + (-b)
    }
}

impl Mul for Dd {
    type Output = Dd;
    #[inline]
    fn mul(self, b: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, b.hi);
        Dd::renorm(p, e + (self.hi * b.lo + self.lo * b.hi))
    }
}

impl Div for Dd {
    type Output = Dd;
    /// Long division with three quotient digits.
    #[inline]
    fn div(self, b: Dd) -> Dd {
        let q1 = self.hi / b.hi;
        if !q1.is_finite() || q1 == 0.0 {
            return Dd::from(q1);
        }
        let r = self - b.mul_f64(q1);
        let q2 = r.hi / b.hi;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi / b.hi;
        let (q1, q2) = quick_two_sum(q1, q2);
        Dd { hi: q1, lo: q2 } + Dd::from(q3)
    }
}
