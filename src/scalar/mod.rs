//! The scalar types generated code runs on.
//!
//! Every function in [`crate::generated`] is generic over [`Real`]: at `f64`
//! it compiles to the same code as a non-generic `f64` function (each method is the `std` one,
//! `#[inline]`), and at [`Dd`] (double-double, about 106 significant bits)
//! the same straight-line formula is evaluated with a unit roundoff of about
//! 1e-32, which is the reference `pegdyn accuracy` measures `f64` against.
//! At [`Dual`] (forward-mode dual numbers) it evaluates its exact first
//! derivatives in the seeded variables alongside its value.
//!
//! ```
//! use pegdyn::scalar::{Dd, Real};
//! let x = Dd::from_f64(2.0).sqrt();
//! let r = x * x - Dd::from_f64(2.0);
//! assert!(r.to_f64().abs() < 1e-31);
//! ```

mod dd;
mod dd_elementary;
mod dual;
mod real_f64;

pub use dd::Dd;
pub use dual::Dual;

use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// What generated code needs of a scalar: copyable nalgebra scalar, field
/// operations, the functions the emitter writes, and exact conversion of
/// `f64` constants.
///
/// The semantics of [`Real::max0`], [`Real::step`] and [`Real::sign`] are
/// those of the generator's interpreter (`pegdyn_equations::eval::unary`):
/// NaN propagates, `step(0) = 0`, `sign(0) = 0`.
pub trait Real:
    Copy
    + Debug
    + PartialEq
    + PartialOrd
    + nalgebra::Scalar
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The constant `v` (exact: every `f64` is representable).
    fn from_f64(v: f64) -> Self;
    /// The nearest `f64`.
    fn to_f64(self) -> f64;
    /// Sine (argument in radians).
    fn sin(self) -> Self;
    /// Cosine (argument in radians).
    fn cos(self) -> Self;
    /// Tangent (argument in radians).
    fn tan(self) -> Self;
    /// Arcsine, in [−π/2, π/2] rad.
    fn asin(self) -> Self;
    /// Arccosine, in [0, π] rad.
    fn acos(self) -> Self;
    /// Arctangent, in (−π/2, π/2) rad.
    fn atan(self) -> Self;
    /// `atan2(self, x)`, `self` the ordinate.
    fn atan2(self, x: Self) -> Self;
    /// `e^self`.
    fn exp(self) -> Self;
    /// `exp(self) − 1`, accurate near 0.
    fn exp_m1(self) -> Self;
    /// Natural logarithm.
    fn ln(self) -> Self;
    /// `ln(1 + self)`, accurate near 0.
    fn ln_1p(self) -> Self;
    /// Square root.
    fn sqrt(self) -> Self;
    /// Real cube root (`cbrt(−x) = −cbrt(x)`); the generator emits it for
    /// the exponent 1/3.
    fn cbrt(self) -> Self;
    /// `(sin self, cos self)` in one call; the generator emits it when both
    /// are used.
    fn sin_cos(self) -> (Self, Self);
    /// `self^n` for an integer `n`.
    fn powi(self, n: i32) -> Self;
    /// `self^e` for a real `e`.
    fn powf(self, e: Self) -> Self;
    /// `sqrt(self² + y²)` without overflow.
    fn hypot(self, y: Self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// Hyperbolic tangent.
    fn tanh(self) -> Self;
    /// −1, 0 or 1 (0 at ±0; NaN propagates).
    fn sign(self) -> Self;
    /// `max(0, self)` with NaN propagating.
    fn max0(self) -> Self;
    /// 1 for `self > 0`, 0 for `self <= 0`, NaN for NaN.
    fn step(self) -> Self;
    /// True for NaN.
    fn is_nan(self) -> bool;
}
