//! Used by the Rosenbrock table (`tests/integrate/rosenbrock.rs`): the linear
//! stability function of a tableau, its stiff-accuracy defect, a
//! non-autonomous scalar problem with a closed-form solution, and fixed-step
//! options.

#![allow(dead_code)]

use nalgebra::{DMatrix, DVector, Matrix1, SMatrix, SVector};
use pegdyn::integrate::Options;
use pegdyn::integrate::tableau::RosenbrockTableau;
use pegdyn::system::OdeSystem;

/// Stability function `R(z) = 1 + z bᵀ (I − zB)⁻¹ 𝟙`, `B = α + Γ`.
pub fn stability<const S: usize>(t: &RosenbrockTableau<S>, z: f64) -> f64 {
    let mut m = DMatrix::<f64>::identity(S, S);
    for i in 0..S {
        for j in 0..i {
            m[(i, j)] -= z * (t.alpha[i][j] + t.gamma_lower[i][j]);
        }
        m[(i, i)] -= z * t.gamma;
    }
    let y = m
        .lu()
        .solve(&DVector::<f64>::repeat(S, 1.0))
        .expect("regular");
    1.0 + z * DVector::<f64>::from_column_slice(&t.b).dot(&y)
}

/// Largest `|b_j − B_{s,j}|`: zero when the method is stiffly accurate
/// (`b` is the last row of `B = α + Γ`, hence `R(∞) = 0`).
pub fn stiff_accuracy_defect<const S: usize>(t: &RosenbrockTableau<S>) -> f64 {
    (0..S)
        .map(|j| {
            let last = t.alpha[S - 1][j]
                + t.gamma_lower[S - 1][j]
                + if j == S - 1 { t.gamma } else { 0.0 };
            (t.b[j] - last).abs()
        })
        .fold(0.0, f64::max)
}

/// ẋ = cos(t)·x (non-autonomous), exact x₀ e^{sin t}; exact Jacobian and
/// ∂f/∂t so the order is not blurred by finite differences.
pub struct Modulated;
impl OdeSystem<1> for Modulated {
    fn rhs(&self, t: f64, x: &SVector<f64, 1>) -> SVector<f64, 1> {
        x * t.cos()
    }
    fn jacobian(&self, t: f64, _x: &SVector<f64, 1>) -> SMatrix<f64, 1, 1> {
        Matrix1::new(t.cos())
    }
    fn time_derivative(&self, t: f64, x: &SVector<f64, 1>) -> SVector<f64, 1> {
        -x * t.sin()
    }
}

/// Effectively fixed steps: huge tolerances, `h0 = h_max = h`.
pub fn fixed_step(h: f64) -> Options {
    Options {
        h0: Some(h),
        h_max: Some(h),
        ..Options::with_tolerances(1e6, 1e6)
    }
}
