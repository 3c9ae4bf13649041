//! The Rosenbrock (linearly implicit) stepper for stiff systems.
//!
//! Runs a [`RosenbrockTableau`] in the transformed form of Hairer & Wanner
//! II, §IV.7, eq. (7.25), which needs no matrix–vector products:
//! `(I/(hγ) − J) uᵢ = f(t + αᵢh, x + Σⱼ<ᵢ aᵢⱼuⱼ) + Σⱼ<ᵢ (cᵢⱼ/h) uⱼ + γᵢh ∂f/∂t`,
//! `x₁ = x + Σ mᵢuᵢ`, one LU factorization per step (of the velocities
//! only when `J` has a second-order system's block form or the system
//! declares a kinematic split: `super::iteration`). `J` and `∂f/∂t` are
//! evaluated once per step start and reused when the step is retried.
//! Dense output is the cubic Hermite interpolant of the step.

use nalgebra::{SMatrix, SVector};

use crate::system::OdeSystem;

use super::dense::Interpolant;
use super::driver::{Attempt, Stepper};
use super::iteration::IterationLu;
use super::solution::Stats;
use super::tableau::RosenbrockTableau;

/// Transformed coefficients (eq. (7.25)) derived from a tableau.
#[derive(Debug, Clone)]
struct Transformed<const S: usize> {
    gamma: f64,
    a: [[f64; S]; S],
    c: [[f64; S]; S],
    m: [f64; S],
    /// `m − m̂`: weights of the error estimate.
    e: [f64; S],
    /// Stage time offsets `αᵢ`.
    alpha: [f64; S],
    /// `γᵢ = Σⱼ≤ᵢ γᵢⱼ`.
    gamma_sum: [f64; S],
}

impl<const S: usize> Transformed<S> {
    fn new(tab: &RosenbrockTableau<S>) -> Self {
        // Γ lower triangular with diagonal γ; invert by forward substitution.
        let mut big_gamma = tab.gamma_lower;
        for (i, row) in big_gamma.iter_mut().enumerate() {
            row[i] = tab.gamma;
        }
        let mut inv = [[0.0; S]; S];
        for i in 0..S {
            let mut row = [0.0; S];
            row[i] = 1.0 / tab.gamma;
            for (j, r) in row.iter_mut().enumerate().take(i) {
                let s: f64 = (j..i).map(|k| big_gamma[i][k] * inv[k][j]).sum();
                *r = -s / tab.gamma;
            }
            inv[i] = row;
        }
        let row_times_inv = |v: &[f64; S]| {
            let mut out = [0.0; S];
            for (j, o) in out.iter_mut().enumerate() {
                *o = (0..S).map(|k| v[k] * inv[k][j]).sum();
            }
            out
        };
        let mut a = [[0.0; S]; S];
        let mut c = [[0.0; S]; S];
        let mut alpha = [0.0; S];
        let mut gamma_sum = [0.0; S];
        for i in 0..S {
            a[i] = row_times_inv(&tab.alpha[i]);
            for j in 0..i {
                c[i][j] = -inv[i][j];
            }
            alpha[i] = tab.alpha[i].iter().sum();
            gamma_sum[i] = big_gamma[i].iter().sum();
        }
        let m = row_times_inv(&tab.b);
        let m_hat = row_times_inv(&tab.b_embedded);
        let mut e = [0.0; S];
        for i in 0..S {
            e[i] = m[i] - m_hat[i];
        }
        Transformed {
            gamma: tab.gamma,
            a,
            c,
            m,
            e,
            alpha,
            gamma_sum,
        }
    }
}

/// Stepper state for a Rosenbrock tableau with `S` stages on `ℝᴺ`.
#[derive(Debug, Clone)]
pub(crate) struct Rosenbrock<const N: usize, const S: usize> {
    order: u32,
    embedded_order: u32,
    coef: Transformed<S>,
    u: [SVector<f64, N>; S],
    /// `J` and `∂f/∂t` at the last step start.
    linearization: Option<Linearization<N>>,
}

/// The Jacobian and time derivative at `(t, x)`.
#[derive(Debug, Clone)]
struct Linearization<const N: usize> {
    t: f64,
    x: SVector<f64, N>,
    jac: SMatrix<f64, N, N>,
    dfdt: SVector<f64, N>,
}

impl<const N: usize, const S: usize> Rosenbrock<N, S> {
    pub(crate) fn new(tableau: &RosenbrockTableau<S>) -> Self {
        Rosenbrock {
            order: tableau.order,
            embedded_order: tableau.embedded_order,
            coef: Transformed::new(tableau),
            u: [SVector::zeros(); S],
            linearization: None,
        }
    }
}

fn all_finite<const N: usize>(v: &SVector<f64, N>) -> bool {
    v.iter().all(|c| c.is_finite())
}

impl<const N: usize, const S: usize> Stepper<N> for Rosenbrock<N, S> {
    fn order(&self) -> u32 {
        self.order
    }

    fn controller_order(&self) -> Option<u32> {
        Some(self.order.min(self.embedded_order) + 1)
    }

    fn attempt<Sys: OdeSystem<N>>(
        &mut self,
        system: &Sys,
        t: f64,
        x: &SVector<f64, N>,
        f0: &SVector<f64, N>,
        h: f64,
        stats: &mut Stats,
    ) -> Attempt<N> {
        let lin: &Linearization<N> = match &mut self.linearization {
            Some(l) if l.t == t && l.x == *x => l,
            slot => {
                stats.jacobian_calls += 1;
                stats.time_derivative_calls += 1;
                slot.insert(Linearization {
                    t,
                    x: *x,
                    jac: system.jacobian(t, x),
                    dfdt: system.time_derivative(t, x),
                })
            }
        };
        let dfdt = &lin.dfdt;
        let k = &self.coef;
        stats.lu_factorizations += 1;
        let Some(lu) = IterationLu::new(
            &lin.jac,
            1.0 / (h * k.gamma),
            system.kinematic_split(),
            system.variational_blocks(),
        ) else {
            return Attempt::Singular;
        };
        for i in 0..S {
            let moved = (0..i).any(|j| k.a[i][j] != 0.0);
            let f = if moved || k.alpha[i] != 0.0 {
                let mut stage_x = *x;
                for j in 0..i {
                    stage_x.axpy(k.a[i][j], &self.u[j], 1.0);
                }
                let f = system.rhs(t + k.alpha[i] * h, &stage_x);
                stats.rhs_calls += 1;
                if !all_finite(&f) {
                    return Attempt::NonFinite;
                }
                f
            } else {
                *f0
            };
            let mut rhs = f + dfdt * (k.gamma_sum[i] * h);
            for j in 0..i {
                rhs.axpy(k.c[i][j] / h, &self.u[j], 1.0);
            }
            let ui = lu.solve(&rhs);
            if !all_finite(&ui) {
                return Attempt::NonFinite;
            }
            self.u[i] = ui;
        }
        let mut x1 = *x;
        let mut err = SVector::<f64, N>::zeros();
        for i in 0..S {
            x1.axpy(k.m[i], &self.u[i], 1.0);
            err.axpy(k.e[i], &self.u[i], 1.0);
        }
        let f1 = system.rhs(t + h, &x1);
        stats.rhs_calls += 1;
        if !all_finite(&x1) || !all_finite(&f1) {
            return Attempt::NonFinite;
        }
        Attempt::Done {
            x1,
            f1,
            err: Some(err),
        }
    }

    fn interpolant(
        &self,
        t0: f64,
        h: f64,
        (x0, f0): (&SVector<f64, N>, &SVector<f64, N>),
        (x1, f1): (&SVector<f64, N>, &SVector<f64, N>),
    ) -> Interpolant<N> {
        Interpolant::Hermite {
            t0,
            h,
            x0: *x0,
            x1: *x1,
            f0: *f0,
            f1: *f1,
        }
    }
}
