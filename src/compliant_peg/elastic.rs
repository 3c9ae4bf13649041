//! The compliant peg with the stick-capable friction law (Hertz–Mindlin
//! tangential compliance capped by Coulomb) as an [`OdeSystem`].
//!
//! State `y = (x, z, θ, ẋ, ż, θ̇, W, S, u_edge_left, u_wall_right,
//! u_edge_right, u_wall_left)`: the 8 states of [`super::system`] and the
//! utilisation `u = ξ/ξ_max ∈ [−1, 1]` of each contact's tangential spring
//! (friction force `−μ N u`). The equations are in
//! `equations/src/models/compliant_peg/elastic.rs` and `docs/compliant.md`.

use nalgebra::{SMatrix, SVector};

use super::params::{CompliantParams, Load, N_PARAMS_ELASTIC};
use super::system::{Energies, PerContact, Sample, assemble};
use crate::generated::compliant_peg_elastic as gen_elastic;
use crate::system::OdeSystem;

/// Number of states of the elastic-friction model.
pub const N_STATE_ELASTIC: usize = 12;

/// The elastic-friction model with its parameter vector fixed (constant loads).
#[derive(Clone, Debug, PartialEq)]
pub struct ElasticSystem {
    p: SVector<f64, N_PARAMS_ELASTIC>,
}

impl ElasticSystem {
    /// The system of `params` under the constant `load` (always all four
    /// contacts, whatever `params.spec.contacts` says).
    pub fn new(params: &CompliantParams, load: &Load) -> ElasticSystem {
        ElasticSystem {
            p: params.vector_elastic(load),
        }
    }

    /// Contact, energy and depth quantities at state `y`; `tangential` is
    /// the energy stored in the tangential springs.
    pub fn sample(&self, y: &SVector<f64, N_STATE_ELASTIC>) -> Sample {
        let energy = gen_elastic::energy(y, &self.p);
        let c = gen_elastic::contacts(y, &self.p);
        let per = PerContact {
            f: c.normal.as_slice(),
            ft: c.friction.as_slice(),
            d: c.delta.as_slice(),
            p0: c.p0.as_slice(),
        };
        let e = Energies {
            kinetic: energy.kinetic,
            potential: energy.potential,
            depth: energy.depth,
            work: y[6],
            dissipation: y[7],
            tangential: energy.tangential,
        };
        assemble(&per, &e)
    }
}

impl OdeSystem<N_STATE_ELASTIC> for ElasticSystem {
    fn rhs(&self, _t: f64, y: &SVector<f64, N_STATE_ELASTIC>) -> SVector<f64, N_STATE_ELASTIC> {
        gen_elastic::rhs(y, &self.p)
    }

    /// The exact Jacobian generated from the expression trees.
    fn jacobian(
        &self,
        _t: f64,
        y: &SVector<f64, N_STATE_ELASTIC>,
    ) -> SMatrix<f64, N_STATE_ELASTIC, N_STATE_ELASTIC> {
        gen_elastic::jacobian(y, &self.p)
    }

    /// Zero: the loads are constant, the system autonomous.
    fn time_derivative(
        &self,
        _t: f64,
        _y: &SVector<f64, N_STATE_ELASTIC>,
    ) -> SVector<f64, N_STATE_ELASTIC> {
        SVector::zeros()
    }
}
