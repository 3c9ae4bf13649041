//! The linear systems `(cI − J) u = r` of a Rosenbrock step for a state
//! of positions with a kinematic map: `n_x` positions `x` whose rates are
//! `ẋ = K(x) u`, `n_u` velocities `u` with `u̇ = a(x, u)`, and `m` trailing
//! integrals `w` (work, dissipation) that no rate reads:
//!
//! ```text
//!       x    u    w
//! J = [ P    K    0 ]   ẋ = K(x) u,    P = ∂(K(x) u)/∂x
//!     [ A    B    0 ]   u̇ = a(x, u)
//!     [ C    D    0 ]   ẇ = g(x, u)
//! ```
//!
//! Eliminating the positions (block Gaussian elimination, the Schur
//! complement of `E = cI − P`) leaves `n_u` unknowns:
//!
//! ```text
//! E = cI − P,   M = E⁻¹ K,   S = cI − B − A M
//! S u_u = r_u + A E⁻¹ r_x
//! u_x = E⁻¹ r_x + M u_u
//! u_w = (r_w + C u_x + D u_u) / c
//! ```
//!
//! (`det(cI − J) = det E · det S · cᵐ`, so `S` is regular wherever the whole
//! matrix and `E` are). A second-order system (`ẋ = u`: `P = 0`, `K = I`)
//! is the special case `E = cI`, `M = I/c`, `S = cI − B − A/c` of
//! `super::iteration`. For a rigid body with a unit quaternion, `x = (p, q)`
//! and `u = (v, ω)` (`ω` in body axes), `ṗ = v` and `q̇ = ½ q ⊗ (0, ω) =
//! ½ Ξ(q) ω`,
//!
//! ```text
//!        ⎡ −q₁ −q₂ −q₃ ⎤                  ⎡ 0  −ω₁ −ω₂ −ω₃ ⎤
//! Ξ(q) = ⎢  q₀ −q₃  q₂ ⎥,   ∂q̇/∂q = ½ Ω,  Ω = ⎢ ω₁  0   ω₃ −ω₂ ⎥
//!        ⎢  q₃  q₀ −q₁ ⎥                  ⎢ ω₂ −ω₃  0   ω₁ ⎥
//!        ⎣ −q₂  q₁  q₀ ⎦                  ⎣ ω₃  ω₂ −ω₁  0  ⎦
//! ```
//!
//! so `P = diag(0, ½ Ω)`, `K = diag(I, ½ Ξ(q))` and, `Ω` being
//! skew-symmetric with `Ω² = −|ω|² I`,
//!
//! ```text
//! E⁻¹ = diag(I/c, (cI + ½ Ω) / (c² + |ω|²/4)),
//! M   = diag(I/c, (cI + ½ Ω) Ξ(q) / (2 (c² + |ω|²/4)))
//! S   = cI − B − A M      (6 × 6: the velocity block)
//! ```
//!
//! `E` is factorized like any small matrix (partial pivoting), so the
//! solve holds for every kinematic map; the closed forms above are what it
//! computes for the rigid body (`E` is never singular there: its
//! eigenvalues are `c` and `c ± i|ω|/2`).

use nalgebra::{SMatrix, SVector};

use super::lu::Lu;
use crate::system::KinematicSplit;

/// The factorized iteration matrix of a state with a kinematic split
/// (borrowing `J`).
#[derive(Debug, Clone)]
pub struct Kinematic<'j, const N: usize> {
    /// Number of positions `n_x`.
    nx: usize,
    /// Number of velocities `n_u`.
    nu: usize,
    /// `1/c = hγ`.
    inv_c: f64,
    /// The Jacobian: `A`, `C` and `D` are read by the solves.
    jac: &'j SMatrix<f64, N, N>,
    /// Factors of `E = cI − P` (leading `n_x × n_x` block).
    e: Lu<N>,
    /// `M = E⁻¹ K` (leading `n_x × n_u` block).
    pub m: SMatrix<f64, N, N>,
    /// Factors of `S = cI − B − A M` (leading `n_u × n_u` block).
    s: Lu<N>,
}

/// Why [`Kinematic::new`] gave no factorization.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refused {
    /// The split does not fit `J`: sizes beyond `N`, or a non-zero entry in
    /// a column of the integrals. Use the full factorization.
    NotThisForm,
    /// `E` has a zero pivot: use the full factorization.
    PositionsSingular,
    /// `S` has a zero or non-finite pivot: `cI − J` is singular.
    Singular,
}

impl<'j, const N: usize> Kinematic<'j, N> {
    /// Factorizes `cI − jac` by the elimination of the module
    /// documentation.
    pub fn new(
        jac: &'j SMatrix<f64, N, N>,
        c: f64,
        split: KinematicSplit,
    ) -> Result<Self, Refused> {
        match (split.positions, split.velocities) {
            // A rigid body with a unit quaternion: loops of constant length.
            (7, 6) => Self::new_sized(jac, c, 7, 6),
            (nx, nu) => Self::new_sized(jac, c, nx, nu),
        }
    }

    #[inline(always)]
    fn new_sized(
        jac: &'j SMatrix<f64, N, N>,
        c: f64,
        nx: usize,
        nu: usize,
    ) -> Result<Self, Refused> {
        let n = nx + nu;
        if nx == 0 || nu == 0 || n > N {
            return Err(Refused::NotThisForm);
        }
        if (0..N).any(|i| (n..N).any(|j| jac[(i, j)] != 0.0)) {
            return Err(Refused::NotThisForm);
        }
        let mut e = SMatrix::<f64, N, N>::zeros();
        for i in 0..nx {
            for j in 0..nx {
                e[(i, j)] = -jac[(i, j)];
            }
            e[(i, i)] += c;
        }
        let e = Lu::leading_block(e, nx).ok_or(Refused::PositionsSingular)?;
        // M = E⁻¹ K, column by column.
        let mut m = SMatrix::<f64, N, N>::zeros();
        let mut col = [0.0; N];
        let mut y = [0.0; N];
        for j in 0..nu {
            for i in 0..nx {
                col[i] = jac[(i, nx + j)];
            }
            e.solve_block(&col, &mut y, nx);
            for i in 0..nx {
                m[(i, j)] = y[i];
            }
        }
        let mut s = SMatrix::<f64, N, N>::zeros();
        for i in 0..nu {
            for j in 0..nu {
                let mut am = 0.0;
                for k in 0..nx {
                    am += jac[(nx + i, k)] * m[(k, j)];
                }
                s[(i, j)] = -jac[(nx + i, nx + j)] - am;
            }
            s[(i, i)] += c;
        }
        let s = Lu::leading_block(s, nu).ok_or(Refused::Singular)?;
        Ok(Kinematic {
            nx,
            nu,
            inv_c: 1.0 / c,
            jac,
            e,
            m,
            s,
        })
    }

    /// Solves `(cI − J) u = r`.
    pub fn solve(&self, r: &SVector<f64, N>) -> SVector<f64, N> {
        match (self.nx, self.nu) {
            (7, 6) => self.solve_sized(r, 7, 6),
            (nx, nu) => self.solve_sized(r, nx, nu),
        }
    }

    #[inline(always)]
    fn solve_sized(&self, r: &SVector<f64, N>, nx: usize, nu: usize) -> SVector<f64, N> {
        let jac = self.jac;
        // t = E⁻¹ r_x
        let mut t = [0.0; N];
        self.e.solve_block(r.as_slice(), &mut t, nx);
        // S u_u = r_u + A t
        let mut rhs = [0.0; N];
        for i in 0..nu {
            let mut at = 0.0;
            for k in 0..nx {
                at += jac[(nx + i, k)] * t[k];
            }
            rhs[i] = r[nx + i] + at;
        }
        let mut u_u = [0.0; N];
        self.s.solve_block(&rhs, &mut u_u, nu);
        let mut u = SVector::<f64, N>::zeros();
        for i in 0..nx {
            let mut mu = 0.0;
            for (k, uk) in u_u[..nu].iter().enumerate() {
                mu += self.m[(i, k)] * uk;
            }
            u[i] = t[i] + mu;
        }
        for i in 0..nu {
            u[nx + i] = u_u[i];
        }
        let n = nx + nu;
        for i in n..N {
            let mut s = r[i];
            for k in 0..n {
                s += jac[(i, k)] * u[k];
            }
            u[i] = s * self.inv_c;
        }
        u
    }
}
