//! Textbook systems with known solutions, written once for tests and
//! benches (and independent of code generation).
//!
//! Every problem implements [`OdeSystem`] with a hand-written right-hand
//! side and exact Jacobian, and says what is known about its solution.

use nalgebra::{Matrix1, Matrix2, SMatrix, SVector, Vector1, Vector2};

use crate::system::OdeSystem;

/// `ẋ = −λx`; exact solution `x(t) = x₀ e^{−λt}`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExponentialDecay {
    /// Decay rate λ (1/time).
    pub lambda: f64,
}

impl ExponentialDecay {
    /// The exact solution from `x0` at `t = 0`.
    pub fn exact(&self, x0: f64, t: f64) -> Vector1<f64> {
        Vector1::new(x0 * (-self.lambda * t).exp())
    }
}

impl OdeSystem<1> for ExponentialDecay {
    fn rhs(&self, _t: f64, x: &SVector<f64, 1>) -> SVector<f64, 1> {
        -self.lambda * x
    }
    fn jacobian(&self, _t: f64, _x: &SVector<f64, 1>) -> SMatrix<f64, 1, 1> {
        Matrix1::new(-self.lambda)
    }
    fn time_derivative(&self, _t: f64, _x: &SVector<f64, 1>) -> SVector<f64, 1> {
        SVector::zeros()
    }
}

/// Harmonic oscillator `q̈ = −ω²q`, state `(q, q̇)`.
///
/// Exact: `q = q₀ cos ωt + (q̇₀/ω) sin ωt`; the energy
/// `E = (q̇² + ω²q²)/2` is constant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicOscillator {
    /// Angular frequency ω (rad/time).
    pub omega: f64,
}

impl HarmonicOscillator {
    /// The exact solution from `x0` at `t = 0`.
    pub fn exact(&self, x0: &Vector2<f64>, t: f64) -> Vector2<f64> {
        let (s, c) = (self.omega * t).sin_cos();
        let w = self.omega;
        Vector2::new(x0[0] * c + x0[1] / w * s, -x0[0] * w * s + x0[1] * c)
    }

    /// The energy per unit mass `(q̇² + ω²q²)/2`.
    pub fn energy(&self, x: &Vector2<f64>) -> f64 {
        0.5 * (x[1] * x[1] + self.omega * self.omega * x[0] * x[0])
    }
}

impl OdeSystem<2> for HarmonicOscillator {
    fn rhs(&self, _t: f64, x: &SVector<f64, 2>) -> SVector<f64, 2> {
        Vector2::new(x[1], -self.omega * self.omega * x[0])
    }
    fn jacobian(&self, _t: f64, _x: &SVector<f64, 2>) -> SMatrix<f64, 2, 2> {
        Matrix2::new(0.0, 1.0, -self.omega * self.omega, 0.0)
    }
    fn time_derivative(&self, _t: f64, _x: &SVector<f64, 2>) -> SVector<f64, 2> {
        SVector::zeros()
    }
}

/// Linear stiff system `ẋ = A x` with `A = P diag(λ_slow, λ_fast) P⁻¹`,
/// `P = [[1, 1], [1, −1]]`: eigenvalues `λ_slow` (e.g. −1) and `λ_fast`
/// (e.g. −10⁴) along the directions `(1, 1)` and `(1, −1)`.
///
/// Exact: `x(t) = P diag(e^{λ_slow t}, e^{λ_fast t}) P⁻¹ x₀`. Once the fast
/// mode has decayed an explicit method is still limited to
/// `h ≲ 3.3/|λ_fast|` by stability, an L-stable method is not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StiffLinear {
    /// Slow eigenvalue (1/time, negative).
    pub lambda_slow: f64,
    /// Fast eigenvalue (1/time, negative, `|λ_fast| ≫ |λ_slow|`).
    pub lambda_fast: f64,
}

impl StiffLinear {
    /// Eigenvalues −1 and −10⁴ (stiffness ratio 10⁴).
    pub fn standard() -> Self {
        StiffLinear {
            lambda_slow: -1.0,
            lambda_fast: -1e4,
        }
    }

    fn matrix(&self) -> Matrix2<f64> {
        let (s, f) = (self.lambda_slow, self.lambda_fast);
        Matrix2::new(s + f, s - f, s - f, s + f) * 0.5
    }

    /// The exact solution from `x0` at `t = 0`.
    pub fn exact(&self, x0: &Vector2<f64>, t: f64) -> Vector2<f64> {
        let slow = 0.5 * (x0[0] + x0[1]) * (self.lambda_slow * t).exp();
        let fast = 0.5 * (x0[0] - x0[1]) * (self.lambda_fast * t).exp();
        Vector2::new(slow + fast, slow - fast)
    }
}

impl OdeSystem<2> for StiffLinear {
    fn rhs(&self, _t: f64, x: &SVector<f64, 2>) -> SVector<f64, 2> {
        self.matrix() * x
    }
    fn jacobian(&self, _t: f64, _x: &SVector<f64, 2>) -> SMatrix<f64, 2, 2> {
        self.matrix()
    }
    fn time_derivative(&self, _t: f64, _x: &SVector<f64, 2>) -> SVector<f64, 2> {
        SVector::zeros()
    }
}

/// Van der Pol oscillator `ẍ − μ(1 − x²)ẋ + x = 0`, state `(x, ẋ)`.
///
/// Stiff for large μ (relaxation oscillations of period ≈ (3 − 2 ln 2) μ).
/// No closed form: tests compare against a very tight reference run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VanDerPol {
    /// Damping parameter μ (dimensionless).
    pub mu: f64,
}

impl OdeSystem<2> for VanDerPol {
    fn rhs(&self, _t: f64, x: &SVector<f64, 2>) -> SVector<f64, 2> {
        Vector2::new(x[1], self.mu * (1.0 - x[0] * x[0]) * x[1] - x[0])
    }
    fn jacobian(&self, _t: f64, x: &SVector<f64, 2>) -> SMatrix<f64, 2, 2> {
        Matrix2::new(
            0.0,
            1.0,
            -2.0 * self.mu * x[0] * x[1] - 1.0,
            self.mu * (1.0 - x[0] * x[0]),
        )
    }
    fn time_derivative(&self, _t: f64, _x: &SVector<f64, 2>) -> SVector<f64, 2> {
        SVector::zeros()
    }
}

/// Simple pendulum `θ̈ = −(g/l) sin θ`, state `(θ, θ̇)` in rad and rad/s.
///
/// Released from rest at `θ₀`, it first reaches `θ = 0` after a quarter
/// period `K(sin(θ₀/2)) / √(g/l)` ([`Pendulum::quarter_period`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pendulum {
    /// Gravity over length, `g/l` (1/s²).
    pub g_over_l: f64,
}

impl Pendulum {
    /// Time from rest at amplitude `theta0` (rad, `|θ₀| < π`) to the first
    /// zero crossing: `K(k)/√(g/l)`, `k = sin(θ₀/2)`.
    pub fn quarter_period(&self, theta0: f64) -> f64 {
        elliptic_k((0.5 * theta0).sin()) / self.g_over_l.sqrt()
    }

    /// Energy per unit `m l²`: `θ̇²/2 + (g/l)(1 − cos θ)`.
    pub fn energy(&self, x: &Vector2<f64>) -> f64 {
        0.5 * x[1] * x[1] + self.g_over_l * (1.0 - x[0].cos())
    }
}

impl OdeSystem<2> for Pendulum {
    fn rhs(&self, _t: f64, x: &SVector<f64, 2>) -> SVector<f64, 2> {
        Vector2::new(x[1], -self.g_over_l * x[0].sin())
    }
    fn jacobian(&self, _t: f64, x: &SVector<f64, 2>) -> SMatrix<f64, 2, 2> {
        Matrix2::new(0.0, 1.0, -self.g_over_l * x[0].cos(), 0.0)
    }
    fn time_derivative(&self, _t: f64, _x: &SVector<f64, 2>) -> SVector<f64, 2> {
        SVector::zeros()
    }
}

/// Complete elliptic integral of the first kind `K(k) = ∫₀^{π/2} dφ/√(1 − k² sin²φ)`
/// (modulus `k`, `|k| < 1`), as Carlson's `K = R_F(0, 1 − k², 1)`
/// ([`crate::hertz::elliptic::carlson_rf`], the crate's one elliptic-integral
/// implementation).
///
/// ```
/// // K(1/√2) = Γ(1/4)² / (4√π) = 1.854074677301372 (Abramowitz & Stegun 17.3).
/// let k = pegdyn::reference_problems::elliptic_k(std::f64::consts::FRAC_1_SQRT_2);
/// assert!((k - 1.854074677301372).abs() < 1e-14);
/// ```
pub fn elliptic_k(k: f64) -> f64 {
    crate::hertz::elliptic::carlson_rf(0.0, 1.0 - k * k, 1.0)
}
