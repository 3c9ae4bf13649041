//! Static friction at rest on three points: can K, B1 and B2 hold the peg
//! at rest under its loads?
//!
//! At rest (q̇ = 0, q̈ = 0) the forward system of
//! [`forward_system`] (two Lagrange rows, three centre-of-mass rows) reads
//! Σᵢ Nᵢ aᵢ(tᵢ) = b, where the column aᵢ(tᵢ) of contact i is affine in its
//! friction direction tᵢ (the friction force is f Nᵢ tᵢ) and b holds
//! gravity and the applied loads. Static friction may point anywhere in the
//! contact's tangent plane (the column space of its Jacobian Jᵢ) with
//! |tᵢ| ≤ 1. The peg can stay at rest iff b is a non-negative combination
//! of the columns aᵢ(t) over the unit tangent circle of each contact.
//!
//! The circle is replaced by the inscribed regular polygon of [`POLYGON`]
//! vertices, and non-negative least squares (Lawson–Hanson) finds the
//! combination. The polygon lies inside the cone, so a combination found is
//! a certificate: the peg *can* be held (Nᵢ = Σₖ λᵢₖ ≥ 0 and the friction
//! force inside f Nᵢ times the polygon). It may miss an equilibrium that
//! needs friction within 1 − cos(π/[`POLYGON`]) ≈ 0.5 % of the cone's
//! edge; the answer is then "not held", the conservative side for a stick
//! decision (the caller keeps its previous verdict).

use std::f64::consts::TAU;

use nalgebra::{DMatrix, DVector, Vector2, Vector3, Vector5};

use crate::rigid_peg::RigidError;
use crate::rigid_peg::dynamics::forward_system;
use crate::rigid_peg::forward::ForwardModel;
use crate::rigid_peg::kinematics::Pose;

/// Vertices of the polygon inscribed in each contact's friction circle.
pub const POLYGON: usize = 32;

/// Relative residual (of the rows scaled to newtons, against m g + |b|)
/// below which the combination is taken to balance the loads.
pub const RESIDUAL_TOL: f64 = 1e-9;

/// A static equilibrium on three points found by [`hold_at_rest`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hold {
    /// Normal reactions `[N_K, N_B1, N_B2]` (N), all ≥ 0.
    pub normal: [f64; 3],
    /// Friction forces in frame components (η, n, z) (N), each in the
    /// tangent plane of its contact with |Fᵢ| ≤ f Nᵢ.
    pub friction: [Vector3<f64>; 3],
}

/// Orthonormal basis of the column space of a contact Jacobian (its
/// tangent plane), or `None` if it is rank-deficient.
fn tangent_basis(j: &nalgebra::Matrix3x2<f64>) -> Option<(Vector3<f64>, Vector3<f64>)> {
    let e1 = j.column(0).try_normalize(0.0)?;
    let c2 = j.column(1) - e1 * e1.dot(&j.column(1));
    let e2 = c2.try_normalize(1e-12 * j.column(1).norm())?;
    Some((e1, e2))
}

/// Whether static friction holds the peg at rest at `q = (γ, ψ)` on all
/// three contacts under the model's loads; the equilibrium found, if any.
///
/// # Errors
/// [`RigidError::NotThreePoint`] outside γ0 < γ < π/2.
pub fn hold_at_rest(model: &ForwardModel, q: Vector2<f64>) -> Result<Option<Hold>, RigidError> {
    let p = &model.params;
    let pose = Pose::try_new(p, q[0], q[1])?;
    let jac = pose.jacobians_local();
    let zero = Vector2::zeros();
    let mut t = [Vector3::zeros(); 3];
    let (_, b) = forward_system(p, &model.loads, &pose, zero, &t);
    // Lagrange rows (N·m) in newtons: divide by the peg height.
    let scale = Vector5::new(1.0 / p.height, 1.0 / p.height, 1.0, 1.0, 1.0);
    let mut g = DMatrix::zeros(5, 3 * POLYGON);
    let mut dirs = Vec::with_capacity(3 * POLYGON);
    for i in 0..3 {
        let Some((e1, e2)) = tangent_basis(&jac.contacts[i]) else {
            return Ok(None);
        };
        for k in 0..POLYGON {
            let (s, c) = (TAU * k as f64 / POLYGON as f64).sin_cos();
            t[i] = e1 * c + e2 * s;
            let (a, _) = forward_system(p, &model.loads, &pose, zero, &t);
            let col = a.column(2 + i).component_mul(&scale);
            g.set_column(i * POLYGON + k, &col);
            dirs.push(t[i]);
        }
        t[i] = Vector3::zeros();
    }
    let b = DVector::from_column_slice(b.component_mul(&scale).as_slice());
    if wedges(&g) {
        return Ok(None);
    }
    let Some(lambda) = nnls(&g, &b) else {
        return Ok(None);
    };
    let residual = (&g * &lambda - &b).norm();
    let tol = RESIDUAL_TOL * (p.mass * p.gravity + b.norm());
    if residual.is_nan() || residual > tol {
        return Ok(None);
    }
    let mut hold = Hold {
        normal: [0.0; 3],
        friction: [Vector3::zeros(); 3],
    };
    for (col, (&l, d)) in lambda.iter().zip(&dirs).enumerate() {
        let i = col / POLYGON;
        hold.normal[i] += l;
        hold.friction[i] += d * (p.friction * l);
    }
    Ok(Some(hold))
}

/// Whether a self-equilibrated contact force system exists inside the
/// (polygonal) cones: G λ = 0 with λ ≥ 0, Σ λ = 1. Then the static problem
/// is wedged: any load is held by a large enough internal pre-stress, which
/// a peg arriving at rest need not have, so a combination balancing the
/// loads proves nothing.
fn wedges(g: &DMatrix<f64>) -> bool {
    let n = g.ncols();
    let w = g.amax().max(f64::MIN_POSITIVE);
    let mut a = DMatrix::zeros(6, n);
    a.view_mut((0, 0), (5, n)).copy_from(g);
    a.row_mut(5).fill(w);
    let mut b = DVector::zeros(6);
    b[5] = w;
    nnls(&a, &b).is_some_and(|x| (&a * &x - &b).norm() <= 1e-9 * w)
}

/// Non-negative least squares min |G x − b|, x ≥ 0 (Lawson–Hanson active
/// set); `None` if it does not converge in 3·columns iterations.
fn nnls(g: &DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    let n = g.ncols();
    let mut x = DVector::zeros(n);
    let mut passive = vec![false; n];
    let tol = 1e-12 * g.amax().max(f64::MIN_POSITIVE) * b.amax().max(f64::MIN_POSITIVE);
    for _ in 0..3 * n {
        let w = g.transpose() * (b - g * &x);
        let Some(j) = (0..n)
            .filter(|&j| !passive[j] && w[j] > tol)
            .max_by(|&a, &c| w[a].total_cmp(&w[c]))
        else {
            return Some(x);
        };
        passive[j] = true;
        for _ in 0..=n {
            let idx: Vec<usize> = (0..n).filter(|&j| passive[j]).collect();
            let gp = g.select_columns(&idx);
            let zp = gp.svd(true, true).solve(b, 1e-14).ok()?;
            if zp.iter().all(|&v| v > 0.0) {
                x.fill(0.0);
                for (k, &j) in idx.iter().enumerate() {
                    x[j] = zp[k];
                }
                break;
            }
            // Step towards z until the first passive x_j reaches 0; that
            // one (and any other at 0) leaves the passive set.
            let (mut alpha, mut first) = (f64::INFINITY, idx[0]);
            for (k, &j) in idx.iter().enumerate() {
                if zp[k] <= 0.0 {
                    let a = x[j] / (x[j] - zp[k]);
                    if a < alpha {
                        (alpha, first) = (a, j);
                    }
                }
            }
            for (k, &j) in idx.iter().enumerate() {
                x[j] += alpha * (zp[k] - x[j]);
                if j == first || x[j] <= 0.0 {
                    x[j] = 0.0;
                    passive[j] = false;
                }
            }
        }
    }
    None
}
