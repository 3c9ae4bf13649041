//! The planar double pendulum: two point masses on massless rods, angles
//! `θ₁`, `θ₂` from the downward vertical. Its parameters and the generated
//! `double_pendulum` model as an [`OdeSystem`].

use nalgebra::{SMatrix, SVector, Vector4};

use crate::generated::double_pendulum as generated;
use crate::system::{OdeSystem, finite_difference_jacobian};

#[cfg(feature = "scenes")]
fn standard_gravity() -> f64 {
    super::pendulum::STANDARD_GRAVITY
}

/// The `[double_pendulum]` table.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "scenes", derive(serde::Deserialize))]
#[cfg_attr(feature = "scenes", serde(deny_unknown_fields))]
pub struct DoublePendulumParams {
    /// Upper bob mass `m₁`, kg.
    pub mass1: f64,
    /// Lower bob mass `m₂`, kg.
    pub mass2: f64,
    /// Upper rod length `l₁`, m.
    pub length1: f64,
    /// Lower rod length `l₂`, m.
    pub length2: f64,
    /// Gravitational acceleration `g`, m/s².
    #[cfg_attr(feature = "scenes", serde(default = "standard_gravity"))]
    pub gravity: f64,
    /// Initial upper angle, degrees from the downward vertical.
    pub theta1_deg: f64,
    /// Initial lower angle, degrees from the downward vertical.
    pub theta2_deg: f64,
    /// Initial upper angular velocity, rad/s.
    #[cfg_attr(feature = "scenes", serde(default))]
    pub omega1: f64,
    /// Initial lower angular velocity, rad/s.
    #[cfg_attr(feature = "scenes", serde(default))]
    pub omega2: f64,
}

impl From<&DoublePendulumParams> for generated::Params<f64> {
    /// The generated model's masses, rod lengths and gravity.
    fn from(p: &DoublePendulumParams) -> Self {
        generated::Params {
            m1: p.mass1,
            m2: p.mass2,
            l1: p.length1,
            l2: p.length2,
            g: p.gravity,
        }
    }
}

/// The generated `double_pendulum` model as an [`OdeSystem`], state
/// `(θ₁, θ₂, θ̇₁, θ̇₂)`.
#[derive(Debug, Clone, Copy)]
pub struct DoublePendulumSystem {
    /// The generated model's parameter vector ([`generated::Params`]).
    p: SVector<f64, 5>,
}

impl DoublePendulumSystem {
    /// The system for the given parameters.
    pub fn new(p: &DoublePendulumParams) -> Self {
        DoublePendulumSystem {
            p: generated::Params::from(p).into(),
        }
    }

    /// Total energy `T + V`, J.
    pub fn energy(&self, x: &Vector4<f64>) -> f64 {
        generated::energy(x, &self.p)
    }
}

impl OdeSystem<4> for DoublePendulumSystem {
    fn rhs(&self, _t: f64, x: &Vector4<f64>) -> Vector4<f64> {
        generated::rhs(x, &self.p)
    }

    fn state_names(&self) -> &'static [&'static str] {
        &generated::X_NAMES
    }

    /// `∂ẋ/∂x = [[0, I], [M⁻¹G]]` from the generated mass matrix and
    /// Jacobian terms `G`.
    fn jacobian(&self, t: f64, x: &Vector4<f64>) -> SMatrix<f64, 4, 4> {
        let dynamics = generated::dynamics(x, &self.p);
        let lu = dynamics.mass.lu();
        let solved = lu
            .solve(&dynamics.forcing)
            .and_then(|qdd| lu.solve(&generated::jacobian_terms(x, &qdd, &self.p)));
        match solved {
            Some(lower) => {
                let mut j = SMatrix::<f64, 4, 4>::zeros();
                j[(0, 2)] = 1.0;
                j[(1, 3)] = 1.0;
                j.fixed_view_mut::<2, 4>(2, 0).copy_from(&lower);
                j
            }
            None => finite_difference_jacobian(|x| self.rhs(t, x), x),
        }
    }

    fn time_derivative(&self, _t: f64, _x: &Vector4<f64>) -> Vector4<f64> {
        Vector4::zeros()
    }
}
