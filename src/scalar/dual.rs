//! Forward-mode dual numbers `a + Σ bᵢ εᵢ` (`εᵢ εⱼ = 0`) with `N`
//! derivative components, implementing [`Real`] so that generated
//! straight-line functions and hand-written laws generic over the scalar
//! evaluate their exact first derivatives alongside their values (the
//! compliant 3-D peg's exact Jacobian seeds its 15 state components and
//! an edge angle in `Dual<16>`). Every rule is the derivative of the
//! elementary function (`d sin a = cos a da`, `d √a = da / (2 √a)`, ...);
//! the branch functions (`abs`, `sign`, `max0`, `step`) take the
//! derivative of the active branch.
//!
//! ```
//! use pegdyn::scalar::{Dual, Real};
//! // d/dx (x sin x) at x = 2: sin 2 + 2 cos 2.
//! let x = Dual::<1>::variable(2.0, 0);
//! let y = x * x.sin();
//! assert!((y.d[0] - (2f64.sin() + 2.0 * 2f64.cos())).abs() < 1e-15);
//! ```

use super::Real;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A value with its gradient in `N` seeded variables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dual<const N: usize> {
    /// The value.
    pub v: f64,
    /// The derivatives in the seeded variables.
    pub d: [f64; N],
}

impl<const N: usize> PartialOrd for Dual<N> {
    #[inline]
    fn partial_cmp(&self, o: &Dual<N>) -> Option<std::cmp::Ordering> {
        self.v.partial_cmp(&o.v)
    }
}

impl<const N: usize> Dual<N> {
    /// A constant (zero derivatives).
    #[inline]
    pub fn constant(v: f64) -> Dual<N> {
        Dual { v, d: [0.0; N] }
    }

    /// The variable number `k` with value `v` (derivative 1 in slot `k`).
    #[inline]
    pub fn variable(v: f64, k: usize) -> Dual<N> {
        let mut d = [0.0; N];
        d[k] = 1.0;
        Dual { v, d }
    }

    /// `f(self)` given `f(v)` and `f′(v)`.
    #[inline]
    fn chain(self, value: f64, slope: f64) -> Dual<N> {
        let mut d = self.d;
        for x in &mut d {
            *x *= slope;
        }
        Dual { v: value, d }
    }
}

impl<const N: usize> Add for Dual<N> {
    type Output = Dual<N>;
    #[inline]
    fn add(self, o: Dual<N>) -> Dual<N> {
        let mut d = self.d;
        for (x, y) in d.iter_mut().zip(o.d) {
            *x += y;
        }
        Dual { v: self.v + o.v, d }
    }
}

impl<const N: usize> Sub for Dual<N> {
    type Output = Dual<N>;
    #[inline]
    fn sub(self, o: Dual<N>) -> Dual<N> {
        let mut d = self.d;
        for (x, y) in d.iter_mut().zip(o.d) {
            *x -= y;
        }
        Dual { v: self.v - o.v, d }
    }
}

impl<const N: usize> Neg for Dual<N> {
    type Output = Dual<N>;
    #[inline]
    fn neg(self) -> Dual<N> {
        self.chain(-self.v, -1.0)
    }
}

impl<const N: usize> Mul for Dual<N> {
    type Output = Dual<N>;
    #[inline]
    fn mul(self, o: Dual<N>) -> Dual<N> {
        let mut d = [0.0; N];
        for (k, x) in d.iter_mut().enumerate() {
            *x = self.d[k] * o.v + self.v * o.d[k];
        }
        Dual { v: self.v * o.v, d }
    }
}

impl<const N: usize> Div for Dual<N> {
    type Output = Dual<N>;
    #[inline]
    fn div(self, o: Dual<N>) -> Dual<N> {
        let q = self.v / o.v;
        let mut d = [0.0; N];
        for (k, x) in d.iter_mut().enumerate() {
            *x = (self.d[k] - q * o.d[k]) / o.v;
        }
        Dual { v: q, d }
    }
}

impl<const N: usize> Real for Dual<N> {
    #[inline]
    fn from_f64(v: f64) -> Dual<N> {
        Dual::constant(v)
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self.v
    }
    #[inline]
    fn sin(self) -> Dual<N> {
        self.chain(self.v.sin(), self.v.cos())
    }
    #[inline]
    fn cos(self) -> Dual<N> {
        self.chain(self.v.cos(), -self.v.sin())
    }
    #[inline]
    fn tan(self) -> Dual<N> {
        let t = self.v.tan();
        self.chain(t, 1.0 + t * t)
    }
    #[inline]
    fn asin(self) -> Dual<N> {
        self.chain(self.v.asin(), 1.0 / (1.0 - self.v * self.v).sqrt())
    }
    #[inline]
    fn acos(self) -> Dual<N> {
        self.chain(self.v.acos(), -1.0 / (1.0 - self.v * self.v).sqrt())
    }
    #[inline]
    fn atan(self) -> Dual<N> {
        self.chain(self.v.atan(), 1.0 / (1.0 + self.v * self.v))
    }
    #[inline]
    fn atan2(self, x: Dual<N>) -> Dual<N> {
        // d atan2(y, x) = (x dy − y dx) / (x² + y²)
        let r2 = self.v * self.v + x.v * x.v;
        let mut d = [0.0; N];
        for (k, e) in d.iter_mut().enumerate() {
            *e = (x.v * self.d[k] - self.v * x.d[k]) / r2;
        }
        Dual {
            v: self.v.atan2(x.v),
            d,
        }
    }
    #[inline]
    fn exp(self) -> Dual<N> {
        let e = self.v.exp();
        self.chain(e, e)
    }
    #[inline]
    fn exp_m1(self) -> Dual<N> {
        self.chain(self.v.exp_m1(), self.v.exp())
    }
    #[inline]
    fn ln(self) -> Dual<N> {
        self.chain(self.v.ln(), 1.0 / self.v)
    }
    #[inline]
    fn ln_1p(self) -> Dual<N> {
        self.chain(self.v.ln_1p(), 1.0 / (1.0 + self.v))
    }
    #[inline]
    fn sqrt(self) -> Dual<N> {
        let s = self.v.sqrt();
        self.chain(s, 0.5 / s)
    }
    #[inline]
    fn cbrt(self) -> Dual<N> {
        let c = self.v.cbrt();
        self.chain(c, 1.0 / (3.0 * c * c))
    }
    #[inline]
    fn sin_cos(self) -> (Dual<N>, Dual<N>) {
        (Real::sin(self), Real::cos(self))
    }
    #[inline]
    fn powi(self, n: i32) -> Dual<N> {
        let slope = if n == 0 {
            0.0
        } else {
            f64::from(n) * self.v.powi(n - 1)
        };
        self.chain(self.v.powi(n), slope)
    }
    #[inline]
    fn powf(self, e: Dual<N>) -> Dual<N> {
        // d a^e = e a^(e−1) da + a^e ln a de (the second term only where e varies).
        let val = self.v.powf(e.v);
        let da = e.v * self.v.powf(e.v - 1.0);
        let de = if e.d.iter().any(|&x| x != 0.0) {
            val * self.v.ln()
        } else {
            0.0
        };
        let mut d = [0.0; N];
        for (k, x) in d.iter_mut().enumerate() {
            *x = da * self.d[k] + de * e.d[k];
        }
        Dual { v: val, d }
    }
    #[inline]
    fn hypot(self, y: Dual<N>) -> Dual<N> {
        (self * self + y * y).sqrt()
    }
    #[inline]
    fn abs(self) -> Dual<N> {
        if self.v < 0.0 { -self } else { self }
    }
    #[inline]
    fn tanh(self) -> Dual<N> {
        let t = self.v.tanh();
        self.chain(t, 1.0 - t * t)
    }
    #[inline]
    fn sign(self) -> Dual<N> {
        Dual::constant(Real::sign(self.v))
    }
    #[inline]
    fn max0(self) -> Dual<N> {
        if self.v > 0.0 {
            self
        } else {
            Dual::constant(Real::max0(self.v))
        }
    }
    #[inline]
    fn step(self) -> Dual<N> {
        Dual::constant(Real::step(self.v))
    }
    #[inline]
    fn is_nan(self) -> bool {
        self.v.is_nan()
    }
}
