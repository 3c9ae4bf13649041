//! A compliant wrist: a linear spring–damper between the peg and a robot
//! frame about a compliance centre on the peg's axis (the remote centre
//! compliance of D. E. Whitney, "Quasi-static assembly of compliantly
//! supported rigid parts", 1982).
//!
//! The compliance centre is the point `c_P = p + (L_c − L/2) a` of the peg
//! (`p` the centre of mass, `a` the axis, `L_c` the height above the tip).
//! The robot frame is a pose `(c_R, R_R)`: undeflected, `c_P = c_R` and the
//! peg's body frame is `R_R`. With the deflection `d = R_Rᵀ (c_P − c_R)`
//! (robot axes) and the relative rotation `q_rel = q_R* ⊗ q = (w, u)`:
//!
//! ```text
//! V = ½ (K_x d_x² + K_y d_y² + K_z d_z²) + 2 (K_θ u_x² + K_θ u_y² + K_φ u_z²)
//! ```
//!
//! (`2 K u_i² = ½ K θ_i² + O(θ⁴)` for a rotation vector `θ`; the quaternion
//! form is smooth everywhere and its gradient is exact). Under a
//! force-controlled descent the axial term `½ K_z d_z²` is replaced by
//! `f d_z`: a constant force `f` down the robot's axis. Forces on the peg
//! (hole frame, `G = ∂V/∂d`, `H = ∂V/∂φ` in the robot axes):
//!
//! ```text
//! F = −R_R (G + C_t ḋ),                    ḋ = R_Rᵀ (v_cP − ċ_R) − Ω_R × d
//! M = −R (2 (w K_r u + K_r u × u)) − R_R C_r R_Rᵀ (ω − Ω_R) + (c_P − p) × F
//! ```
//!
//! (`M` about the centre of mass). The dampers dissipate
//! `Ṡ_w = ḋᵀ C_t ḋ + ω_relᵀ C_r ω_rel ≥ 0`, and the robot delivers the power
//! `Ẇ_r = (G + C_t ḋ)·ḋ_R − 2 Ω_R·(w K_r u + u × K_r u) − (C_r ω_rel)·Ω_R`,
//! `ḋ_R = −R_Rᵀ ċ_R − Ω_R × d` the part of `ḋ` due to the robot's motion,
//! so that `T + m g z + V_c + V − W − W_r + S + S_w` is constant.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

/// Stiffness and damping of a compliant wrist (SI units, robot axes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WristParams {
    /// Height `L_c` of the compliance centre above the peg's tip, along the
    /// axis (m).
    pub centre_height: f64,
    /// Lateral stiffnesses `K_x`, `K_y` (N/m).
    pub lateral: [f64; 2],
    /// Axial stiffness `K_z` (N/m), unused under a force-controlled descent.
    pub axial: f64,
    /// Angular stiffness `K_θ` about the two lateral axes (N·m/rad).
    pub angular: f64,
    /// Torsional stiffness `K_φ` about the peg's axis (N·m/rad).
    pub torsional: f64,
    /// Translational damping `C_x = C_y` (N·s/m).
    pub lateral_damping: f64,
    /// Axial damping `C_z` (N·s/m).
    pub axial_damping: f64,
    /// Angular damping `C_θ = C_φ` (N·m·s/rad).
    pub angular_damping: f64,
}

/// The robot side of the wrist at one instant (hole frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RobotFrame {
    /// Where the compliance centre sits when the wrist is undeflected (m).
    pub position: Vector3<f64>,
    /// The peg's orientation when the wrist is undeflected.
    pub orientation: UnitQuaternion<f64>,
    /// `ċ_R` (m/s).
    pub velocity: Vector3<f64>,
    /// `Ω_R`, hole frame (rad/s).
    pub angular_velocity: Vector3<f64>,
    /// `Some(f)`: a constant axial force `f` (N, positive down the robot's
    /// axis) replaces the axial spring.
    pub axial_force: Option<f64>,
}

/// The peg's pose and velocities (hole frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PegMotion {
    /// Centre of mass (m).
    pub centre: Vector3<f64>,
    /// Orientation (body to hole frame).
    pub orientation: UnitQuaternion<f64>,
    /// Centre-of-mass velocity (m/s).
    pub velocity: Vector3<f64>,
    /// Angular velocity, hole frame (rad/s).
    pub angular_velocity: Vector3<f64>,
}

/// What the wrist does to the peg at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WristLoad {
    /// Force on the peg, hole frame (N).
    pub force: Vector3<f64>,
    /// Moment on the peg about its centre of mass, hole frame (N·m).
    pub moment: Vector3<f64>,
    /// Force on the peg in the robot axes (N): lateral `x, y`, axial `z`.
    pub force_robot: Vector3<f64>,
    /// Moment on the peg about the compliance centre, robot axes (N·m).
    pub moment_robot: Vector3<f64>,
    /// Deflection `d` of the compliance centre, robot axes (m).
    pub deflection: Vector3<f64>,
    /// Relative rotation angle between peg and robot frame (rad).
    pub rotation: f64,
    /// Elastic energy `V` (J).
    pub potential: f64,
    /// Dissipation rate of the dampers `Ṡ_w` (W).
    pub dissipation_rate: f64,
    /// Power delivered by the robot `Ẇ_r` (W).
    pub robot_power: f64,
}

impl WristParams {
    /// `(K_x, K_y, K_z)` as a diagonal matrix; `K_z = 0` under a force.
    fn translational(&self, force_mode: bool) -> Matrix3<f64> {
        let kz = if force_mode { 0.0 } else { self.axial };
        Matrix3::from_diagonal(&Vector3::new(self.lateral[0], self.lateral[1], kz))
    }

    /// The wrist's load on a peg of length `length` in motion `m` held by
    /// the robot frame `r`.
    pub fn load(&self, length: f64, m: &PegMotion, r: &RobotFrame) -> WristLoad {
        let axis = m.orientation * Vector3::z();
        let arm = axis * (self.centre_height - 0.5 * length);
        let cp = m.centre + arm;
        let rr = r.orientation.to_rotation_matrix();
        let rt = rr.transpose();
        let omega_rb = rt * r.angular_velocity;
        let d = rt * (cp - r.position);
        let kt = self.translational(r.axial_force.is_some());
        let mut g = kt * d;
        let mut potential = 0.5 * d.dot(&g);
        if let Some(f) = r.axial_force {
            g.z = f;
            potential += f * d.z;
        }
        let v_cp = m.velocity + m.angular_velocity.cross(&arm);
        let d_robot = -(rt * r.velocity) - omega_rb.cross(&d);
        let d_dot = rt * v_cp + d_robot;
        let ct = Vector3::new(
            self.lateral_damping,
            self.lateral_damping,
            self.axial_damping,
        );
        let damp_t = ct.component_mul(&d_dot);
        let force_robot = -(g + damp_t);

        let rel = r.orientation.inverse() * m.orientation;
        let (w, u) = (rel.w, Vector3::new(rel.i, rel.j, rel.k));
        let kr = Vector3::new(self.angular, self.angular, self.torsional);
        let ku = kr.component_mul(&u);
        let h = (ku * w + ku.cross(&u)) * 2.0;
        let omega_rel = rt * (m.angular_velocity - r.angular_velocity);
        let damp_r = omega_rel * self.angular_damping;
        // `h` is in the peg's body axes (the gradient in a body rotation),
        // the damping moment in the robot's.
        let spring_moment = m.orientation * (-h);
        let pure = spring_moment - rr * damp_r;
        let moment_robot = rt * pure;
        let potential = potential + 2.0 * u.dot(&ku);

        let force = rr * force_robot;
        let moment = pure + arm.cross(&force);
        let dissipation_rate = d_dot.dot(&damp_t) + omega_rel.dot(&damp_r);
        let robot_power = (g + damp_t).dot(&d_robot)
            - 2.0 * omega_rb.dot(&(ku * w + u.cross(&ku)))
            - damp_r.dot(&omega_rb);
        WristLoad {
            force,
            moment,
            force_robot,
            moment_robot,
            deflection: d,
            rotation: 2.0 * u.norm().atan2(w.abs()),
            potential,
            dissipation_rate,
            robot_power,
        }
    }

    /// The natural frequencies (rad/s) of a free peg of mass `mass` and
    /// transverse inertia `j_t` about its centre of mass held by the
    /// undamped wrist, linearized about the undeflected aligned pose: the
    /// axial `√(K_z/m)`, the torsional `√(K_φ/J_a)`, and for each lateral
    /// axis the two roots of the coupled translation–tilt pair
    /// `det([K − ω² m, K e; K e, K e² + K_θ − ω² J_t]) = 0`,
    /// `e = L_c − L/2` the height of the compliance centre above the centre
    /// of mass.
    pub fn linear_frequencies(&self, mass: f64, j_t: f64, j_a: f64, length: f64) -> Vec<f64> {
        let e = self.centre_height - 0.5 * length;
        let mut out = vec![(self.axial / mass).sqrt(), (self.torsional / j_a).sqrt()];
        for &k in &self.lateral {
            // m J ω⁴ − (m (k e² + K_θ) + J k) ω² + k K_θ = 0.
            let a = mass * j_t;
            let b = -(mass * (k * e * e + self.angular) + j_t * k);
            let c = k * self.angular;
            let disc = (b * b - 4.0 * a * c).max(0.0).sqrt();
            out.push(((-b - disc) / (2.0 * a)).sqrt());
            out.push(((-b + disc) / (2.0 * a)).sqrt());
        }
        out
    }
}
