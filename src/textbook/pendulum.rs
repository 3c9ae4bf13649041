//! The simple pendulum (point mass on a massless rod), `θ̈ = −(g/L) sin θ`
//! with `θ` from the downward vertical: its parameters, the generated
//! `pendulum` model as an [`OdeSystem`] and the exact period.

use nalgebra::{SMatrix, Vector2, Vector3};

use crate::generated::pendulum as generated;
use crate::hertz::elliptic::carlson_rf;
use crate::system::{OdeSystem, finite_difference_jacobian};

/// Standard gravity, m/s².
pub const STANDARD_GRAVITY: f64 = 9.80665;

#[cfg(feature = "scenes")]
fn standard_gravity() -> f64 {
    STANDARD_GRAVITY
}

/// The `[pendulum]` table.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "scenes", derive(serde::Deserialize))]
#[cfg_attr(feature = "scenes", serde(deny_unknown_fields))]
pub struct PendulumParams {
    /// Rod length `L`, m.
    pub length: f64,
    /// Bob mass `m`, kg.
    pub mass: f64,
    /// Gravitational acceleration `g`, m/s².
    #[cfg_attr(feature = "scenes", serde(default = "standard_gravity"))]
    pub gravity: f64,
    /// Initial angle from the downward vertical, degrees.
    pub theta0_deg: f64,
    /// Initial angular velocity, rad/s.
    #[cfg_attr(feature = "scenes", serde(default))]
    pub omega0: f64,
}

/// The exact period of a librating pendulum,
/// `T = 4 √(L/g) K(m)`, `m = sin²(θ_max/2)`, with the complete elliptic
/// integral of the first kind `K(m) = R_F(0, 1 − m, 1)`
/// ([`carlson_rf`]), where the amplitude
/// follows from energy conservation, `cos θ_max = cos θ₀ − L ω₀²/(2g)`.
/// `None` when the pendulum circulates (`cos θ_max ≤ −1`) or stays at rest.
pub fn exact_period(p: &PendulumParams) -> Option<f64> {
    let cos_max =
        p.theta0_deg.to_radians().cos() - p.length * p.omega0 * p.omega0 / (2.0 * p.gravity);
    if cos_max <= -1.0 || cos_max >= 1.0 {
        return None;
    }
    // 1 − m = cos²(θ_max/2) = (1 + cos θ_max)/2.
    let mc = 0.5 * (1.0 + cos_max);
    Some(4.0 * (p.length / p.gravity).sqrt() * carlson_rf(0.0, mc, 1.0))
}

impl From<&PendulumParams> for generated::Params<f64> {
    /// The generated model's mass, rod length and gravity.
    fn from(p: &PendulumParams) -> Self {
        generated::Params {
            m: p.mass,
            l: p.length,
            g: p.gravity,
        }
    }
}

/// The generated `pendulum` model as an [`OdeSystem`], state `(θ, θ̇)`.
#[derive(Debug, Clone, Copy)]
pub struct PendulumSystem {
    /// The generated model's parameter vector ([`generated::Params`]).
    p: Vector3<f64>,
}

impl PendulumSystem {
    /// The system for the given parameters.
    pub fn new(p: &PendulumParams) -> Self {
        PendulumSystem {
            p: generated::Params::from(p).into(),
        }
    }

    /// Total energy `T + V`, J.
    pub fn energy(&self, x: &Vector2<f64>) -> f64 {
        generated::energy(x, &self.p)
    }
}

impl OdeSystem<2> for PendulumSystem {
    fn rhs(&self, _t: f64, x: &Vector2<f64>) -> Vector2<f64> {
        generated::rhs(x, &self.p)
    }

    fn state_names(&self) -> &'static [&'static str] {
        &generated::X_NAMES
    }

    /// `∂ẋ/∂x = [[0, 1], [M⁻¹G]]` from the generated mass matrix and
    /// Jacobian terms `G`.
    fn jacobian(&self, t: f64, x: &Vector2<f64>) -> SMatrix<f64, 2, 2> {
        let dynamics = generated::dynamics(x, &self.p);
        let lu = dynamics.mass.lu();
        let solved = lu
            .solve(&dynamics.forcing)
            .and_then(|qdd| lu.solve(&generated::jacobian_terms(x, &qdd, &self.p)));
        match solved {
            Some(row) => SMatrix::<f64, 2, 2>::new(0.0, 1.0, row[(0, 0)], row[(0, 1)]),
            None => finite_difference_jacobian(|x| self.rhs(t, x), x),
        }
    }

    fn time_derivative(&self, _t: f64, _x: &Vector2<f64>) -> Vector2<f64> {
        Vector2::zeros()
    }
}
