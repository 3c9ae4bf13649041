//! Forward sensitivities of the compliant planar peg along `Q` directions
//! in its parameter space: design quantities `q` that move several model
//! parameters at once (a hole diameter moves the peg radius, the mass, the
//! inertia and the Hertz stiffnesses). With `P = ∂p/∂q` (24 × Q, the model
//! parameters' derivatives, computed by the caller) the variational
//! equations along `q` are
//!
//! ```text
//! ṡ_q = J s_q + (∂f/∂p) P,   s_q(t₀) = ∂y₀/∂q,
//! ```
//!
//! `∂f/∂p` being the generated `rhs_p`. The events' gradients in `q` are
//! `g_q = g_p P` (plus a direct term where an event's threshold is itself
//! one of the `q`, [`CompliantDirections::depth_event`]). See
//! `docs/sensitivities.md`.

use nalgebra::{SMatrix, SVector};

use super::params::{CompliantParams, Load, N_PARAMS};
use super::system::N_STATE;
use crate::generated::compliant_peg as all;
use crate::integrate::Direction;
use crate::scalar::Dual;
use crate::sensitivity::{ParameterJacobian, SensitivityError, SensitivityEvent};

/// Dual numbers seeded in the 8 states and the 24 parameters.
type D = Dual<{ N_STATE + N_PARAMS }>;

/// Dual numbers seeded in the 8 states only.
type Dy = Dual<N_STATE>;

/// The compliant planar peg under a constant load, with sensitivities along
/// `Q` directions `∂p/∂q` in its parameter space.
#[derive(Clone, Debug, PartialEq)]
pub struct CompliantDirections<const Q: usize> {
    p: SVector<f64, N_PARAMS>,
    dp: SMatrix<f64, N_PARAMS, Q>,
    values: SVector<f64, Q>,
}

impl<const Q: usize> CompliantDirections<Q> {
    /// The model of `params` under `load` with directions `dp = ∂p/∂q`
    /// (rows in `compliant_peg::P_NAMES` order) and the directions' values
    /// `q` (which scale the integrated sensitivities; a zero counts as 1).
    ///
    /// # Errors
    /// [`SensitivityError::Unsupported`] for the lean contact set or the
    /// elastic friction law (their parameter Jacobians are not generated).
    pub fn new(
        params: &CompliantParams,
        load: &Load,
        dp: SMatrix<f64, N_PARAMS, Q>,
        values: SVector<f64, Q>,
    ) -> Result<Self, SensitivityError> {
        super::ode_at_parameters::check_supported(params)?;
        Ok(CompliantDirections {
            p: params.vector(load),
            dp,
            values,
        })
    }

    /// The model parameter vector (`compliant_peg::P_NAMES` order).
    pub fn parameter_vector(&self) -> &SVector<f64, N_PARAMS> {
        &self.p
    }

    /// `(∂g/∂y, ∂g/∂q = (∂g/∂p) P)` of a dual value seeded by [`Self::seeded`].
    fn split(&self, g: D) -> (SVector<f64, N_STATE>, SVector<f64, Q>) {
        let g_p = SVector::<f64, N_PARAMS>::from_fn(|k, _| g.d[N_STATE + k]);
        (SVector::from_fn(|i, _| g.d[i]), self.dp.transpose() * g_p)
    }

    fn seeded(&self, y: &SVector<f64, N_STATE>) -> (SVector<D, N_STATE>, SVector<D, N_PARAMS>) {
        (
            SVector::from_fn(|i, _| D::variable(y[i], i)),
            SVector::from_fn(|i, _| D::variable(self.p[i], N_STATE + i)),
        )
    }

    /// The penetration `δ_c` of contact `c` (index into
    /// [`super::sensitivity::CONTACTS`]).
    pub fn delta(&self, c: usize, y: &SVector<f64, N_STATE>) -> f64 {
        all::contacts(y, &self.p).delta[c]
    }

    /// The normal force `F_c` of contact `c` (N).
    pub fn force(&self, c: usize, y: &SVector<f64, N_STATE>) -> f64 {
        all::contacts(y, &self.p).normal[c]
    }

    /// The depth `l` of the bottom face's centre (m).
    pub fn depth(&self, y: &SVector<f64, N_STATE>) -> f64 {
        all::energy(y, &self.p).depth
    }

    /// `(∂F_c/∂y, ∂F_c/∂q)`: the normal force's gradient.
    pub fn force_gradient(
        &self,
        c: usize,
        y: &SVector<f64, N_STATE>,
    ) -> (SVector<f64, N_STATE>, SVector<f64, Q>) {
        let (yd, pd) = self.seeded(y);
        self.split(all::contacts(&yd, &pd).normal[c])
    }

    /// `(∂l/∂y, ∂l/∂q)`: the depth's gradient.
    pub fn depth_gradient(
        &self,
        y: &SVector<f64, N_STATE>,
    ) -> (SVector<f64, N_STATE>, SVector<f64, Q>) {
        let (yd, pd) = self.seeded(y);
        self.split(all::energy(&yd, &pd).depth)
    }

    /// The event `δ_c = 0` of contact `c` (index into
    /// [`super::sensitivity::CONTACTS`]), either direction.
    pub fn contact_event(&self, c: usize) -> SensitivityEvent<'_, N_STATE, Q> {
        SensitivityEvent::new(
            move |_, y| self.delta(c, y),
            move |_, y| {
                let (yd, pd) = self.seeded(y);
                self.split(all::contacts(&yd, &pd).delta[c])
            },
        )
    }

    /// The terminal event "the bottom face's centre reaches `target`" (m),
    /// rising: `g = l(y, p) − target`. When `target` is itself direction
    /// `k` (`target_column = Some(k)`), `∂g/∂q_k` gains `−1`.
    pub fn depth_event(
        &self,
        target: f64,
        target_column: Option<usize>,
    ) -> SensitivityEvent<'_, N_STATE, Q> {
        SensitivityEvent::new(
            move |_, y| self.depth(y) - target,
            move |_, y| {
                let (g_y, mut g_q) = self.depth_gradient(y);
                if let Some(k) = target_column {
                    g_q[k] -= 1.0;
                }
                (g_y, g_q)
            },
        )
        .direction(Direction::Rising)
        .terminal()
    }

    /// `dF_c/dt = (∂F_c/∂y) f(y)`, zero where contact `c`'s force peaks.
    pub fn force_rate(&self, c: usize, y: &SVector<f64, N_STATE>) -> f64 {
        self.rate(y, |out| out.normal[c])
    }

    /// `dδ_c/dt = (∂δ_c/∂y) f(y)`: positive while contact `c` closes.
    pub fn delta_rate(&self, c: usize, y: &SVector<f64, N_STATE>) -> f64 {
        self.rate(y, |out| out.delta[c])
    }

    /// The time derivative `(∂g/∂y) f(y)` of an output `g` of `contacts`.
    fn rate(&self, y: &SVector<f64, N_STATE>, g: impl Fn(&all::ContactsOut<Dy>) -> Dy) -> f64 {
        let yd: SVector<Dy, N_STATE> = SVector::from_fn(|i, _| Dy::variable(y[i], i));
        let pd: SVector<Dy, N_PARAMS> = self.p.map(Dy::constant);
        let g = g(&all::contacts(&yd, &pd));
        let f = all::rhs(y, &self.p);
        (0..N_STATE).map(|i| g.d[i] * f[i]).sum()
    }

    /// The terminal event "contact `c`'s force reaches a maximum":
    /// `dF_c/dt` falling through zero. Its state gradient is a central
    /// difference of `dF_c/dt` (its time's sensitivity is not used: at a
    /// peak the force's derivative is `∂F/∂y s + ∂F/∂q` whatever the peak's
    /// time does); its `∂g/∂q` is zero.
    pub fn peak_event(&self, c: usize) -> SensitivityEvent<'_, N_STATE, Q> {
        SensitivityEvent::new(
            move |_, y| self.force_rate(c, y),
            move |_, y| {
                let g_y = SVector::from_fn(|i, _| {
                    let h = 1e-7 * y[i].abs().max(1e-6);
                    let (mut up, mut down) = (*y, *y);
                    up[i] += h;
                    down[i] -= h;
                    (self.force_rate(c, &up) - self.force_rate(c, &down)) / (2.0 * h)
                });
                (g_y, SVector::zeros())
            },
        )
        .direction(Direction::Falling)
        .terminal()
    }
}

super::ode_at_parameters::impl_ode_at_parameters!(CompliantDirections, Q);

impl<const Q: usize> ParameterJacobian<N_STATE, Q> for CompliantDirections<Q> {
    fn parameters(&self) -> SVector<f64, Q> {
        self.values
    }

    /// `(∂f/∂p) P`: the generated `rhs_p` along the directions.
    fn parameter_jacobian(&self, _t: f64, y: &SVector<f64, N_STATE>) -> SMatrix<f64, N_STATE, Q> {
        all::rhs_p(y, &self.p) * self.dp
    }
}
