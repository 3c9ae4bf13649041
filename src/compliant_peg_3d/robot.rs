//! The prescribed motion of the wrist's robot frame, built from a few
//! pieces (hole frame, SI units):
//!
//! ```text
//! c_R(t) = (x₀ + s_x(t), y₀ + s_y(t), z(t))
//! z(t)   = max(z₀ − v t, z_end)                       (descent at speed v)
//! s(t)   = (ρ(t) cos Ωt, ρ(t) sin Ωt),  ρ = b Ωt / 2π  (spiral search, pitch b)
//! R_R(t) = R_z(ψ) R_y(θ₀) R_z(−ψ) R_z(φ),  ψ = ψ₀ + ψ̇ t,  φ = φ̇ t
//! Ω_R    = ψ̇ (e_z − a_R) + φ̇ a_R,          a_R = R_R e_z
//! ```
//!
//! `θ₀` is the angular error (the tilt of the robot's axis), `ψ` its
//! azimuth, precessing at `ψ̇`; `R_z(ψ) R_y(θ₀) R_z(−ψ)` turns `e_z` into
//! `a_R` without twist, so `φ̇` is a pure spin about the peg's axis. Under a
//! force-controlled descent the robot's height stays `z₀` and the wrist
//! pushes with a constant axial force instead of its axial spring.

use super::frame::{V3, add, dot, rotate, scale, sub};
use super::wrist::{FrameTerms, RobotFrame};
use crate::scalar::Real;
use nalgebra::{UnitQuaternion, Vector3};
use std::f64::consts::TAU;

/// How the robot moves along the hole's axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Descent {
    /// Down at `speed` (m/s) until the frame's height reaches `end` (m).
    Speed {
        /// Descent speed `v` (m/s, > 0 downwards).
        speed: f64,
        /// Lowest height `z_end` of the frame (m).
        end: f64,
    },
    /// The frame stays at its start height; the wrist pushes with the
    /// constant axial force `force` (N, positive into the hole).
    Force {
        /// Axial force `f` (N).
        force: f64,
    },
}

/// An Archimedean spiral search about the start position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spiral {
    /// Radial growth per turn `b` (m).
    pub pitch: f64,
    /// Angular rate `Ω` (rad/s).
    pub rate: f64,
}

/// The robot frame's prescribed motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RobotMotion {
    /// Start position of the frame (where the compliance centre sits
    /// undeflected), hole frame (m): `x₀, y₀` the lateral error.
    pub start: Vector3<f64>,
    /// Angular error `θ₀` (rad).
    pub tilt: f64,
    /// Azimuth `ψ₀` of the tilt at `t = 0` (rad).
    pub tilt_azimuth: f64,
    /// Precession rate `ψ̇` of the tilt direction (rad/s).
    pub precession_rate: f64,
    /// Spin rate `φ̇` about the peg's axis (rad/s).
    pub spin_rate: f64,
    /// Axial motion.
    pub descent: Descent,
    /// Optional spiral search.
    pub spiral: Option<Spiral>,
}

impl RobotMotion {
    /// The frame at time `t` (s).
    pub fn frame(&self, t: f64) -> RobotFrame {
        let (z, vz, axial_force) = match self.descent {
            Descent::Speed { speed, end } => {
                let z = self.start.z - speed * t;
                if z > end {
                    (z, -speed, None)
                } else {
                    (end, 0.0, None)
                }
            }
            Descent::Force { force } => (self.start.z, 0.0, Some(force)),
        };
        let (mut sx, mut sy, mut vx, mut vy) = (0.0, 0.0, 0.0, 0.0);
        if let Some(s) = self.spiral {
            let th = s.rate * t;
            let rho = s.pitch * th / TAU;
            let rho_dot = s.pitch * s.rate / TAU;
            let (sn, cs) = th.sin_cos();
            sx = rho * cs;
            sy = rho * sn;
            vx = rho_dot * cs - rho * s.rate * sn;
            vy = rho_dot * sn + rho * s.rate * cs;
        }
        let psi = self.tilt_azimuth + self.precession_rate * t;
        let ez = Vector3::z_axis();
        let rz_psi = UnitQuaternion::from_axis_angle(&ez, psi);
        let ry = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), self.tilt);
        let spin = UnitQuaternion::from_axis_angle(&ez, self.spin_rate * t);
        let orientation = rz_psi * ry * rz_psi.inverse() * spin;
        let a = orientation * Vector3::z();
        let angular_velocity = (Vector3::z() - a) * self.precession_rate + a * self.spin_rate;
        RobotFrame {
            position: Vector3::new(self.start.x + sx, self.start.y + sy, z),
            orientation,
            velocity: Vector3::new(vx, vy, vz),
            angular_velocity,
            axial_force,
        }
    }
}

/// The robot motion's quantities that design parameters move, at any
/// scalar: the start position `c_R(0)` (m), the angular error `θ₀` (rad),
/// the descent's speed `v` (m/s) and lowest height `z_end` (m) (both 0
/// under a force), and the precession and spin rates `ψ̇`, `φ̇` (rad/s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MotionOf<T> {
    /// `c_R(0)` (m).
    pub start: V3<T>,
    /// `θ₀` (rad).
    pub tilt: T,
    /// `v` (m/s).
    pub speed: T,
    /// `z_end` (m).
    pub end: T,
    /// `ψ̇` (rad/s).
    pub precession_rate: T,
    /// `φ̇` (rad/s).
    pub spin_rate: T,
}

/// `a ⊗ b` of quaternions `(w, i, j, k)`.
fn product<T: Real>(a: &[T; 4], b: &[T; 4]) -> [T; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

impl RobotMotion {
    /// The quantities of [`MotionOf`] as constants of `T`.
    pub fn of<T: Real>(&self) -> MotionOf<T> {
        let c = T::from_f64;
        let (speed, end) = match self.descent {
            Descent::Speed { speed, end } => (speed, end),
            Descent::Force { .. } => (0.0, 0.0),
        };
        MotionOf {
            start: [c(self.start.x), c(self.start.y), c(self.start.z)],
            tilt: c(self.tilt),
            speed: c(speed),
            end: c(end),
            precession_rate: c(self.precession_rate),
            spin_rate: c(self.spin_rate),
        }
    }

    /// The frame's terms at time `t` (s) as the wrist reads them
    /// ([`FrameTerms`]), at any scalar: the formulas of the module
    /// documentation with `p`'s quantities in place of this motion's (the
    /// azimuth and the spiral are this motion's constants).
    /// [`RobotMotion::frame`] is the same frame at `f64` in nalgebra's
    /// types, which the right-hand side reads; this form carries the
    /// frame's derivative in design parameters ([`super::design`]).
    pub fn terms_of<T: Real>(&self, t: f64, p: &MotionOf<T>) -> FrameTerms<T> {
        let c = T::from_f64;
        let (z, vz, axial_force) = match self.descent {
            Descent::Speed { .. } => {
                let z = p.start[2] - p.speed * c(t);
                if z.to_f64() > p.end.to_f64() {
                    (z, -p.speed, None)
                } else {
                    (p.end, c(0.0), None)
                }
            }
            Descent::Force { force } => (p.start[2], c(0.0), Some(c(force))),
        };
        let f = self.frame(t);
        // The spiral's offset: the frame's lateral position less the start's.
        let (sx, sy) = (f.position.x - self.start.x, f.position.y - self.start.y);
        let psi = c(self.tilt_azimuth) + p.precession_rate * c(t);
        let half = |angle: T| (c(0.5) * angle).sin_cos();
        let (sp, cp) = half(psi);
        let (st, ct) = half(p.tilt);
        let (ss, cs) = half(p.spin_rate * c(t));
        let zero = c(0.0);
        let rz = [cp, zero, zero, sp];
        let rz_inv = [cp, zero, zero, -sp];
        let ry = [ct, zero, st, zero];
        let spin = [cs, zero, zero, ss];
        let q = product(&product(&product(&rz, &ry), &rz_inv), &spin);
        let ez = [zero, zero, c(1.0)];
        let a = rotate(&q, &ez);
        let omega = add(
            &scale(&sub(&ez, &a), p.precession_rate),
            &scale(&a, p.spin_rate),
        );
        let (w, i, j, k) = (q[0], q[1], q[2], q[3]);
        let one = c(1.0);
        let two = c(2.0);
        let rotation = [
            [
                one - two * (j * j + k * k),
                two * (i * j - w * k),
                two * (i * k + w * j),
            ],
            [
                two * (i * j + w * k),
                one - two * (i * i + k * k),
                two * (j * k - w * i),
            ],
            [
                two * (i * k - w * j),
                two * (j * k + w * i),
                one - two * (i * i + j * j),
            ],
        ];
        let transposed: [V3<T>; 3] =
            std::array::from_fn(|r| std::array::from_fn(|s| rotation[s][r]));
        let times = |m: &[V3<T>; 3], v: &V3<T>| -> V3<T> { std::array::from_fn(|r| dot(&m[r], v)) };
        let velocity = [c(f.velocity.x), c(f.velocity.y), vz];
        FrameTerms {
            position: [p.start[0] + c(sx), p.start[1] + c(sy), z],
            rotation,
            transposed,
            omega_robot: times(&transposed, &omega),
            robot_velocity: times(&transposed, &velocity).map(|v| -v),
            angular_velocity: omega,
            inverse: [-i, -j, -k, w],
            axial_force,
        }
    }
}
