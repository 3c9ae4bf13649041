//! Forward sensitivities of the compliant planar peg (all four contacts,
//! regularized friction) with respect to `P` of its model parameters
//! (`compliant_peg::P_NAMES`: mass, inertia, dimensions, friction,
//! stiffnesses, loads, ...), and its events with their exact gradients:
//! the contact events `δ_c(y, p) = 0` (a contact closing or opening) and
//! the depth event `l(y, p) = target` (seated).
//!
//! `∂f/∂p` is the generated `rhs_p`; the events' gradients are the
//! generated `contacts` and `energy` evaluated at dual numbers seeded in
//! the 8 states and 24 parameters. The right-hand side is continuous
//! across the contact events (the Hertz force `k max(δ, 0)^{3/2}` starts
//! from zero), so the sensitivities do not jump there; the events are
//! located so that each integration step sees a smooth right-hand side,
//! and their times' sensitivities are reported. See
//! `docs/sensitivities.md`.

use nalgebra::{SMatrix, SVector};

use super::params::{CompliantParams, Load, N_PARAMS};
use super::system::N_STATE;
use crate::generated::compliant_peg as all;
use crate::integrate::Direction;
use crate::scalar::Dual;
use crate::sensitivity::{ParameterJacobian, SensitivityError, SensitivityEvent};

/// The contacts of the model, in the order of its `contacts` outputs.
pub const CONTACTS: [&str; 4] = ["edge_left", "wall_right", "edge_right", "wall_left"];

/// Dual numbers seeded in the 8 states and the 24 parameters.
type D = Dual<{ N_STATE + N_PARAMS }>;

/// The compliant planar peg under a constant load, with `P` of its
/// parameters chosen for sensitivities.
#[derive(Clone, Debug, PartialEq)]
pub struct CompliantSensitivity<const P: usize> {
    p: SVector<f64, N_PARAMS>,
    columns: [usize; P],
}

impl<const P: usize> CompliantSensitivity<P> {
    /// The model of `params` under `load`, sensitivities with respect to
    /// the parameters named `names` (from `compliant_peg::P_NAMES`).
    ///
    /// # Errors
    /// [`SensitivityError::UnknownParameter`] (with the valid names),
    /// [`SensitivityError::DuplicateParameter`], or
    /// [`SensitivityError::Unsupported`] for the lean contact set or the
    /// elastic friction law (their parameter Jacobians are not generated).
    pub fn new(
        params: &CompliantParams,
        load: &Load,
        names: [&str; P],
    ) -> Result<Self, SensitivityError> {
        super::ode_at_parameters::check_supported(params)?;
        let mut columns = [0; P];
        for (k, name) in names.iter().enumerate() {
            let Some(c) = all::P_NAMES.iter().position(|n| n == name) else {
                return Err(SensitivityError::UnknownParameter {
                    name: (*name).to_owned(),
                    valid: all::P_NAMES.join(", "),
                });
            };
            if columns[..k].contains(&c) {
                return Err(SensitivityError::DuplicateParameter {
                    name: (*name).to_owned(),
                });
            }
            columns[k] = c;
        }
        Ok(CompliantSensitivity {
            p: params.vector(load),
            columns,
        })
    }

    /// The full parameter vector (`compliant_peg::P_NAMES` order).
    pub fn parameter_vector(&self) -> &SVector<f64, N_PARAMS> {
        &self.p
    }

    /// The state and parameters as duals seeded in all 32 of them.
    fn seeded(&self, y: &SVector<f64, N_STATE>) -> (SVector<D, N_STATE>, SVector<D, N_PARAMS>) {
        (
            SVector::from_fn(|i, _| D::variable(y[i], i)),
            SVector::from_fn(|i, _| D::variable(self.p[i], N_STATE + i)),
        )
    }

    /// `(∂g/∂y, ∂g/∂p)` of a dual value, `p` restricted to the chosen
    /// parameters.
    fn split(&self, g: D) -> (SVector<f64, N_STATE>, SVector<f64, P>) {
        (
            SVector::from_fn(|i, _| g.d[i]),
            SVector::from_fn(|k, _| g.d[N_STATE + self.columns[k]]),
        )
    }

    /// The penetration `δ_c` of contact `c` (index into [`CONTACTS`]) at
    /// dual numbers.
    fn delta(&self, c: usize, y: &SVector<f64, N_STATE>) -> D {
        let (yd, pd) = self.seeded(y);
        all::contacts(&yd, &pd).delta[c]
    }

    /// The event `δ_c = 0` of the contact named `contact` (one of
    /// [`CONTACTS`]), either direction: the contact closes or opens.
    ///
    /// # Errors
    /// [`SensitivityError::UnknownContact`] (with the valid names).
    pub fn contact_event(
        &self,
        contact: &str,
    ) -> Result<SensitivityEvent<'_, N_STATE, P>, SensitivityError> {
        let Some(c) = CONTACTS.iter().position(|n| *n == contact) else {
            return Err(SensitivityError::UnknownContact {
                name: contact.to_owned(),
                valid: CONTACTS.join(", "),
            });
        };
        Ok(SensitivityEvent::new(
            move |_, y| all::contacts(y, &self.p).delta[c],
            move |_, y| self.split(self.delta(c, y)),
        ))
    }

    /// The terminal event "the bottom face's centre reaches `target`" (m),
    /// rising.
    pub fn depth_event(&self, target: f64) -> SensitivityEvent<'_, N_STATE, P> {
        SensitivityEvent::new(
            move |_, y| all::energy(y, &self.p).depth - target,
            move |_, y| {
                let (yd, pd) = self.seeded(y);
                self.split(all::energy(&yd, &pd).depth)
            },
        )
        .direction(Direction::Rising)
        .terminal()
    }
}

super::ode_at_parameters::impl_ode_at_parameters!(CompliantSensitivity, P);

impl<const P: usize> ParameterJacobian<N_STATE, P> for CompliantSensitivity<P> {
    fn parameters(&self) -> SVector<f64, P> {
        SVector::from_fn(|k, _| self.p[self.columns[k]])
    }

    /// The chosen columns of the generated `rhs_p`.
    fn parameter_jacobian(&self, _t: f64, y: &SVector<f64, N_STATE>) -> SMatrix<f64, N_STATE, P> {
        let full = all::rhs_p(y, &self.p);
        SMatrix::from_fn(|i, k| full[(i, self.columns[k])])
    }
}
