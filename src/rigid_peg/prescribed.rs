//! Prescribed motion (paper's cases (i) and (ii), Fig. 9): given γ(t), ψ(t)
//! and their derivatives, the normal reactions N_K, N_B1, N_B2 and the
//! moments M_γ, M_ψ that drive the motion.
//!
//! [`reactions`] uses the generated model in the smallest variant that
//! represents the state ([`Variant::smallest_at`]); [`reactions_hand`] is
//! the same computation with the hand-derived model, kept for tests and
//! benches.

use nalgebra::{Vector2, Vector3};

use crate::rigid_peg::dynamics::{friction_directions, prescribed_system, solve};
pub use crate::rigid_peg::generated_model::Reactions;
use crate::rigid_peg::generated_model::{self, Variant};
use crate::rigid_peg::kinematics::Pose;
use crate::rigid_peg::{Loads, PegParams, RigidError};

/// Reactions for the state (γ, ψ, γ̇, ψ̇) and accelerations (γ̈, ψ̈), with
/// the assembly force `loads.force` (its moments are ignored: they are the
/// unknowns). Friction opposes each contact's sliding velocity. Computed
/// with the generated model: planar when ψ̇ = ψ̈ = 0 and the loads lie in
/// the symmetry plane, frictionless when f = 0.
///
/// # Errors
/// [`RigidError::Param`] for invalid parameters or a non-finite state,
/// [`RigidError::NotThreePoint`] outside γ0 < γ < π/2,
/// [`RigidError::NoSliding`] when friction acts and a contact does not
/// slide (no friction direction), [`RigidError::Singular`] when the
/// reactions are indeterminate.
pub fn reactions(
    p: &PegParams,
    loads: &Loads,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
    qddot: Vector2<f64>,
) -> Result<Reactions, RigidError> {
    let loads = Loads {
        m_psi: 0.0,
        ..*loads
    };
    let planar_now = qdot[1] == 0.0 && qddot[1] == 0.0;
    let variant = Variant::smallest_at(p, &loads, q[1], planar_now);
    let t = if variant.has_friction() {
        let v = generated_model::contact_velocities(variant, p, q, qdot)?;
        generated_model::friction_directions(&v)?
    } else {
        [Vector3::zeros(); 3]
    };
    generated_model::prescribed(variant, p, &loads, q, qdot, qddot, &t)
}

/// [`reactions`] computed with the hand-derived model
/// ([`crate::rigid_peg::dynamics`]), always in the full 2-DOF form.
///
/// # Errors
/// As [`reactions`] (without the parameter checks).
pub fn reactions_hand(
    p: &PegParams,
    loads: &Loads,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
    qddot: Vector2<f64>,
) -> Result<Reactions, RigidError> {
    let pose = Pose::try_new(p, q[0], q[1])?;
    let t = friction_directions(&pose.kinematics(qdot))?;
    let (a, rhs) = prescribed_system(p, loads, &pose, qdot, qddot, &t);
    let y = solve(&a, &rhs, q[0])?;
    Ok(Reactions {
        m_gamma: y[0],
        m_psi: y[1],
        normal: [y[2], y[3], y[4]],
    })
}

/// One row of the Fig. 9 study: reactions over m g, moments over m g D.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fig9Row {
    /// γ (rad).
    pub gamma: f64,
    /// ψ̇ (1/s).
    pub psidot: f64,
    /// N_B1/(m g).
    pub n_b1: f64,
    /// N_B2/(m g).
    pub n_b2: f64,
    /// N_K/(m g).
    pub n_k: f64,
    /// M_γ/(m g D).
    pub m_gamma: f64,
    /// M_ψ/(m g D).
    pub m_psi: f64,
    /// All reactions non-negative.
    pub feasible: bool,
}

/// The Fig. 9 table: for each ψ̇ of `psidots` and each γ of `gammas`, the
/// steady rates (γ̇, ψ̇) = (`gammadot`, ψ̇), γ̈ = ψ̈ = 0, ψ = 0, no applied
/// force.
///
/// # Errors
/// As [`reactions`].
pub fn fig9_rows(
    p: &PegParams,
    gammas: &[f64],
    gammadot: f64,
    psidots: &[f64],
) -> Result<Vec<Fig9Row>, RigidError> {
    let (w, wd) = (p.mass * p.gravity, p.mass * p.gravity * p.hole_diameter);
    let mut rows = Vec::with_capacity(gammas.len() * psidots.len());
    for &psidot in psidots {
        for &gamma in gammas {
            let r = reactions(
                p,
                &Loads::default(),
                Vector2::new(gamma, 0.0),
                Vector2::new(gammadot, psidot),
                Vector2::zeros(),
            )?;
            rows.push(Fig9Row {
                gamma,
                psidot,
                n_b1: r.normal[1] / w,
                n_b2: r.normal[2] / w,
                n_k: r.normal[0] / w,
                m_gamma: r.m_gamma / wd,
                m_psi: r.m_psi / wd,
                feasible: r.feasible(),
            });
        }
    }
    Ok(rows)
}

/// `count` values of γ from `start` to `end`, geometrically spaced in
/// γ − γ0 so that they are dense near γ0 (`start > γ0`, `count ≥ 2`).
pub fn gamma_grid(gamma0: f64, start: f64, end: f64, count: usize) -> Vec<f64> {
    let (lo, hi) = (start - gamma0, end - gamma0);
    let n = count.max(2);
    (0..n)
        .map(|i| gamma0 + lo * (hi / lo).powf(i as f64 / (n - 1) as f64))
        .collect()
}
