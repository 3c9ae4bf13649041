//! The interface between a model and the integrators.
//!
//! A model is a first-order system `ẋ = f(t, x)` with a fixed state dimension
//! `N`. Generated models (see `src/generated.rs`) implement [`OdeSystem`]
//! with their exact right-hand side and exact Jacobian; hand-written systems
//! (tests, [`crate::reference_problems`]) may rely on the finite-difference
//! defaults.
//!
//! Everything here works on fixed-size nalgebra types, so no call allocates.
//!
//! A model whose equations are not defined at some states (a contact law
//! that cannot be set up there) says why through the fallible forms
//! [`OdeSystem::try_rhs`] and [`OdeSystem::try_jacobian`]; the integrators
//! call those and return the first [`ModelError`] met in
//! [`crate::integrate::Solution::model_error`].

use nalgebra::{SMatrix, SVector};

/// Why a model cannot evaluate its equations at a state.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// A Hertz contact could not be set up at the state (for the compliant
    /// 3-D peg: a contact whose relative curvatures are not positive).
    #[error(transparent)]
    Hertz(#[from] crate::hertz::HertzError),
}

/// How a mechanical system's state splits for the linear solves of the
/// implicit integrators: `positions` components `x` first, then
/// `velocities` components `u`, then integrals (work, dissipation) that no
/// rate reads (their columns of the Jacobian are zero), with the positions'
/// rates a kinematic map of the velocities, `ẋ = K(x) u` (`ṗ = v` and
/// `q̇ = ½ q ⊗ (0, ω)` for a rigid body with a unit quaternion). The
/// Rosenbrock methods then factorize an `n_u × n_u` Schur complement
/// instead of the whole `N × N` iteration matrix (see
/// [`OdeSystem::kinematic_split`]). Only a speed-up: the solution is the
/// same to rounding, and a Jacobian that does not have this form (a
/// non-zero column of an integral) is factorized whole.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KinematicSplit {
    /// Number of position components `n_x`.
    pub positions: usize,
    /// Number of velocity components `n_u`.
    pub velocities: usize,
}

/// A system of ordinary differential equations `ẋ = f(t, x)`, `x ∈ ℝᴺ`.
///
/// The integrators in [`crate::integrate`] count how often they call
/// [`rhs`](OdeSystem::rhs), [`jacobian`](OdeSystem::jacobian) and
/// [`time_derivative`](OdeSystem::time_derivative) (see
/// [`crate::integrate::Stats`]); implementations need not count anything.
///
/// ```
/// use nalgebra::{SMatrix, SVector, Vector2};
/// use pegdyn::system::OdeSystem;
///
/// /// Harmonic oscillator `q̈ = −q` as `x = (q, q̇)`.
/// struct Oscillator;
/// impl OdeSystem<2> for Oscillator {
///     fn rhs(&self, _t: f64, x: &SVector<f64, 2>) -> SVector<f64, 2> {
///         Vector2::new(x[1], -x[0])
///     }
/// }
///
/// // The default Jacobian is a forward finite difference of `rhs`.
/// let j: SMatrix<f64, 2, 2> = Oscillator.jacobian(0.0, &Vector2::new(0.3, 0.1));
/// assert!((j[(0, 1)] - 1.0).abs() < 1e-7 && (j[(1, 0)] + 1.0).abs() < 1e-7);
/// ```
pub trait OdeSystem<const N: usize> {
    /// The right-hand side `f(t, x)`, in the units of the state per unit time.
    fn rhs(&self, t: f64, x: &SVector<f64, N>) -> SVector<f64, N>;

    /// The right-hand side, or why the model cannot evaluate it at
    /// `(t, x)`. The integrators call this form. The default is
    /// `Ok(rhs(t, x))`; a model that can fail overrides it (and then
    /// returns NaN from [`rhs`](OdeSystem::rhs) where this fails).
    ///
    /// # Errors
    /// The model's [`ModelError`] at `(t, x)`.
    fn try_rhs(&self, t: f64, x: &SVector<f64, N>) -> Result<SVector<f64, N>, ModelError> {
        Ok(self.rhs(t, x))
    }

    /// The Jacobian `∂f/∂x` at `(t, x)`, entry `(i, j) = ∂fᵢ/∂xⱼ`.
    ///
    /// The default is a forward finite difference: column `j` is
    /// `(f(t, x + δⱼ eⱼ) − f(t, x)) / δⱼ` with `δⱼ = √ε · max(|xⱼ|, 1)`
    /// (ε the machine epsilon), which costs `N + 1` calls of
    /// [`rhs`](OdeSystem::rhs) and is accurate to about `√ε ≈ 1.5e-8`
    /// relative. Implicit integrators only use the Jacobian in the iteration
    /// matrix, so this accuracy is enough for convergence, but generated
    /// models override it with the exact symbolic Jacobian.
    fn jacobian(&self, t: f64, x: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        finite_difference_jacobian(|x| self.rhs(t, x), x)
    }

    /// The Jacobian, or why the model cannot evaluate it at `(t, x)`: as
    /// [`try_rhs`](OdeSystem::try_rhs) to [`rhs`](OdeSystem::rhs). The
    /// default is `Ok(jacobian(t, x))`.
    ///
    /// # Errors
    /// The model's [`ModelError`] at `(t, x)`.
    fn try_jacobian(&self, t: f64, x: &SVector<f64, N>) -> Result<SMatrix<f64, N, N>, ModelError> {
        Ok(self.jacobian(t, x))
    }

    /// The partial time derivative `∂f/∂t` at `(t, x)`, needed by
    /// Rosenbrock methods for non-autonomous systems.
    ///
    /// The default is the forward difference
    /// `(f(t + δ, x) − f(t, x)) / δ` with `δ = √ε · max(|t|, 1)` (two calls
    /// of [`rhs`](OdeSystem::rhs)). Autonomous systems, such as all the
    /// generated rigid-body models, should override it to return zero.
    fn time_derivative(&self, t: f64, x: &SVector<f64, N>) -> SVector<f64, N> {
        let delta = f64::EPSILON.sqrt() * t.abs().max(1.0);
        // Make t + delta exactly representable so the quotient is consistent.
        let t1 = t + delta;
        let delta = t1 - t;
        (self.rhs(t1, x) - self.rhs(t, x)) / delta
    }

    /// The split of the state into positions with a kinematic map,
    /// velocities and integrals ([`KinematicSplit`]), if the model has
    /// one; `None` (the default) otherwise. A second-order system
    /// `ẋ = u` need not declare it: its unit position rows are recognized
    /// in the Jacobian itself.
    fn kinematic_split(&self) -> Option<KinematicSplit> {
        None
    }

    /// `Some(n)` for a state of `N / n` blocks of `n` components whose
    /// Jacobian is block lower-triangular with every diagonal block equal
    /// to the first and no off-diagonal block outside the first block
    /// column, the form of a state with its forward sensitivities
    /// (`z = (y, s₁, …, s_P)`, `ż = (f, J s₁ + ∂f/∂p₁, …)`):
    ///
    /// ```text
    ///       y    s₁   s₂
    /// J = [ J    0    0 ]
    ///     [ B₁   J    0 ]     Bₖ = ∂(J sₖ + ∂f/∂pₖ)/∂y
    ///     [ B₂   0    J ]
    /// ```
    ///
    /// The Rosenbrock methods then factorize `cI − J` at the block's size
    /// once per step and solve the blocks in turn: `(cI − J) u₀ = r₀`,
    /// `(cI − J) uₖ = rₖ + Bₖ u₀`. `None` (the default): no such form.
    fn variational_blocks(&self) -> Option<usize> {
        None
    }

    /// Names of the state components in order (e.g. the generated
    /// model's `X_NAMES`), used to name a component that turns non-finite;
    /// empty (the default) when the system has none.
    fn state_names(&self) -> &'static [&'static str] {
        &[]
    }
}

/// A forward finite-difference Jacobian of `f` at `x` (see
/// [`OdeSystem::jacobian`] for the step rule). Costs `N + 1` calls of `f`.
pub fn finite_difference_jacobian<const N: usize>(
    f: impl Fn(&SVector<f64, N>) -> SVector<f64, N>,
    x: &SVector<f64, N>,
) -> SMatrix<f64, N, N> {
    let f0 = f(x);
    let mut jac = SMatrix::<f64, N, N>::zeros();
    let mut xp = *x;
    for j in 0..N {
        let delta = f64::EPSILON.sqrt() * x[j].abs().max(1.0);
        xp[j] = x[j] + delta;
        // The representable step, so that (f(xp) - f0) / delta is consistent.
        let delta = xp[j] - x[j];
        jac.set_column(j, &((f(&xp) - f0) / delta));
        xp[j] = x[j];
    }
    jac
}

/// Adapts a closure `|t, x| -> ẋ` to an [`OdeSystem`] (finite-difference
/// Jacobian and time derivative).
///
/// ```
/// use nalgebra::Vector1;
/// use pegdyn::system::{FnSystem, OdeSystem};
///
/// let decay = FnSystem(|_t: f64, x: &Vector1<f64>| -2.0 * x);
/// assert_eq!(decay.rhs(0.0, &Vector1::new(1.5))[0], -3.0);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct FnSystem<F>(pub F);

impl<const N: usize, F> OdeSystem<N> for FnSystem<F>
where
    F: Fn(f64, &SVector<f64, N>) -> SVector<f64, N>,
{
    fn rhs(&self, t: f64, x: &SVector<f64, N>) -> SVector<f64, N> {
        (self.0)(t, x)
    }
}
