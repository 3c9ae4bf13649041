//! Stick or slip from rest.
//!
//! Every contact of the three-point peg slides unless q̇ = 0: each contact
//! Jacobian J_i has full column rank 2 for γ0 < γ < π/2
//! (`tests/rigid_peg/stick.rs`). So the peg sticks only when it is at rest.
//! At rest, a motion starts in some direction û of q̈; Coulomb friction at
//! each contact then opposes J_i û, which fixes the forward system. A start
//! along û is consistent iff the solved q̈ is a positive multiple of û and
//! every N_i ≥ 0. The search runs over the unit circle: [`SAMPLES`]
//! directions, then bisection on the sign changes of the cross product
//! û × q̈(û). No consistent direction: static friction holds, the peg
//! sticks.

use std::f64::consts::TAU;

use nalgebra::Vector2;

use crate::rigid_peg::RigidError;
use crate::rigid_peg::forward::{Accelerations, ForwardModel};

/// Number of sample directions on the circle.
pub const SAMPLES: usize = 720;

/// A consistent sliding start from rest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlidingStart {
    /// Unit direction û of q̈ (and of the ensuing q̇), (γ, ψ) components.
    pub direction: Vector2<f64>,
    /// q̈ = λ û, λ > 0 (1/s²).
    pub qdd: Vector2<f64>,
    /// Normal reactions `[N_K, N_B1, N_B2]` (N), all ≥ 0.
    pub normal: [f64; 3],
}

/// What a peg at rest does.
#[derive(Clone, Debug, PartialEq)]
pub enum RestOutcome {
    /// No sliding start is consistent: static friction holds.
    Sticks,
    /// It starts to slide; `starts[0]` has the largest acceleration |q̈|,
    /// further entries are other consistent starts (non-uniqueness).
    Slides {
        /// Consistent starts, largest |q̈| first.
        starts: Vec<SlidingStart>,
    },
    /// No three-point start is consistent, but a start with q̈ = λ û,
    /// λ > 0, exists that needs contact `contact` to pull: the peg does not
    /// stay on three points (it leaves the model). Static friction is not
    /// checked here: [`crate::rigid_peg::trajectory::simulate`] asks
    /// [`crate::rigid_peg::static_hold::hold_at_rest`] before reporting a
    /// lift-off.
    LeavesContact {
        /// The start with the largest |q̈| among these (`normal` has the
        /// negative entry).
        start: SlidingStart,
        /// Index of the most negative reaction (0 = K, 1 = B1, 2 = B2).
        contact: usize,
    },
}

fn direction(theta: f64) -> Vector2<f64> {
    Vector2::new(theta.cos(), theta.sin())
}

/// û × q̈(û) / |q̈| (sine of the angle from û to q̈), or `None` where the
/// system is singular.
fn cross(model: &ForwardModel, q: Vector2<f64>, theta: f64) -> Option<(f64, Accelerations)> {
    let u = direction(theta);
    let a = model.evaluate_start(q, u).ok()?;
    let n = a.qdd.norm();
    if !n.is_finite() || n == 0.0 {
        return None;
    }
    Some(((u[0] * a.qdd[1] - u[1] * a.qdd[0]) / n, a))
}

/// Decides stick or slip for the peg at rest at `q = (γ, ψ)`.
///
/// # Errors
/// [`RigidError::NotThreePoint`] outside γ0 < γ < π/2.
pub fn start_from_rest(model: &ForwardModel, q: Vector2<f64>) -> Result<RestOutcome, RigidError> {
    crate::rigid_peg::kinematics::Geometry::try_new(&model.params, q[0])?;
    let thetas: Vec<f64> = (0..SAMPLES)
        .map(|k| TAU * k as f64 / SAMPLES as f64)
        .collect();
    let values: Vec<Option<f64>> = thetas
        .iter()
        .map(|&th| cross(model, q, th).map(|c| c.0))
        .collect();
    let mut starts: Vec<SlidingStart> = Vec::new();
    let mut pulling: Vec<SlidingStart> = Vec::new();
    for k in 0..SAMPLES {
        let (Some(c0), Some(c1)) = (values[k], values[(k + 1) % SAMPLES]) else {
            continue;
        };
        let (mut a, mut b) = (thetas[k], thetas[k] + TAU / SAMPLES as f64);
        let root = if c0 == 0.0 {
            a
        } else if c0.signum() == c1.signum() || c1 == 0.0 {
            continue;
        } else {
            let ca = c0;
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                match cross(model, q, m) {
                    Some((cm, _)) if cm.signum() == ca.signum() => a = m,
                    Some(_) => b = m,
                    None => break,
                }
            }
            0.5 * (a + b)
        };
        let Some((_, acc)) = cross(model, q, root) else {
            continue;
        };
        let u = direction(root);
        let lambda = u.dot(&acc.qdd);
        let scale = model.params.mass * model.params.gravity;
        let start = SlidingStart {
            direction: u,
            qdd: acc.qdd,
            normal: acc.normal,
        };
        if lambda > 0.0 && acc.normal.iter().all(|&n| n >= -1e-9 * scale) {
            starts.push(start);
        } else if lambda > 0.0 {
            pulling.push(start);
        }
    }
    if starts.is_empty() {
        pulling.sort_by(|x, y| y.qdd.norm().total_cmp(&x.qdd.norm()));
        return Ok(match pulling.first() {
            None => RestOutcome::Sticks,
            Some(s) => {
                let contact = (0..3)
                    .min_by(|&i, &j| s.normal[i].total_cmp(&s.normal[j]))
                    .unwrap_or(0);
                RestOutcome::LeavesContact { start: *s, contact }
            }
        });
    }
    starts.sort_by(|x, y| y.qdd.norm().total_cmp(&x.qdd.norm()));
    Ok(RestOutcome::Slides { starts })
}
