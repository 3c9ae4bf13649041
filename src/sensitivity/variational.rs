//! The state and its scaled sensitivities as one system of `M = N (1 + P)`
//! components: `z = (y, p₁ s₁, …, p_P s_P)` with
//! `ż = (f, p₁ (J s₁ + ∂f/∂p₁), …)` (column `k` scaled by the parameter's
//! value `c_k`, 1 for a zero parameter).

use nalgebra::{SMatrix, SVector};

use super::ParameterJacobian;
use crate::system::{ModelError, OdeSystem};

/// The variational system of `system` (built only by [`super::integrate`],
/// which checks `M = N (1 + P)`).
pub(super) struct Variational<'a, S, const N: usize, const P: usize> {
    pub(super) system: &'a S,
    /// The column scales `c_k`.
    pub(super) scale: SVector<f64, P>,
}

impl<S, const N: usize, const P: usize> Variational<'_, S, N, P> {
    /// `z` of `y` and the unscaled sensitivities `s`.
    pub(super) fn pack<const M: usize>(
        &self,
        y: &SVector<f64, N>,
        s: &SMatrix<f64, N, P>,
    ) -> SVector<f64, M> {
        SVector::from_fn(|i, _| {
            if i < N {
                y[i]
            } else {
                let (k, r) = ((i - N) / N, (i - N) % N);
                self.scale[k] * s[(r, k)]
            }
        })
    }

    /// `y` and the unscaled sensitivities of `z`.
    pub(super) fn unpack<const M: usize>(
        &self,
        z: &SVector<f64, M>,
    ) -> (SVector<f64, N>, SMatrix<f64, N, P>) {
        let (y, cs) = Self::split(z);
        (y, SMatrix::from_fn(|r, k| cs[(r, k)] / self.scale[k]))
    }

    /// `y` and the scaled columns `c_k s_k` of `z`.
    fn split<const M: usize>(z: &SVector<f64, M>) -> (SVector<f64, N>, SMatrix<f64, N, P>) {
        let y = SVector::from_fn(|i, _| z[i]);
        let cs = SMatrix::from_fn(|r, k| z[N + k * N + r]);
        (y, cs)
    }
}

impl<S: ParameterJacobian<N, P>, const N: usize, const P: usize> Variational<'_, S, N, P> {
    /// The scaled columns' rate `c_k (J s_k + ∂f/∂p_k)` at `(t, y)` for the
    /// scaled columns `cs` (column `k` is `c_k s_k`): from the model's
    /// one-pass rate where it has one
    /// ([`ParameterJacobian::try_sensitivity_rate`]), else from `J` and
    /// `∂f/∂p`.
    fn scaled_rate(
        &self,
        t: f64,
        y: &SVector<f64, N>,
        cs: &SMatrix<f64, N, P>,
    ) -> Result<SMatrix<f64, N, P>, ModelError> {
        let s = SMatrix::<f64, N, P>::from_fn(|r, k| cs[(r, k)] / self.scale[k]);
        if let Some(rate) = self.system.try_sensitivity_rate(t, y, &s) {
            let rate = rate?;
            return Ok(SMatrix::from_fn(|r, k| rate[(r, k)] * self.scale[k]));
        }
        let j = self.system.try_jacobian(t, y)?;
        let fp = self.system.try_parameter_jacobian(t, y)?;
        let mut out = SMatrix::<f64, N, P>::zeros();
        for k in 0..P {
            out.set_column(k, &(j * cs.column(k) + fp.column(k) * self.scale[k]));
        }
        Ok(out)
    }
}

impl<S: ParameterJacobian<N, P>, const N: usize, const P: usize, const M: usize> OdeSystem<M>
    for Variational<'_, S, N, P>
{
    fn rhs(&self, t: f64, z: &SVector<f64, M>) -> SVector<f64, M> {
        self.try_rhs(t, z)
            .unwrap_or_else(|_| SVector::repeat(f64::NAN))
    }

    /// The blocks `(y, c₁ s₁, …)` of `N` ([`OdeSystem::variational_blocks`]).
    fn variational_blocks(&self) -> Option<usize> {
        Some(N)
    }

    /// The Jacobian of `ż` in block form: the model's `J` on the diagonal
    /// blocks and, in the first block column, `Bₖ = c_k ∂(J s_k +
    /// ∂f/∂p_k)/∂y` at the fixed `s_k` (second derivatives of `f`), by
    /// forward differences of the sensitivities' rate in each state
    /// component (step `√ε · max(|y_j|, 1)`, as
    /// [`crate::system::finite_difference_jacobian`]): `N + 1` evaluations
    /// of the rate.
    fn try_jacobian(&self, t: f64, z: &SVector<f64, M>) -> Result<SMatrix<f64, M, M>, ModelError> {
        let (y, cs) = Self::split(z);
        let j = self.system.try_jacobian(t, &y)?;
        let base = self.scaled_rate(t, &y, &cs)?;
        let mut out = SMatrix::<f64, M, M>::zeros();
        for b in 0..=P {
            out.fixed_view_mut::<N, N>(b * N, b * N).copy_from(&j);
        }
        for col in 0..N {
            let mut moved = y;
            moved[col] += f64::EPSILON.sqrt() * y[col].abs().max(1.0);
            let delta = moved[col] - y[col];
            let rate = self.scaled_rate(t, &moved, &cs)?;
            for k in 0..P {
                for r in 0..N {
                    out[(N + k * N + r, col)] = (rate[(r, k)] - base[(r, k)]) / delta;
                }
            }
        }
        Ok(out)
    }

    /// `ż = (f, c_k (J s_k + ∂f/∂p_k))` with `c_k s_k` read from `z`
    /// (`Variational::scaled_rate`).
    fn try_rhs(&self, t: f64, z: &SVector<f64, M>) -> Result<SVector<f64, M>, ModelError> {
        let (y, cs) = Self::split(z);
        let f = self.system.try_rhs(t, &y)?;
        let rate = self.scaled_rate(t, &y, &cs)?;
        let mut out = SVector::<f64, M>::zeros();
        out.fixed_rows_mut::<N>(0).copy_from(&f);
        for k in 0..P {
            out.fixed_rows_mut::<N>(N + k * N)
                .copy_from(&rate.column(k));
        }
        Ok(out)
    }
}
