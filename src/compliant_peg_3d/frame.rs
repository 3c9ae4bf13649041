//! The peg's frame in any scalar ([`Real`]): 3-vectors as arrays, the
//! pose's unit quaternion, body vectors turned into the hole frame, the
//! peg's axis, and its motion (centre of mass, velocity, angular velocity
//! in the hole frame) at a state.
//!
//! The contact law ([`super::law`]) is written with these once and
//! evaluated at `f64` by the right-hand side and at dual numbers
//! ([`crate::scalar::Dual`]) by the exact Jacobian. Each operation keeps
//! the order in which nalgebra evaluates the same formula at `f64`, so
//! the right-hand side is the same to the last bit as the nalgebra form:
//!
//! ```text
//! a·b    = (a₀b₀ + a₁b₁) + a₂b₂
//! a × b  = (a₁b₂ − a₂b₁, a₂b₀ − a₀b₂, a₀b₁ − a₁b₀)
//! |c|²   = (c₀² + c₂²) + (c₁² + c₃²)            (four components c in storage order)
//! R(q) v = (w t + u × t) + v,   t = 2 (u × v),   q = (w, u)
//! ```
//!
//! A state `y = (p, q, v, ω_body, W, S)` has the pose `x = (p, q/|q|)`
//! ([`pose`]); the rotation uses `q/|q|` normalized once more in the
//! storage order `(i, j, k, w)` of a quaternion, as the right-hand side
//! always has.

use crate::scalar::Real;

/// A 3-vector (hole frame unless said otherwise).
pub type V3<T> = [T; 3];

/// `a + b`.
pub fn add<T: Real>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a − b`.
pub fn sub<T: Real>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a s`.
pub fn scale<T: Real>(a: &V3<T>, s: T) -> V3<T> {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// `a·b = (a₀b₀ + a₁b₁) + a₂b₂`.
pub fn dot<T: Real>(a: &V3<T>, b: &V3<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a × b`.
pub fn cross<T: Real>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `|c|² = (c₀² + c₂²) + (c₁² + c₃²)` of four components in storage order.
fn norm_squared4<T: Real>(c: [T; 4]) -> T {
    (c[0] * c[0] + c[2] * c[2]) + (c[1] * c[1] + c[3] * c[3])
}

/// The pose `x = (p, q/|q|)` of the first seven components `(p, q)` of a
/// state, `q = (w, i, j, k)`.
pub fn pose<T: Real>(y: &[T]) -> [T; 7] {
    let qn = norm_squared4([y[3], y[4], y[5], y[6]]).sqrt();
    [y[0], y[1], y[2], y[3] / qn, y[4] / qn, y[5] / qn, y[6] / qn]
}

/// The unit quaternion `(w, i, j, k)/|q|` of a pose's quaternion,
/// normalized in the storage order `(i, j, k, w)`.
pub fn unit_quaternion<T: Real>(x: &[T; 7]) -> [T; 4] {
    let n = norm_squared4([x[4], x[5], x[6], x[3]]).sqrt();
    [x[3] / n, x[4] / n, x[5] / n, x[6] / n]
}

/// `R(q) v` for a unit quaternion `q = (w, u)`: `(w t + u × t) + v` with
/// `t = 2 (u × v)`.
pub fn rotate<T: Real>(q: &[T; 4], v: &V3<T>) -> V3<T> {
    let (w, u) = (q[0], [q[1], q[2], q[3]]);
    let t = scale(&cross(&u, v), T::from_f64(2.0));
    let c = cross(&u, &t);
    add(&add(&scale(&t, w), &c), v)
}

/// The peg's axis `a = R(q) e_z` of a pose (unit quaternion
/// `(w, i, j, k)`): `(2(ik + wj), 2(jk − wi), 1 − 2(i² + j²))`, the third
/// column of the rotation matrix of the generated pair functions.
pub fn axis<T: Real>(x: &[T; 7]) -> V3<T> {
    let (w, i, j, k) = (x[3], x[4], x[5], x[6]);
    let two = T::from_f64(2.0);
    [
        two * (i * k + w * j),
        two * (j * k - w * i),
        T::from_f64(1.0) - two * (i * i + j * j),
    ]
}

/// The peg's pose and motion at a state, in the hole frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion<T> {
    /// The pose `x = (p, q/|q|)` ([`pose`]).
    pub pose: [T; 7],
    /// Centre of mass `p` (m).
    pub centre: V3<T>,
    /// Velocity of the centre of mass `v` (m/s).
    pub velocity: V3<T>,
    /// Angular velocity `ω = R(q) ω_body` (rad/s).
    pub omega: V3<T>,
}

impl<T: Real> Motion<T> {
    /// The motion of state `y = (p, q, v, ω_body, …)` (at least 13
    /// components).
    pub fn of_state(y: &[T]) -> Motion<T> {
        let x = pose(y);
        let q = unit_quaternion(&x);
        Motion {
            pose: x,
            centre: [x[0], x[1], x[2]],
            velocity: [y[7], y[8], y[9]],
            omega: rotate(&q, &[y[10], y[11], y[12]]),
        }
    }

    /// The velocity `v + ω × (x_c − p)` of the peg's material point at
    /// `point` (m/s).
    pub fn point_velocity(&self, point: &V3<T>) -> V3<T> {
        add(
            &self.velocity,
            &cross(&self.omega, &sub(point, &self.centre)),
        )
    }
}
