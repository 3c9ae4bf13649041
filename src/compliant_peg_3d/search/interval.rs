//! Closed intervals of reals with outward rounding: the enclosures of the
//! certified search.
//!
//! Every operation returns an interval that contains the exact result of
//! the operation on any reals in its operands. In round-to-nearest each
//! `f64` operation (`+`, `−`, `×`, `÷`, `√`) errs by at most half an ulp
//! of its result, so each computed bound is moved outwards by [`down`] or
//! [`up`], which step it by more than an ulp (`|x| · 2⁻⁵¹` plus the
//! smallest normal number, which covers the subnormal range).

/// `x` moved down by more than one ulp (`x − |x| 2⁻⁵¹ − 2⁻¹⁰²²`; a
/// rounded `x − d` with `d ≥ ulp(x)` is below `x` by at least half of `d`).
pub fn down(x: f64) -> f64 {
    x - (x.abs() * f64::EPSILON * 2.0 + f64::MIN_POSITIVE)
}

/// `x` moved up by more than one ulp (see [`down`]).
pub fn up(x: f64) -> f64 {
    x + (x.abs() * f64::EPSILON * 2.0 + f64::MIN_POSITIVE)
}

/// The closed interval `[lo, hi]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iv {
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
}

impl Iv {
    /// `[lo, hi]` as given (callers guarantee `lo ≤ hi`).
    pub const fn new(lo: f64, hi: f64) -> Iv {
        Iv { lo, hi }
    }

    /// Every real: what is known of a quantity that cannot be bounded.
    pub const ALL: Iv = Iv::new(f64::NEG_INFINITY, f64::INFINITY);

    /// `[c − r, c + r]` rounded outwards (`r ≥ 0`).
    pub fn around(c: f64, r: f64) -> Iv {
        Iv::new(down(c - r), up(c + r))
    }

    /// `max(|lo|, |hi|)`: the largest magnitude in the interval.
    pub fn mag(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// The intersection with `o` (both contain the same quantity, so it is
    /// not empty).
    pub fn meet(self, o: Iv) -> Iv {
        Iv::new(self.lo.max(o.lo), self.hi.min(o.hi))
    }

    /// The midpoint: a float value of the enclosed quantity.
    pub fn mid(self) -> f64 {
        0.5 * self.lo + 0.5 * self.hi
    }

    /// Whether the interval contains no zero.
    pub fn excludes_zero(self) -> bool {
        self.lo > 0.0 || self.hi < 0.0
    }

    /// The interval shifted by the real `c`.
    pub fn plus(self, c: f64) -> Iv {
        Iv::new(down(self.lo + c), up(self.hi + c))
    }

    /// `self · c` for a real `c`.
    pub fn scale(self, c: f64) -> Iv {
        let (a, b) = (self.lo * c, self.hi * c);
        Iv::new(down(a.min(b)), up(a.max(b)))
    }

    /// `{x² : x ∈ self}` (tight when the interval contains zero).
    pub fn square(self) -> Iv {
        if self.lo >= 0.0 {
            Iv::new(down(self.lo * self.lo), up(self.hi * self.hi))
        } else if self.hi <= 0.0 {
            Iv::new(down(self.hi * self.hi), up(self.lo * self.lo))
        } else {
            let m = self.lo.abs().max(self.hi);
            Iv::new(0.0, up(m * m))
        }
    }

    /// `c / self` for a real `c ≥ 0` and an interval of positive reals.
    pub fn recip_times(self, c: f64) -> Iv {
        Iv::new(down(c / self.hi), up(c / self.lo))
    }

    /// `√self` of the non-negative part of the interval.
    pub fn sqrt(self) -> Iv {
        Iv::new(down(self.lo.max(0.0).sqrt()).max(0.0), up(self.hi.sqrt()))
    }
}

impl std::ops::Add for Iv {
    type Output = Iv;

    /// `self + o`.
    fn add(self, o: Iv) -> Iv {
        Iv::new(down(self.lo + o.lo), up(self.hi + o.hi))
    }
}

impl std::ops::Sub for Iv {
    type Output = Iv;

    /// `self − o`.
    fn sub(self, o: Iv) -> Iv {
        Iv::new(down(self.lo - o.hi), up(self.hi - o.lo))
    }
}

impl std::ops::Mul for Iv {
    type Output = Iv;

    /// `self · o`.
    fn mul(self, o: Iv) -> Iv {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Iv::new(down(lo), up(hi))
    }
}
