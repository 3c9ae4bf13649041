//! Forward sensitivities `s = ∂y/∂p` of a solution with respect to a few
//! parameters, integrated with the state by the variational equations
//!
//! ```text
//! ẏ = f(y, p),   ṡ = J(y, p) s + ∂f/∂p(y, p),   s(t₀) = ∂y₀/∂p,
//! ```
//!
//! `J = ∂f/∂y` and `∂f/∂p` being the model's exact generated Jacobians
//! ([`ParameterJacobian`]). The state and the `P` sensitivity columns are
//! integrated as one system, by the explicit Dormand–Prince 5(4) method or
//! a Rosenbrock method whose one factorization of the state's `cI − J` per
//! step serves every column, with the error control on all of them
//! ([`integrate`], in [`forward`]); each
//! column is integrated scaled by its parameter (`p_k s_k`, the change of
//! the state per relative change of `p_k`) so that one absolute tolerance
//! suits parameters of any unit.
//!
//! At a located event `g(y, p) = 0` the event time moves with the
//! parameters,
//!
//! ```text
//! ∂t_e/∂p = −(g_y s + g_p) / (g_y f⁻),
//! ```
//!
//! and where the right-hand side switches there (`f⁻ → f⁺`) the
//! sensitivities jump by `Δs = (f⁻ − f⁺) ∂t_e/∂p` ([`event_jump`]). See
//! `docs/sensitivities.md`.
//!
//! ```
//! use nalgebra::{SMatrix, SVector, Vector1};
//! use pegdyn::integrate::{Method, Options};
//! use pegdyn::sensitivity::{ParameterJacobian, integrate};
//! use pegdyn::system::OdeSystem;
//!
//! /// ẏ = −k y: y = y₀ e^{−kt}, ∂y/∂k = −t y.
//! struct Decay(f64);
//! impl OdeSystem<1> for Decay {
//!     fn rhs(&self, _t: f64, y: &SVector<f64, 1>) -> SVector<f64, 1> {
//!         -self.0 * y
//!     }
//! }
//! impl ParameterJacobian<1, 1> for Decay {
//!     fn parameters(&self) -> SVector<f64, 1> {
//!         Vector1::new(self.0)
//!     }
//!     fn parameter_jacobian(&self, _t: f64, y: &SVector<f64, 1>) -> SMatrix<f64, 1, 1> {
//!         -y
//!     }
//! }
//! let run = integrate::<_, 1, 1, 2>(
//!     &Decay(3.0),
//!     (0.0, Vector1::new(2.0), SMatrix::zeros()),
//!     0.5,
//!     Method::Dopri5,
//!     &Options::with_tolerances(1e-10, 1e-12),
//!     Vec::new(),
//! )
//! .unwrap();
//! let exact = -0.5 * 2.0 * (-1.5f64).exp();
//! assert!((run.s[(0, 0)] - exact).abs() < 1e-9 * exact.abs());
//! ```

pub mod forward;
mod variational;

use nalgebra::{SMatrix, SVector};

use crate::integrate::IntegrateError;
use crate::system::{ModelError, OdeSystem};

pub use forward::{
    EventSensitivity, SensitivityEvent, SensitivityObserver, SensitivityRun, event_jump, integrate,
    integrate_observed,
};

/// A system whose right-hand side's derivatives with respect to `P` chosen
/// parameters are known (for generated models: the `rhs_p` the generator
/// emits beside `∂f/∂y`).
pub trait ParameterJacobian<const N: usize, const P: usize>: OdeSystem<N> {
    /// The values of the chosen parameters (the sensitivities are
    /// integrated scaled by them; a zero value counts as 1).
    fn parameters(&self) -> SVector<f64, P>;

    /// `∂f/∂p` at `(t, y)`: column `k` is the derivative with respect to
    /// the `k`-th chosen parameter.
    fn parameter_jacobian(&self, t: f64, y: &SVector<f64, N>) -> SMatrix<f64, N, P>;

    /// `∂f/∂p`, or why the model cannot evaluate it at `(t, y)`. The
    /// default is `Ok(parameter_jacobian(t, y))`.
    ///
    /// # Errors
    /// The model's [`ModelError`] at `(t, y)`.
    fn try_parameter_jacobian(
        &self,
        t: f64,
        y: &SVector<f64, N>,
    ) -> Result<SMatrix<f64, N, P>, ModelError> {
        Ok(self.parameter_jacobian(t, y))
    }

    /// `J s + ∂f/∂p` (column `k`: `J s_k + ∂f/∂p_k`, the sensitivities'
    /// rate) in one pass, for a model that pushes the columns of `s`
    /// through its right-hand side as directional derivatives (dual
    /// numbers seeded with `s_k` in the state and `e_k` in the
    /// parameters). `None`, the default, makes the integrator form `J`
    /// and `∂f/∂p` and multiply. Called at any `(t, y)`: after `try_rhs`
    /// at the same point along the run, alone at the moved states of the
    /// Rosenbrock methods' Jacobian (whatever the rate needs of the right-
    /// hand side's work, it does itself).
    fn try_sensitivity_rate(
        &self,
        _t: f64,
        _y: &SVector<f64, N>,
        _s: &SMatrix<f64, N, P>,
    ) -> Option<Result<SMatrix<f64, N, P>, ModelError>> {
        None
    }
}

/// Why sensitivities could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SensitivityError {
    /// The augmented dimension `M` is not `N (1 + P)`.
    #[error("augmented dimension {m} given, N (1 + P) = {expected} needed")]
    Dimension {
        /// The `M` given.
        m: usize,
        /// `N (1 + P)`.
        expected: usize,
    },
    /// A parameter name the model does not have.
    #[error("unknown parameter `{name}`; the parameters are: {valid}")]
    UnknownParameter {
        /// The name given.
        name: String,
        /// The valid names, comma-separated.
        valid: String,
    },
    /// A contact name the model does not have.
    #[error("unknown contact `{name}`; the contacts are: {valid}")]
    UnknownContact {
        /// The name given.
        name: String,
        /// The valid names, comma-separated.
        valid: String,
    },
    /// A parameter chosen twice.
    #[error("parameter `{name}` chosen twice")]
    DuplicateParameter {
        /// The name given twice.
        name: String,
    },
    /// A model variant whose parameter Jacobian is not generated.
    #[error("sensitivities are not available for {what}")]
    Unsupported {
        /// The variant.
        what: &'static str,
    },
    /// An event crossed tangentially (`g_y f = 0`): its time does not
    /// depend differentiably on the parameters.
    #[error(
        "event {index} at t = {t} is crossed tangentially (g_y f = {rate}): its time is not \
         differentiable in the parameters"
    )]
    TangentialEvent {
        /// The event's index.
        index: usize,
        /// Its time, s.
        t: f64,
        /// `g_y f` there.
        rate: f64,
    },
    /// Invalid integration input (tolerances, interval, initial state).
    #[error(transparent)]
    Integrate(#[from] IntegrateError),
}
