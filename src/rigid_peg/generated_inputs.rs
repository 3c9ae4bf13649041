//! The generated rigid-peg functions' typed inputs from the runtime's
//! state, loads and friction directions: the 2-DOF and planar `State`,
//! the planar `Loads` (the 2-DOF ones convert with `From<&Loads>` in
//! [`super::params`]) and the `FrictionDirections` of each.

use nalgebra::{Vector2, Vector3};

use crate::generated::{rigid_peg, rigid_peg_planar};
use crate::rigid_peg::Loads;

/// The 2-DOF state (γ, ψ, γ̇, ψ̇).
pub(super) fn state(q: Vector2<f64>, qdot: Vector2<f64>) -> rigid_peg::State<f64> {
    rigid_peg::State {
        gamma: q[0],
        psi: q[1],
        gammadot: qdot[0],
        psidot: qdot[1],
    }
}

/// The planar state (γ, γ̇).
pub(super) fn planar_state(q: Vector2<f64>, qdot: Vector2<f64>) -> rigid_peg_planar::State<f64> {
    rigid_peg_planar::State {
        gamma: q[0],
        gammadot: qdot[0],
    }
}

/// The planar loads at precession angle `psi`: M_γ and the force's
/// in-plane (e_η) and vertical components.
pub(super) fn planar_loads(loads: &Loads, psi: f64) -> rigid_peg_planar::Loads<f64> {
    let (s, c) = psi.sin_cos();
    let [fx, fy, fz] = loads.force;
    rigid_peg_planar::Loads {
        M_gamma: loads.m_gamma,
        F_x: fx * c + fy * s,
        F_z: fz,
    }
}

/// The friction directions at K, B1, B2 in rotating components.
pub(super) fn directions(t: &[Vector3<f64>; 3]) -> rigid_peg::FrictionDirections<f64> {
    let [k, b1, b2] = t;
    rigid_peg::FrictionDirections {
        t_K_eta: k.x,
        t_K_n: k.y,
        t_K_z: k.z,
        t_B1_eta: b1.x,
        t_B1_n: b1.y,
        t_B1_z: b1.z,
        t_B2_eta: b2.x,
        t_B2_n: b2.y,
        t_B2_z: b2.z,
    }
}

/// The planar friction directions at K and B (= B1 = B2), in-plane
/// components (the planar variant's check has found them planar).
pub(super) fn planar_friction(t: &[Vector3<f64>; 3]) -> rigid_peg_planar::FrictionDirections<f64> {
    rigid_peg_planar::FrictionDirections {
        t_K_eta: t[0].x,
        t_K_z: t[0].z,
        t_B_eta: t[1].x,
        t_B_z: t[1].z,
    }
}
