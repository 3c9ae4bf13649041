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

use super::frame::{V3, add, cross, dot, rotate, scale, sub, unit_quaternion};
use crate::scalar::Real;
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

/// The peg's motion at any scalar ([`Real`]), as the wrist reads it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics<T> {
    /// Centre of mass (m).
    pub centre: V3<T>,
    /// Orientation, a unit quaternion `(w, i, j, k)` (body to hole frame).
    pub orientation: [T; 4],
    /// Centre-of-mass velocity (m/s).
    pub velocity: V3<T>,
    /// Angular velocity, hole frame (rad/s).
    pub angular_velocity: V3<T>,
}

impl<T: Real> Kinematics<T> {
    /// The motion of a peg state `y = (p, q, v, ω_body, …)` (at least 13
    /// components): `q` normalized once, in the storage order `(i, j, k,
    /// w)` as nalgebra's `UnitQuaternion::from_quaternion` normalizes it,
    /// and `ω = R(q) ω_body`.
    pub fn of_state(y: &[T]) -> Kinematics<T> {
        let q = unit_quaternion(&[y[0], y[1], y[2], y[3], y[4], y[5], y[6]]);
        Kinematics {
            centre: [y[0], y[1], y[2]],
            orientation: q,
            velocity: [y[7], y[8], y[9]],
            angular_velocity: rotate(&q, &[y[10], y[11], y[12]]),
        }
    }
}

/// What the wrist does to the peg, at any scalar: the fields of
/// [`WristLoad`] that are smooth in the state (no rotation angle), and
/// the relative rotation `q_rel = (w, u)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoadOf<T> {
    /// Force on the peg, hole frame (N).
    pub force: V3<T>,
    /// Moment on the peg about its centre of mass, hole frame (N·m).
    pub moment: V3<T>,
    /// Force on the peg in the robot axes (N).
    pub force_robot: V3<T>,
    /// Moment on the peg about the compliance centre, robot axes (N·m).
    pub moment_robot: V3<T>,
    /// Deflection `d` of the compliance centre, robot axes (m).
    pub deflection: V3<T>,
    /// `q_rel = q_R* ⊗ q` as `(w, i, j, k)`.
    pub relative: [T; 4],
    /// Elastic energy `V` (J).
    pub potential: T,
    /// Dissipation rate of the dampers `Ṡ_w` (W).
    pub dissipation_rate: T,
    /// Power delivered by the robot `Ẇ_r` (W).
    pub robot_power: T,
}

/// The rows of a 3 × 3 matrix, as constants of `T`.
fn rows<T: Real>(m: &Matrix3<f64>) -> [V3<T>; 3] {
    std::array::from_fn(|i| [m[(i, 0)], m[(i, 1)], m[(i, 2)]].map(T::from_f64))
}

/// `M v` in nalgebra's order: `(m_{i0} v₀ + m_{i1} v₁) + m_{i2} v₂`.
fn mat_vec<T: Real>(m: &[V3<T>; 3], v: &V3<T>) -> V3<T> {
    std::array::from_fn(|i| m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2])
}

/// The wrist's stiffnesses, damping and compliance-centre height at any
/// scalar: constants for the state's derivatives, dual numbers of design
/// parameters for the parameters' ([`super::design`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WristOf<T> {
    /// `L_c` (m).
    pub centre_height: T,
    /// `K_x`, `K_y` (N/m).
    pub lateral: [T; 2],
    /// `K_z` (N/m).
    pub axial: T,
    /// `K_θ` (N·m/rad).
    pub angular: T,
    /// `K_φ` (N·m/rad).
    pub torsional: T,
    /// `C_x = C_y` (N·s/m).
    pub lateral_damping: T,
    /// `C_z` (N·s/m).
    pub axial_damping: T,
    /// `C_θ = C_φ` (N·m·s/rad).
    pub angular_damping: T,
}

/// The robot frame's quantities the wrist reads, at any scalar: the
/// rotation `R_R` (rows) and its transpose, `R_Rᵀ Ω_R`, `−R_Rᵀ ċ_R`, the
/// inverse orientation `q_R*`, the position and `Ω_R`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameTerms<T> {
    /// `c_R` (m).
    pub position: V3<T>,
    /// Rows of `R_R`.
    pub rotation: [V3<T>; 3],
    /// Rows of `R_Rᵀ`.
    pub transposed: [V3<T>; 3],
    /// `R_Rᵀ Ω_R` (rad/s).
    pub omega_robot: V3<T>,
    /// `−R_Rᵀ ċ_R` (m/s).
    pub robot_velocity: V3<T>,
    /// `Ω_R`, hole frame (rad/s).
    pub angular_velocity: V3<T>,
    /// `q_R*` in the storage order `(i, j, k, w)`.
    pub inverse: [T; 4],
    /// The axial force of a force-controlled descent (N).
    pub axial_force: Option<T>,
}

impl<T: Real> FrameTerms<T> {
    /// The terms of the frame `r` as constants, formed at `f64` as
    /// nalgebra forms them.
    pub fn of(r: &RobotFrame) -> FrameTerms<T> {
        let c = T::from_f64;
        let rot = r.orientation.to_rotation_matrix();
        let lift = |v: &Vector3<f64>| [c(v.x), c(v.y), c(v.z)];
        let a = r.orientation.inverse().into_inner().coords;
        FrameTerms {
            position: lift(&r.position),
            rotation: rows(rot.matrix()),
            transposed: rows(rot.transpose().matrix()),
            omega_robot: lift(&(rot.transpose() * r.angular_velocity)),
            robot_velocity: lift(&-(rot.transpose() * r.velocity)),
            angular_velocity: lift(&r.angular_velocity),
            inverse: [c(a[0]), c(a[1]), c(a[2]), c(a[3])],
            axial_force: r.axial_force.map(c),
        }
    }
}

impl WristParams {
    /// The wrist's constants at scalar `T`.
    pub fn of<T: Real>(&self) -> WristOf<T> {
        let c = T::from_f64;
        WristOf {
            centre_height: c(self.centre_height),
            lateral: self.lateral.map(c),
            axial: c(self.axial),
            angular: c(self.angular),
            torsional: c(self.torsional),
            lateral_damping: c(self.lateral_damping),
            axial_damping: c(self.axial_damping),
            angular_damping: c(self.angular_damping),
        }
    }

    /// The wrist's load on a peg of length `length` in motion `m` held by
    /// the robot frame `r`: [`WristParams::load_of`] at `f64`.
    pub fn load(&self, length: f64, m: &PegMotion, r: &RobotFrame) -> WristLoad {
        let q = m.orientation.quaternion();
        let k = Kinematics {
            centre: m.centre.into(),
            orientation: [q.w, q.i, q.j, q.k],
            velocity: m.velocity.into(),
            angular_velocity: m.angular_velocity.into(),
        };
        let l = self.load_of(length, &k, r);
        let [w, ui, uj, uk] = l.relative;
        let u = Vector3::new(ui, uj, uk);
        WristLoad {
            force: l.force.into(),
            moment: l.moment.into(),
            force_robot: l.force_robot.into(),
            moment_robot: l.moment_robot.into(),
            deflection: l.deflection.into(),
            rotation: 2.0 * u.norm().atan2(w.abs()),
            potential: l.potential,
            dissipation_rate: l.dissipation_rate,
            robot_power: l.robot_power,
        }
    }

    /// The wrist's load at any scalar ([`Real`]) with the wrist and the
    /// robot frame `r` constants: [`load_with`] of their constants.
    pub fn load_of<T: Real>(&self, length: f64, m: &Kinematics<T>, r: &RobotFrame) -> LoadOf<T> {
        load_with(&self.of(), T::from_f64(length), m, &FrameTerms::of(r))
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

/// The wrist's load at any scalar ([`Real`]): the formulas of the module
/// documentation for the wrist `wr` on a peg of length `length` in motion
/// `m` held by the robot frame `f`. At `f64` every operation keeps the
/// order in which nalgebra evaluates the same formula (a product `M v` of
/// a 3 × 3 matrix as `(m₀₀v₀ + m₀₁v₁) + m₀₂v₂`, the quaternion product
/// component by component), so [`WristParams::load`] is the nalgebra form
/// to the last bit; at dual numbers it carries the load's derivative in
/// the peg's state (the exact Jacobian of
/// [`super::insertion::Insertion`]) or in design parameters that move the
/// wrist and the frame ([`super::design`]).
pub fn load_with<T: Real>(
    wr: &WristOf<T>,
    length: T,
    m: &Kinematics<T>,
    f: &FrameTerms<T>,
) -> LoadOf<T> {
    let c = T::from_f64;
    let (rr, rt) = (&f.rotation, &f.transposed);
    let q = &m.orientation;
    let axis = rotate(q, &[c(0.0), c(0.0), c(1.0)]);
    let arm = scale(&axis, wr.centre_height - c(0.5) * length);
    let cp = add(&m.centre, &arm);
    let d = mat_vec(rt, &sub(&cp, &f.position));
    let kz = if f.axial_force.is_some() {
        c(0.0)
    } else {
        wr.axial
    };
    let [kx, ky] = wr.lateral;
    let zero = c(0.0);
    let translational = [[kx, zero, zero], [zero, ky, zero], [zero, zero, kz]];
    let mut g = mat_vec(&translational, &d);
    let mut potential = c(0.5) * dot(&d, &g);
    if let Some(fz) = f.axial_force {
        g[2] = fz;
        potential = potential + fz * d[2];
    }
    let v_cp = add(&m.velocity, &cross(&m.angular_velocity, &arm));
    let d_robot = sub(&f.robot_velocity, &cross(&f.omega_robot, &d));
    let d_dot = add(&mat_vec(rt, &v_cp), &d_robot);
    let ct = [wr.lateral_damping, wr.lateral_damping, wr.axial_damping];
    let damp_t: V3<T> = std::array::from_fn(|k| ct[k] * d_dot[k]);
    let pushed = add(&g, &damp_t);
    let force_robot = pushed.map(|v| -v);

    // q_rel = q_R* ⊗ q, nalgebra's product (storage order i, j, k, w).
    let [a0, a1, a2, a3] = f.inverse;
    let (b0, b1, b2, b3) = (q[1], q[2], q[3], q[0]);
    let w = a3 * b3 - a0 * b0 - a1 * b1 - a2 * b2;
    let u = [
        a3 * b0 + a0 * b3 + a1 * b2 - a2 * b1,
        a3 * b1 - a0 * b2 + a1 * b3 + a2 * b0,
        a3 * b2 + a0 * b1 - a1 * b0 + a2 * b3,
    ];
    let kr = [wr.angular, wr.angular, wr.torsional];
    let ku: V3<T> = std::array::from_fn(|k| kr[k] * u[k]);
    let h = scale(&add(&scale(&ku, w), &cross(&ku, &u)), c(2.0));
    let omega_rel = mat_vec(rt, &sub(&m.angular_velocity, &f.angular_velocity));
    let damp_r = scale(&omega_rel, wr.angular_damping);
    // `h` is in the peg's body axes (the gradient in a body rotation),
    // the damping moment in the robot's.
    let spring_moment = rotate(q, &h.map(|v| -v));
    let pure = sub(&spring_moment, &mat_vec(rr, &damp_r));
    let moment_robot = mat_vec(rt, &pure);
    let potential = potential + c(2.0) * dot(&u, &ku);
    let force = mat_vec(rr, &force_robot);
    let moment = add(&pure, &cross(&arm, &force));
    let dissipation_rate = dot(&d_dot, &damp_t) + dot(&omega_rel, &damp_r);
    let omega_rb = &f.omega_robot;
    let robot_power = dot(&pushed, &d_robot)
        - c(2.0) * dot(omega_rb, &add(&scale(&ku, w), &cross(&u, &ku)))
        - dot(&damp_r, omega_rb);
    LoadOf {
        force,
        moment,
        force_robot,
        moment_robot,
        deflection: d,
        relative: [w, u[0], u[1], u[2]],
        potential,
        dissipation_rate,
        robot_power,
    }
}
