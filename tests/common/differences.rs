//! Central differences of a function of one value, Richardson-extrapolated
//! once: the reference the derivative tests of the insertion compare with.

use std::ops::{Div, Mul, Sub};

/// `(4 D(h/2) − D(h))/3`, `D(h) = (f(q + h) − f(q − h))/(2h)`: the
/// derivative of `f` at `q` with error `O(h⁴)`, for a scalar or a vector
/// `f`.
pub fn richardson<T>(q: f64, h: f64, f: impl Fn(f64) -> T) -> T
where
    T: Sub<Output = T> + Div<f64, Output = T> + Mul<f64, Output = T>,
{
    let central = |h: f64| (f(q + h) - f(q - h)) / (2.0 * h);
    (central(0.5 * h) * 4.0 - central(h)) / 3.0
}
