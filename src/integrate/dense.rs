//! Dense output: the interpolant of one accepted step.
//!
//! Used for output at requested times and to locate events
//! ([`super::events`]) without re-integrating.

use nalgebra::SVector;

use super::tableau::dopri5_dense_weights;

/// The interpolant of the accepted step `[t0, t0 + h]`.
#[derive(Debug, Clone)]
pub(crate) enum Interpolant<const N: usize> {
    /// Cubic Hermite through `(x0, f0)` at `t0` and `(x1, f1)` at `t0 + h`
    /// (third order).
    Hermite {
        t0: f64,
        h: f64,
        x0: SVector<f64, N>,
        x1: SVector<f64, N>,
        f0: SVector<f64, N>,
        f1: SVector<f64, N>,
    },
    /// DOPRI5's fourth-order continuous extension from its seven stages.
    Dopri5 {
        t0: f64,
        h: f64,
        x0: SVector<f64, N>,
        k: [SVector<f64, N>; 7],
    },
}

impl<const N: usize> Interpolant<N> {
    /// The interpolated state at time `t` (meant for `t` inside the step).
    pub(crate) fn eval(&self, t: f64) -> SVector<f64, N> {
        match self {
            Interpolant::Hermite {
                t0,
                h,
                x0,
                x1,
                f0,
                f1,
            } => {
                let theta = (t - t0) / h;
                let s = 1.0 - theta;
                // Hermite basis: x0 h00 + h f0 h10 + x1 h01 + h f1 h11.
                let h00 = s * s * (1.0 + 2.0 * theta);
                let h01 = theta * theta * (3.0 - 2.0 * theta);
                let h10 = theta * s * s;
                let h11 = -theta * theta * s;
                x0 * h00 + x1 * h01 + f0 * (h * h10) + f1 * (h * h11)
            }
            Interpolant::Dopri5 { t0, h, x0, k } => {
                let w = dopri5_dense_weights((t - t0) / h);
                let mut x = *x0;
                for (wi, ki) in w.iter().zip(k) {
                    x.axpy(h * wi, ki, 1.0);
                }
                x
            }
        }
    }
}
