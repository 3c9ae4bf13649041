//! Forward-mode dual numbers `a + Σ bᵢ εᵢ` (`εᵢ εⱼ = 0`) with 16
//! derivative components, implementing [`Real`] so that the generated
//! straight-line functions of the 3-D peg evaluate their exact first
//! derivatives alongside their values: the chain rule of the exact
//! Jacobian ([`super::jacobian`]) seeds the 15 state components and the
//! edge angle. Every rule is the derivative of the elementary function
//! (`d sin a = cos a da`, `d √a = da / (2 √a)`, ...); the branch functions
//! (`abs`, `sign`, `max0`, `step`) take the derivative of the active
//! branch.

use crate::scalar::Real;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Number of derivative components.
pub const N: usize = 16;

/// A value with its gradient in `N` seeded variables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dual {
    /// The value.
    pub v: f64,
    /// The derivatives in the seeded variables.
    pub d: [f64; N],
}

impl PartialOrd for Dual {
    fn partial_cmp(&self, o: &Dual) -> Option<std::cmp::Ordering> {
        self.v.partial_cmp(&o.v)
    }
}

impl Dual {
    /// A constant (zero derivatives).
    pub fn constant(v: f64) -> Dual {
        Dual { v, d: [0.0; N] }
    }

    /// The variable number `k` with value `v` (derivative 1 in slot `k`).
    pub fn variable(v: f64, k: usize) -> Dual {
        let mut d = [0.0; N];
        d[k] = 1.0;
        Dual { v, d }
    }

    /// `f(self)` given `f(v)` and `f′(v)`.
    fn chain(self, value: f64, slope: f64) -> Dual {
        let mut d = self.d;
        for x in &mut d {
            *x *= slope;
        }
        Dual { v: value, d }
    }
}

impl Add for Dual {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        let mut d = self.d;
        for (x, y) in d.iter_mut().zip(o.d) {
            *x += y;
        }
        Dual { v: self.v + o.v, d }
    }
}

impl Sub for Dual {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        self + (-o)
    }
}

impl Neg for Dual {
    type Output = Dual;
    fn neg(self) -> Dual {
        self.chain(-self.v, -1.0)
    }
}

impl Mul for Dual {
    type Output = Dual;
    fn mul(self, o: Dual) -> Dual {
        let mut d = [0.0; N];
        for (k, x) in d.iter_mut().enumerate() {
            *x = self.d[k] * o.v + self.v * o.d[k];
        }
        Dual { v: self.v * o.v, d }
    }
}

impl Div for Dual {
    type Output = Dual;
    fn div(self, o: Dual) -> Dual {
        let q = self.v / o.v;
        let mut d = [0.0; N];
        for (k, x) in d.iter_mut().enumerate() {
            *x = (self.d[k] - q * o.d[k]) / o.v;
        }
        Dual { v: q, d }
    }
}

impl Real for Dual {
    fn from_f64(v: f64) -> Dual {
        Dual::constant(v)
    }
    fn to_f64(self) -> f64 {
        self.v
    }
    fn sin(self) -> Dual {
        self.chain(self.v.sin(), self.v.cos())
    }
    fn cos(self) -> Dual {
        self.chain(self.v.cos(), -self.v.sin())
    }
    fn tan(self) -> Dual {
        let t = self.v.tan();
        self.chain(t, 1.0 + t * t)
    }
    fn asin(self) -> Dual {
        self.chain(self.v.asin(), 1.0 / (1.0 - self.v * self.v).sqrt())
    }
    fn acos(self) -> Dual {
        self.chain(self.v.acos(), -1.0 / (1.0 - self.v * self.v).sqrt())
    }
    fn atan(self) -> Dual {
        self.chain(self.v.atan(), 1.0 / (1.0 + self.v * self.v))
    }
    fn atan2(self, x: Dual) -> Dual {
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
    fn exp(self) -> Dual {
        let e = self.v.exp();
        self.chain(e, e)
    }
    fn exp_m1(self) -> Dual {
        self.chain(self.v.exp_m1(), self.v.exp())
    }
    fn ln(self) -> Dual {
        self.chain(self.v.ln(), 1.0 / self.v)
    }
    fn ln_1p(self) -> Dual {
        self.chain(self.v.ln_1p(), 1.0 / (1.0 + self.v))
    }
    fn sqrt(self) -> Dual {
        let s = self.v.sqrt();
        self.chain(s, 0.5 / s)
    }
    fn cbrt(self) -> Dual {
        let c = self.v.cbrt();
        self.chain(c, 1.0 / (3.0 * c * c))
    }
    fn sin_cos(self) -> (Dual, Dual) {
        (Real::sin(self), Real::cos(self))
    }
    fn powi(self, n: i32) -> Dual {
        let slope = if n == 0 {
            0.0
        } else {
            f64::from(n) * self.v.powi(n - 1)
        };
        self.chain(self.v.powi(n), slope)
    }
    fn powf(self, e: Dual) -> Dual {
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
    fn hypot(self, y: Dual) -> Dual {
        (self * self + y * y).sqrt()
    }
    fn abs(self) -> Dual {
        if self.v < 0.0 { -self } else { self }
    }
    fn tanh(self) -> Dual {
        let t = self.v.tanh();
        self.chain(t, 1.0 - t * t)
    }
    fn sign(self) -> Dual {
        Dual::constant(Real::sign(self.v))
    }
    fn max0(self) -> Dual {
        if self.v > 0.0 {
            self
        } else {
            Dual::constant(Real::max0(self.v))
        }
    }
    fn step(self) -> Dual {
        Dual::constant(Real::step(self.v))
    }
    fn is_nan(self) -> bool {
        self.v.is_nan()
    }
}
