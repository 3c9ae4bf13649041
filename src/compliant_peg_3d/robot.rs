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

use super::wrist::RobotFrame;
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
