//! Hand-derived equations of motion and reactions (paper eqs. (22)–(31),
//! corrected).
//!
//! Unknowns of the forward problem: x = [γ̈, ψ̈, N_K, N_B1, N_B2]. Equations:
//! the two Lagrange equations (the normal reactions do no virtual work; the
//! friction forces f·N_i·t_i do, through the contact Jacobians) and the three
//! centre-of-mass equations in the fixed frame:
//!
//! ```text
//! M(γ) q̈ + h(γ, q̇) = Q_app + Q_grav + J_Cᵀ F + Σ_i f N_i J_iᵀ t_i
//! m (J_C q̈ + J̇_C q̇)  = F + m g + Σ_i N_i (n_i + f t_i)
//! ```
//!
//! The centre-of-mass rows are written in the rotating components
//! (e_η, e_n, e_z) — the paper's (29)–(31) rotated by −ψ — so that the
//! lateral balance, which alone fixes N_B1 − N_B2 through the small lateral
//! components ±b/|OB| of the edge normals, carries no rounding from the
//! large in-plane terms.
//!
//! with M = diag(m(η_C'² + z_C'²) + I_ε, m η_C² + I_ε sin²γ + I_ζ cos²γ),
//! h_γ = m(η_C'η_C'' + z_C'z_C'')γ̇² − (m η_C η_C' + (I_ε − I_ζ) sin γ cos γ)ψ̇²,
//! h_ψ = 2(m η_C η_C' + (I_ε − I_ζ) sin γ cos γ)γ̇ψ̇, Q_grav = (−m g z_C', 0).
//! The prescribed-motion problem has the unknowns [M_γ, M_ψ, N_K, N_B1, N_B2]
//! in the same equations.

use nalgebra::{Const, DimMin, Matrix2, Matrix3, SMatrix, SVector, Vector2, Vector3};

use crate::rigid_peg::kinematics::{Kinematics, Pose};
use crate::rigid_peg::{Loads, PegParams, RigidError};

/// 5×5 matrix of a rigid-peg linear system.
pub type Matrix5 = SMatrix<f64, 5, 5>;
/// 5-vector of unknowns or right-hand side.
pub type Vector5 = SVector<f64, 5>;

/// Names of the contacts, in the order used everywhere.
pub const CONTACTS: [&str; 3] = ["K", "B1", "B2"];

/// Mass matrix M(γ) of the Lagrange equations (kg·m²), eqs. (24)–(25).
pub fn mass_matrix(p: &PegParams, pose: &Pose) -> Matrix2<f64> {
    let g = &pose.geo;
    let (s, co) = g.gamma.sin_cos();
    let (m, it, ia) = (p.mass, p.inertia_transverse(), p.inertia_axial());
    Matrix2::new(
        m * (g.deta_c * g.deta_c + g.dz_c * g.dz_c) + it,
        0.0,
        0.0,
        m * g.eta_c * g.eta_c + it * s * s + ia * co * co,
    )
}

/// Velocity terms h(γ, q̇) on the left of the Lagrange equations (N·m).
pub fn velocity_terms(p: &PegParams, pose: &Pose, qdot: Vector2<f64>) -> Vector2<f64> {
    let g = &pose.geo;
    let (s, co) = g.gamma.sin_cos();
    let (m, it, ia) = (p.mass, p.inertia_transverse(), p.inertia_axial());
    let (gd, pd) = (qdot[0], qdot[1]);
    // ½ dI_z/dγ with I_z = m η_C² + I_ε sin²γ + I_ζ cos²γ.
    let half_diz = m * g.eta_c * g.deta_c + (it - ia) * s * co;
    Vector2::new(
        m * (g.deta_c * g.d2eta_c + g.dz_c * g.d2z_c) * gd * gd - half_diz * pd * pd,
        2.0 * half_diz * gd * pd,
    )
}

/// J̇_C q̇: the part of the centre-of-mass acceleration that does not depend
/// on q̈, in frame components (η, n, z) (m/s²).
pub fn com_bias(pose: &Pose, qdot: Vector2<f64>) -> Vector3<f64> {
    let g = &pose.geo;
    let (gd, pd) = (qdot[0], qdot[1]);
    Vector3::new(
        g.d2eta_c * gd * gd - g.eta_c * pd * pd,
        2.0 * g.deta_c * gd * pd,
        g.d2z_c * gd * gd,
    )
}

/// Friction directions t_i = −v_i/|v_i| (unit, force on the peg, frame
/// components (η, n, z)) from the sliding velocities.
///
/// # Errors
/// [`RigidError::NoSliding`] when a contact's sliding speed is zero.
pub fn friction_directions(kin: &Kinematics) -> Result<[Vector3<f64>; 3], RigidError> {
    directions_opposing(&kin.v_contacts_local)
}

/// t_i = −v_i/|v_i| for the sliding velocities `v` of K, B1, B2 (any
/// components; the directions come out in the same ones).
///
/// # Errors
/// [`RigidError::NoSliding`] when a contact's sliding speed is zero or not
/// finite.
pub fn directions_opposing(v: &[Vector3<f64>; 3]) -> Result<[Vector3<f64>; 3], RigidError> {
    let mut t = [Vector3::zeros(); 3];
    for (i, v) in v.iter().enumerate() {
        let speed = v.norm();
        if speed == 0.0 || !speed.is_finite() {
            return Err(RigidError::NoSliding {
                contact: CONTACTS[i],
            });
        }
        t[i] = -v / speed;
    }
    Ok(t)
}

/// Regularized friction directions t_i = −v_i/√(|v_i|² + v_s²) with the
/// velocity scale `v_s` (m/s): |t_i| < 1, defined at v = 0.
pub fn regularized_directions(kin: &Kinematics, v_s: f64) -> [Vector3<f64>; 3] {
    regularized_opposing(&kin.v_contacts_local, v_s)
}

/// t_i = −v_i/√(|v_i|² + v_s²) for the sliding velocities `v` of K, B1, B2
/// (any components; the directions come out in the same ones) and the
/// velocity scale `v_s` (m/s).
pub fn regularized_opposing(v: &[Vector3<f64>; 3], v_s: f64) -> [Vector3<f64>; 3] {
    v.map(|v| -v / (v.norm_squared() + v_s * v_s).sqrt())
}

/// The blocks shared by both problems: Lagrange rows (2) and centre-of-mass
/// rows (3) with the reaction columns, and the known right-hand side.
struct Blocks {
    mass: Matrix2<f64>,
    /// Reaction columns of the Lagrange rows: −f J_iᵀ t_i.
    lag_n: SMatrix<f64, 2, 3>,
    /// q̈ columns of the CoM rows: m J_C.
    com_q: SMatrix<f64, 3, 2>,
    /// Reaction columns of the CoM rows: −(n_i + f t_i).
    com_n: Matrix3<f64>,
    /// Known right-hand side of the Lagrange rows (without M_γ, M_ψ).
    lag_rhs: Vector2<f64>,
    /// Known right-hand side of the CoM rows.
    com_rhs: Vector3<f64>,
}

fn blocks(
    p: &PegParams,
    pose: &Pose,
    qdot: Vector2<f64>,
    force: [f64; 3],
    t: &[Vector3<f64>; 3],
) -> Blocks {
    let j = pose.jacobians_local();
    let f = p.friction;
    let force = pose.frame.matrix().transpose() * Vector3::from(force);
    let weight = Vector3::new(0.0, 0.0, -p.mass * p.gravity);
    let mut lag_n = SMatrix::<f64, 2, 3>::zeros();
    let mut com_n = Matrix3::zeros();
    for (i, ti) in t.iter().enumerate() {
        lag_n.set_column(i, &(-f * j.contacts[i].transpose() * ti));
        com_n.set_column(i, &(-(pose.local.normals[i] + ti * f)));
    }
    let q_grav = Vector2::new(-p.mass * p.gravity * pose.geo.dz_c, 0.0);
    Blocks {
        mass: mass_matrix(p, pose),
        lag_n,
        com_q: j.c * p.mass,
        com_n,
        lag_rhs: q_grav + j.c.transpose() * force - velocity_terms(p, pose, qdot),
        com_rhs: force + weight - com_bias(pose, qdot) * p.mass,
    }
}

/// Forward problem: A x = rhs for x = [γ̈, ψ̈, N_K, N_B1, N_B2], with the
/// friction directions `t` (from [`friction_directions`] or
/// [`regularized_directions`]).
pub fn forward_system(
    p: &PegParams,
    loads: &Loads,
    pose: &Pose,
    qdot: Vector2<f64>,
    t: &[Vector3<f64>; 3],
) -> (Matrix5, Vector5) {
    let bl = blocks(p, pose, qdot, loads.force, t);
    let mut a = Matrix5::zeros();
    a.fixed_view_mut::<2, 2>(0, 0).copy_from(&bl.mass);
    a.fixed_view_mut::<2, 3>(0, 2).copy_from(&bl.lag_n);
    a.fixed_view_mut::<3, 2>(2, 0).copy_from(&bl.com_q);
    a.fixed_view_mut::<3, 3>(2, 2).copy_from(&bl.com_n);
    let mut rhs = Vector5::zeros();
    rhs.fixed_rows_mut::<2>(0)
        .copy_from(&(bl.lag_rhs + Vector2::new(loads.m_gamma, loads.m_psi)));
    rhs.fixed_rows_mut::<3>(2).copy_from(&bl.com_rhs);
    (a, rhs)
}

/// Prescribed-motion problem: A y = rhs for y = [M_γ, M_ψ, N_K, N_B1, N_B2]
/// given q̈ (the applied moments in `loads` are ignored: they are the
/// unknowns).
pub fn prescribed_system(
    p: &PegParams,
    loads: &Loads,
    pose: &Pose,
    qdot: Vector2<f64>,
    qddot: Vector2<f64>,
    t: &[Vector3<f64>; 3],
) -> (Matrix5, Vector5) {
    let bl = blocks(p, pose, qdot, loads.force, t);
    let mut a = Matrix5::zeros();
    a.fixed_view_mut::<2, 2>(0, 0)
        .copy_from(&(-Matrix2::identity()));
    a.fixed_view_mut::<2, 3>(0, 2).copy_from(&bl.lag_n);
    a.fixed_view_mut::<3, 3>(2, 2).copy_from(&bl.com_n);
    let mut rhs = Vector5::zeros();
    rhs.fixed_rows_mut::<2>(0)
        .copy_from(&(bl.lag_rhs - bl.mass * qddot));
    rhs.fixed_rows_mut::<3>(2)
        .copy_from(&(bl.com_rhs - bl.com_q * qddot));
    (a, rhs)
}

/// Solves an N×N rigid-peg system (the hand-derived 5×5, the generated
/// 5×5 or 3×3 planar one) with LU for `C` right-hand sides at once (one
/// for the unknowns, a column per parameter for their derivatives);
/// `gamma` (rad) names the state in the error.
///
/// # Errors
/// [`RigidError::Singular`] when the matrix is singular or the solution is
/// not finite.
pub fn solve<const N: usize, const C: usize>(
    a: &SMatrix<f64, N, N>,
    rhs: &SMatrix<f64, N, C>,
    gamma: f64,
) -> Result<SMatrix<f64, N, C>, RigidError>
where
    Const<N>: DimMin<Const<N>, Output = Const<N>>,
{
    match a.lu().solve(rhs) {
        Some(x) if x.iter().all(|v| v.is_finite()) => Ok(x),
        _ => Err(RigidError::Singular { gamma }),
    }
}

/// The kinetic energy T = ½ m v_C² + ½ ωᵀ I ω (J), computed from the
/// rigid-body definition (not from eq. (22)); used to check (22)–(23).
pub fn kinetic_energy(p: &PegParams, pose: &Pose, kin: &Kinematics) -> f64 {
    let w_ax = kin.omega.dot(&pose.axis);
    let w_tr2 = kin.omega.norm_squared() - w_ax * w_ax;
    0.5 * p.mass * kin.v_c.norm_squared()
        + 0.5 * (p.inertia_axial() * w_ax * w_ax + p.inertia_transverse() * w_tr2)
}

/// The potential energy V = m g z_C (J).
pub fn potential_energy(p: &PegParams, pose: &Pose) -> f64 {
    p.mass * p.gravity * pose.c.z
}
