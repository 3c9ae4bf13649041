//! The one explicit Runge–Kutta engine: runs any [`Tableau`] step by step.
//! Allocation-free: stages live in a fixed array of fixed-size vectors.

use nalgebra::SVector;

use crate::system::OdeSystem;

use super::dense::Interpolant;
use super::driver::{Attempt, Stepper};
use super::solution::Stats;
use super::tableau::{DenseKind, Tableau};

/// Stepper state for an explicit tableau with `S` stages on `ℝᴺ`.
#[derive(Debug, Clone)]
pub(crate) struct ExplicitRk<const N: usize, const S: usize> {
    tableau: Tableau<S>,
    /// Error weights `b − b̂`, if the tableau has an embedded pair.
    error_weights: Option<[f64; S]>,
    /// Stage derivatives `kᵢ` of the last attempted step.
    k: [SVector<f64, N>; S],
}

impl<const N: usize, const S: usize> ExplicitRk<N, S> {
    pub(crate) fn new(tableau: Tableau<S>) -> Self {
        let error_weights = tableau.b_embedded.map(|b_hat| {
            let mut e = [0.0; S];
            for (ei, (b, bh)) in e.iter_mut().zip(tableau.b.iter().zip(b_hat)) {
                *ei = b - bh;
            }
            e
        });
        ExplicitRk {
            tableau,
            error_weights,
            k: [SVector::zeros(); S],
        }
    }

    /// `x + h Σ wᵢ kᵢ` over the current stages.
    fn combine(&self, x: &SVector<f64, N>, h: f64, w: &[f64; S], upto: usize) -> SVector<f64, N> {
        let mut out = *x;
        for (wj, kj) in w.iter().zip(&self.k).take(upto) {
            if *wj != 0.0 {
                out.axpy(h * wj, kj, 1.0);
            }
        }
        out
    }
}

fn all_finite<const N: usize>(v: &SVector<f64, N>) -> bool {
    v.iter().all(|c| c.is_finite())
}

impl<const N: usize, const S: usize> Stepper<N> for ExplicitRk<N, S> {
    fn order(&self) -> u32 {
        self.tableau.order
    }

    fn controller_order(&self) -> Option<u32> {
        self.tableau
            .b_embedded
            .map(|_| self.tableau.order.min(self.tableau.embedded_order) + 1)
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
        let tab = &self.tableau;
        self.k[0] = *f0;
        let mut stage_x = *x;
        for i in 1..S {
            stage_x = self.combine(x, h, &tab.a[i], i);
            let ki = system.rhs(t + tab.c[i] * h, &stage_x);
            stats.rhs_calls += 1;
            if !all_finite(&ki) {
                return Attempt::NonFinite;
            }
            self.k[i] = ki;
        }
        let (x1, f1) = if tab.fsal {
            (stage_x, self.k[S - 1])
        } else {
            let x1 = self.combine(x, h, &tab.b, S);
            if !all_finite(&x1) {
                return Attempt::NonFinite;
            }
            let f1 = system.rhs(t + h, &x1);
            stats.rhs_calls += 1;
            (x1, f1)
        };
        if !all_finite(&x1) || !all_finite(&f1) {
            return Attempt::NonFinite;
        }
        let err = self
            .error_weights
            .map(|e| self.combine(&SVector::zeros(), h, &e, S));
        Attempt::Done { x1, f1, err }
    }

    fn interpolant(
        &self,
        t0: f64,
        h: f64,
        (x0, f0): (&SVector<f64, N>, &SVector<f64, N>),
        (x1, f1): (&SVector<f64, N>, &SVector<f64, N>),
    ) -> Interpolant<N> {
        match self.tableau.dense {
            DenseKind::Dopri5 if S == 7 => {
                let mut k = [SVector::zeros(); 7];
                k.copy_from_slice(&self.k[..7]);
                Interpolant::Dopri5 { t0, h, x0: *x0, k }
            }
            _ => Interpolant::Hermite {
                t0,
                h,
                x0: *x0,
                x1: *x1,
                f0: *f0,
                f1: *f1,
            },
        }
    }
}
