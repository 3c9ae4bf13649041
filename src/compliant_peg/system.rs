//! The compliant peg-in-hole as an [`OdeSystem`] for the integrators, and
//! the derived quantities of one state ([`Sample`]).
//!
//! State `y = (x, z, θ, ẋ, ż, θ̇, W, S)`: the peg's coordinates and
//! velocities, the work `W` of the applied loads and the friction
//! dissipation `S` (see `equations/src/models/compliant_peg/`).

use nalgebra::{SMatrix, SVector};

use super::params::{CompliantParams, ContactSet, Load, N_PARAMS};
use crate::generated::{compliant_peg as all, compliant_peg_lean as lean};
use crate::system::OdeSystem;

/// Number of states.
pub const N_STATE: usize = 8;

/// The model with its parameter vector fixed (autonomous: constant loads).
#[derive(Clone, Debug, PartialEq)]
pub struct CompliantSystem {
    p: SVector<f64, N_PARAMS>,
    contacts: ContactSet,
}

/// Contact and energy quantities of one state. "Edge" is the larger of the
/// two edge contacts (the paper's A), "wall" the larger of the two wall
/// contacts (the paper's B).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Insertion depth `l` of the bottom face's centre (m).
    pub depth: f64,
    /// Normal force at the edge contact `f_A` (N).
    pub f_edge: f64,
    /// Normal force at the wall contact `f_B` (N).
    pub f_wall: f64,
    /// Friction force at the edge contact along its tangent (N).
    pub friction_edge: f64,
    /// Friction force at the wall contact along its tangent (N).
    pub friction_wall: f64,
    /// Maximum Hertz pressure at the edge contact (Pa).
    pub p0_edge: f64,
    /// Maximum Hertz pressure at the wall contact (Pa).
    pub p0_wall: f64,
    /// Penetration at the edge contact (m; negative = gap).
    pub delta_edge: f64,
    /// Penetration at the wall contact (m; negative = gap).
    pub delta_wall: f64,
    /// Kinetic energy `T` (J), (59).
    pub kinetic: f64,
    /// Contact potential `P` (J), (63).
    pub potential: f64,
    /// Work of the applied loads since the start (J).
    pub work: f64,
    /// Energy dissipated by friction since the start (J), `S_μ` of (64).
    pub dissipation: f64,
    /// Energy stored in the tangential springs of the elastic friction law
    /// (J; 0 with the regularized law).
    pub tangential: f64,
}

impl Sample {
    /// `T + P + E_t − W + S`: constant along a solution (energy balance).
    pub fn balance(&self) -> f64 {
        self.kinetic + self.potential + self.tangential - self.work + self.dissipation
    }
}

/// Per-contact outputs of a generated `contacts` function (in the order
/// edge_left, wall_right[, edge_right, wall_left]): normal force, friction,
/// penetration, maximum pressure.
pub(crate) struct PerContact<'a> {
    pub f: &'a [f64],
    pub ft: &'a [f64],
    pub d: &'a [f64],
    pub p0: &'a [f64],
}

/// The energies and depth of one state (the generated `energy` outputs
/// and the state's work and dissipation).
pub(crate) struct Energies {
    pub kinetic: f64,
    pub potential: f64,
    pub depth: f64,
    pub work: f64,
    pub dissipation: f64,
    /// Stored in the tangential springs (0 with the regularized law).
    pub tangential: f64,
}

/// The [`Sample`] of per-contact outputs and energies: "edge" and "wall"
/// are the contact of each pair with the larger penetration.
pub(crate) fn assemble(c: &PerContact<'_>, e: &Energies) -> Sample {
    let d = c.d;
    let pick = |first: usize| {
        let mut k = first;
        if d.len() > first + 2 && d[first + 2] > d[first] {
            k = first + 2;
        }
        k
    };
    let (a, b) = (pick(0), pick(1));
    Sample {
        depth: e.depth,
        f_edge: c.f[a],
        f_wall: c.f[b],
        friction_edge: c.ft[a],
        friction_wall: c.ft[b],
        p0_edge: c.p0[a],
        p0_wall: c.p0[b],
        delta_edge: d[a],
        delta_wall: d[b],
        kinetic: e.kinetic,
        potential: e.potential,
        work: e.work,
        dissipation: e.dissipation,
        tangential: e.tangential,
    }
}

impl CompliantSystem {
    /// The system of `params` under the constant `load`.
    pub fn new(params: &CompliantParams, load: &Load) -> CompliantSystem {
        CompliantSystem {
            p: params.vector(load),
            contacts: params.spec.contacts,
        }
    }

    /// Contact, energy and depth quantities at state `y`.
    pub fn sample(&self, y: &SVector<f64, N_STATE>) -> Sample {
        // One `EnergyOut` for both models (the lean model shares it).
        let energy = match self.contacts {
            ContactSet::All => all::energy(y, &self.p),
            ContactSet::Lean => lean::energy(y, &self.p),
        };
        let e = Energies {
            kinetic: energy.kinetic,
            potential: energy.potential,
            depth: energy.depth,
            work: y[6],
            dissipation: y[7],
            tangential: 0.0,
        };
        match self.contacts {
            ContactSet::All => {
                let c = all::contacts(y, &self.p);
                let per = PerContact {
                    f: c.normal.as_slice(),
                    ft: c.friction.as_slice(),
                    d: c.delta.as_slice(),
                    p0: c.p0.as_slice(),
                };
                assemble(&per, &e)
            }
            ContactSet::Lean => {
                let c = lean::contacts(y, &self.p);
                let per = PerContact {
                    f: c.normal.as_slice(),
                    ft: c.friction.as_slice(),
                    d: c.delta.as_slice(),
                    p0: c.p0.as_slice(),
                };
                assemble(&per, &e)
            }
        }
    }
}

impl OdeSystem<N_STATE> for CompliantSystem {
    fn rhs(&self, _t: f64, y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        match self.contacts {
            ContactSet::All => all::rhs(y, &self.p),
            ContactSet::Lean => lean::rhs(y, &self.p),
        }
    }

    fn state_names(&self) -> &'static [&'static str] {
        &all::Y_NAMES
    }

    /// The exact Jacobian generated from the expression trees.
    fn jacobian(&self, _t: f64, y: &SVector<f64, N_STATE>) -> SMatrix<f64, N_STATE, N_STATE> {
        match self.contacts {
            ContactSet::All => all::jacobian(y, &self.p),
            ContactSet::Lean => lean::jacobian(y, &self.p),
        }
    }

    /// Zero: the loads are constant, the system autonomous.
    fn time_derivative(&self, _t: f64, _y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        SVector::zeros()
    }
}
