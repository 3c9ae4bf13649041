//! The integrators' view of a model that can fail: every right-hand side
//! and Jacobian goes through the fallible forms
//! [`OdeSystem::try_rhs`] and [`OdeSystem::try_jacobian`]. A refusal
//! reaches the steppers as a non-finite value, so the step is rejected and
//! retried smaller exactly as for NaN (a trial stage may leave the model's
//! domain where the solution does not), and the first refusal is kept for
//! [`super::Solution::model_error`].

use std::cell::Cell;

use nalgebra::{SMatrix, SVector};

use crate::system::{KinematicSplit, ModelError, OdeSystem};

/// `system` seen through its fallible forms, keeping the first refusal.
pub(crate) struct Checked<'s, S> {
    system: &'s S,
    first: Cell<Option<ModelError>>,
}

impl<'s, S> Checked<'s, S> {
    pub(crate) fn new(system: &'s S) -> Self {
        Checked {
            system,
            first: Cell::new(None),
        }
    }

    /// The first refusal met, if any.
    pub(crate) fn into_first(self) -> Option<ModelError> {
        self.first.into_inner()
    }

    fn keep(&self, e: ModelError) {
        let first = self.first.take();
        self.first.set(first.or(Some(e)));
    }
}

impl<const N: usize, S: OdeSystem<N>> OdeSystem<N> for Checked<'_, S> {
    fn rhs(&self, t: f64, x: &SVector<f64, N>) -> SVector<f64, N> {
        self.system.try_rhs(t, x).unwrap_or_else(|e| {
            self.keep(e);
            SVector::repeat(f64::NAN)
        })
    }

    fn jacobian(&self, t: f64, x: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        self.system.try_jacobian(t, x).unwrap_or_else(|e| {
            self.keep(e);
            SMatrix::repeat(f64::NAN)
        })
    }

    fn time_derivative(&self, t: f64, x: &SVector<f64, N>) -> SVector<f64, N> {
        self.system.time_derivative(t, x)
    }

    fn kinematic_split(&self) -> Option<KinematicSplit> {
        self.system.kinematic_split()
    }

    fn variational_blocks(&self) -> Option<usize> {
        self.system.variational_blocks()
    }

    fn state_names(&self) -> &'static [&'static str] {
        self.system.state_names()
    }
}
