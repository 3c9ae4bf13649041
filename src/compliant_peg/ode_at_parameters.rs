//! What the compliant planar peg's sensitivity adapters share: the model
//! variants they support, and the model (all four contacts) as an
//! [`OdeSystem`] at a fixed parameter vector, for the adapters that carry one
//! (`sensitivity::CompliantSensitivity`, `directions::CompliantDirections`):
//!
//! ```text
//! ẏ = f(y, p)   (generated `rhs`),   ∂f/∂y (generated `jacobian`),   ∂f/∂t = 0.
//! ```
//!
//! [`OdeSystem`]: crate::system::OdeSystem

use super::params::{CompliantParams, ContactSet, FrictionLaw};
use crate::sensitivity::SensitivityError;

/// Refuses the model variants without generated parameter Jacobians.
///
/// # Errors
/// [`SensitivityError::Unsupported`] for the lean contact set or the
/// elastic friction law.
pub(crate) fn check_supported(params: &CompliantParams) -> Result<(), SensitivityError> {
    if params.spec.contacts != ContactSet::All {
        return Err(SensitivityError::Unsupported {
            what: "the compliant planar peg with the lean contact set",
        });
    }
    if params.spec.friction_law != FrictionLaw::Regularized {
        return Err(SensitivityError::Unsupported {
            what: "the compliant planar peg with the elastic friction law",
        });
    }
    Ok(())
}

/// Implements `OdeSystem<N_STATE>` for `$ty<const $c: usize>`, a type with a
/// field `p` holding the full parameter vector (`compliant_peg::P_NAMES`
/// order).
macro_rules! impl_ode_at_parameters {
    ($ty:ident, $c:ident) => {
        impl<const $c: usize> $crate::system::OdeSystem<{ $crate::compliant_peg::system::N_STATE }>
            for $ty<$c>
        {
            fn rhs(
                &self,
                _t: f64,
                y: &nalgebra::SVector<f64, { $crate::compliant_peg::system::N_STATE }>,
            ) -> nalgebra::SVector<f64, { $crate::compliant_peg::system::N_STATE }> {
                $crate::generated::compliant_peg::rhs(y, &self.p)
            }

            fn jacobian(
                &self,
                _t: f64,
                y: &nalgebra::SVector<f64, { $crate::compliant_peg::system::N_STATE }>,
            ) -> nalgebra::SMatrix<
                f64,
                { $crate::compliant_peg::system::N_STATE },
                { $crate::compliant_peg::system::N_STATE },
            > {
                $crate::generated::compliant_peg::jacobian(y, &self.p)
            }

            fn time_derivative(
                &self,
                _t: f64,
                _y: &nalgebra::SVector<f64, { $crate::compliant_peg::system::N_STATE }>,
            ) -> nalgebra::SVector<f64, { $crate::compliant_peg::system::N_STATE }> {
                nalgebra::SVector::zeros()
            }

            fn state_names(&self) -> &'static [&'static str] {
                &$crate::generated::compliant_peg::Y_NAMES
            }
        }
    };
}

pub(crate) use impl_ode_at_parameters;
