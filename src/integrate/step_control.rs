//! Error norm, PI step-size controller and starting step.
//!
//! Follows Hairer, Nørsett & Wanner I, §II.4 (error norm, starting step)
//! and the PI ("Lund-stabilized") controller of their `DOPRI5` code
//! (§IV.2 of volume II): `h_new = h · clamp(0.9 · err⁻ᵅ · err_prev^β)` with
//! `α = 1/q − 0.75β`, `β = 0.2/q`, `q` = (lower of the two orders) + 1.

use nalgebra::SVector;

use crate::system::OdeSystem;

use super::options::Options;
use super::solution::Stats;

/// Weighted RMS norm of the error estimate `err` of the step `x0 → x1`
/// over its first `n` components (all when `n ≥ N`):
/// `√(mean((errᵢ / (atolᵢ + rtol·max(|x0ᵢ|, |x1ᵢ|)))²))` with the
/// tolerances of `o` (`atolᵢ` from [`Options::atol_of`]); not finite when
/// any component of `err` is not, counted or not.
pub(crate) fn error_norm<const N: usize>(
    err: &SVector<f64, N>,
    (x0, x1): (&SVector<f64, N>, &SVector<f64, N>),
    o: &Options,
    n: usize,
) -> f64 {
    let n = n.min(N);
    if n == 0 {
        return 0.0;
    }
    if err.iter().skip(n).any(|e| !e.is_finite()) {
        return f64::NAN;
    }
    let mut sum = 0.0;
    for i in 0..n {
        let scale = o.atol_of(i) + o.rtol * x0[i].abs().max(x1[i].abs());
        sum += (err[i] / scale).powi(2);
    }
    (sum / n as f64).sqrt()
}

/// The PI step-size controller.
#[derive(Debug, Clone)]
pub(crate) struct PiController {
    alpha: f64,
    beta: f64,
    err_prev: f64,
}

/// Safety factor on the predicted optimal step.
const SAFETY: f64 = 0.9;
/// Largest step decrease factor per step.
const SHRINK_LIMIT: f64 = 0.2;
/// Largest step increase factor per step.
const GROW_LIMIT: f64 = 10.0;

impl PiController {
    /// A controller for an error estimate of order `q − 1` (so the local
    /// error behaves like `h^q`).
    pub(crate) fn new(q: u32) -> Self {
        let q = f64::from(q.max(1));
        let beta = 0.2 / q;
        PiController {
            alpha: 1.0 / q - 0.75 * beta,
            beta,
            err_prev: 1e-4,
        }
    }

    /// Next step after accepting a step of size `h` with error norm `err ≤ 1`.
    pub(crate) fn accepted(&mut self, h: f64, err: f64) -> f64 {
        let err = err.max(1e-10);
        let factor = SAFETY * err.powf(-self.alpha) * self.err_prev.powf(self.beta);
        self.err_prev = err.max(1e-4);
        h * factor.clamp(SHRINK_LIMIT, GROW_LIMIT)
    }

    /// Retry step after rejecting a step of size `h` with error norm `err > 1`.
    pub(crate) fn rejected(&self, h: f64, err: f64) -> f64 {
        h * (SAFETY * err.powf(-self.alpha)).max(SHRINK_LIMIT)
    }
}

/// Starting step (Hairer, Nørsett & Wanner I, §II.4): balances an explicit
/// Euler step against the change of `f`, for a method of order `order`.
/// Costs one call of `rhs` (counted in `stats`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn initial_step<const N: usize, S: OdeSystem<N>>(
    system: &S,
    t0: f64,
    x0: &SVector<f64, N>,
    f0: &SVector<f64, N>,
    order: u32,
    o: &Options,
    h_max: f64,
    stats: &mut Stats,
) -> f64 {
    let scaled_norm = |v: &SVector<f64, N>| {
        if N == 0 {
            return 0.0;
        }
        let mut sum = 0.0;
        for i in 0..N {
            sum += (v[i] / (o.atol_of(i) + o.rtol * x0[i].abs())).powi(2);
        }
        (sum / N as f64).sqrt()
    };
    let d0 = scaled_norm(x0);
    let d1 = scaled_norm(f0);
    let mut h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    h0 = h0.min(h_max);
    let x1 = x0 + f0 * h0;
    let f1 = system.rhs(t0 + h0, &x1);
    stats.rhs_calls += 1;
    let d2 = scaled_norm(&(f1 - f0)) / h0;
    if !d2.is_finite() {
        return h0.min(h_max);
    }
    let dmax = d1.max(d2);
    let h1 = if dmax <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / dmax).powf(1.0 / f64::from(order + 1))
    };
    (100.0 * h0).min(h1).min(h_max)
}
