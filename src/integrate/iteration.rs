//! The linear systems of a Rosenbrock step, `(cI − J) u = r` with
//! `c = 1/(hγ)`: one factorization per step, one solve per stage.
//!
//! A mechanical system written in first-order form has a Jacobian of block
//! form
//!
//! ```text
//!       q  v  w
//! J = [ 0  I  0 ]   q' = v            (n positions)
//!     [ A  B  0 ]   v' = a(q, v)      (n velocities)
//!     [ C  D  0 ]   w' = g(q, v)      (m = N − 2n integrals: work,
//!                                      dissipation; nothing reads them)
//! ```
//!
//! and `(cI − J) u = r` reduces to `n` unknowns (the structure option
//! `M1`/`M2` of Hairer & Wanner's RADAU5 code, here with the trailing
//! integrals added):
//!
//! ```text
//! (cI − B − A/c) u_v = r_v + A r_q / c
//! u_q = (r_q + u_v) / c
//! u_w = (r_w + C u_q + D u_v) / c
//! ```
//!
//! The reduced matrix is factorized with partial pivoting like the full
//! one. The block form is read off the Jacobian itself (exact zeros and
//! ones in the position rows, zero columns for the integrals), so a
//! generated Jacobian gets the reduction and a finite-difference one, whose
//! position rows are not exact, the full factorization.
//!
//! A system whose positions have a kinematic map `ẋ = K(x) u` (a rigid
//! body's quaternion) declares its [`KinematicSplit`]; its iteration
//! matrix is reduced to the velocities by `super::kinematic`.
//!
//! A state with its forward sensitivities declares its blocks
//! ([`crate::system::OdeSystem::variational_blocks`]): `J` is block
//! lower-triangular with equal diagonal blocks `J₀` and off-diagonal blocks
//! `Bₖ` in the first block column only, so `cI − J₀` is factorized at the
//! block's size and the blocks are solved in turn (block forward
//! substitution):
//!
//! ```text
//! (cI − J₀) u₀ = r₀,    (cI − J₀) uₖ = rₖ + Bₖ u₀
//! ```

use nalgebra::{SMatrix, SVector};

use super::kinematic::{Kinematic, Refused};
use super::lu::Lu;
use crate::system::KinematicSplit;

/// The factorized iteration matrix `cI − J` of one step (borrowing `J`).
#[derive(Debug, Clone)]
pub enum IterationLu<'j, const N: usize> {
    /// `cI − J` factorized whole.
    Dense(Lu<N>),
    /// The reduced `n × n` system of a second-order Jacobian.
    SecondOrder(Reduced<'j, N>),
    /// The velocity block of a state with a kinematic split.
    Kinematic(Kinematic<'j, N>),
    /// The diagonal block of a state with its sensitivities.
    Blocks(Blocks<'j, N>),
}

/// `cI − J₀` factorized at the block size `n`, `J`'s first block column
/// kept for the solves.
#[derive(Debug, Clone)]
pub struct Blocks<'j, const N: usize> {
    /// The block size.
    n: usize,
    /// The Jacobian: its first block column `(J₀, B₁, …)` is read by the
    /// solves.
    jac: &'j SMatrix<f64, N, N>,
    /// Factors of `cI − J₀` (`n × n`, allocated once per step: the
    /// block's size is not a constant of the stepper).
    lu: nalgebra::linalg::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

/// The reduced system `(cI − B − A/c) u_v = r_v + A r_q / c`.
#[derive(Debug, Clone)]
pub struct Reduced<'j, const N: usize> {
    /// Number of positions (and of velocities).
    n: usize,
    /// `1/c = hγ`.
    inv_c: f64,
    /// The Jacobian: its `A`, `C` and `D` blocks are read by the solves.
    jac: &'j SMatrix<f64, N, N>,
    /// Factors of `cI − B − A/c` (leading `n × n` block).
    lu: Lu<N>,
}

impl<'j, const N: usize> IterationLu<'j, N> {
    /// Factorizes `cI − jac`, reduced when `jac` has the second-order
    /// block form or fits the system's kinematic `split`; `None` if a
    /// pivot is zero or not finite.
    ///
    /// With `blocks = Some(n)` ([`crate::system::OdeSystem::variational_blocks`])
    /// and `jac` of that block form (checked), the block `cI − J₀` alone is
    /// factorized.
    pub fn new(
        jac: &'j SMatrix<f64, N, N>,
        c: f64,
        split: Option<KinematicSplit>,
        blocks: Option<usize>,
    ) -> Option<Self> {
        if let Some(n) = blocks.filter(|&n| has_variational_blocks(jac, n)) {
            return Blocks::new(jac, c, n).map(IterationLu::Blocks);
        }
        let second_order = second_order_split(jac);
        if let (None, Some(split)) = (second_order, split) {
            match Kinematic::new(jac, c, split) {
                Ok(k) => return Some(IterationLu::Kinematic(k)),
                Err(Refused::Singular) => return None,
                Err(Refused::NotThisForm | Refused::PositionsSingular) => {}
            }
        }
        match second_order {
            Some(n) => {
                let mut s = SMatrix::<f64, N, N>::zeros();
                for i in 0..n {
                    for j in 0..n {
                        s[(i, j)] = -jac[(n + i, n + j)] - jac[(n + i, j)] / c;
                    }
                    s[(i, i)] += c;
                }
                let lu = Lu::leading(s, n)?;
                Some(IterationLu::SecondOrder(Reduced {
                    n,
                    inv_c: 1.0 / c,
                    jac,
                    lu,
                }))
            }
            None => Lu::new(SMatrix::<f64, N, N>::identity() * c - jac).map(IterationLu::Dense),
        }
    }

    /// Solves `(cI − J) u = r`.
    pub fn solve(&self, r: &SVector<f64, N>) -> SVector<f64, N> {
        match self {
            IterationLu::Dense(lu) => lu.solve(r),
            IterationLu::SecondOrder(reduced) => reduced.solve(r),
            IterationLu::Kinematic(k) => k.solve(r),
            IterationLu::Blocks(b) => b.solve(r),
        }
    }

    /// `true` when the reduced system is used.
    pub fn is_reduced(&self) -> bool {
        !matches!(self, IterationLu::Dense(_))
    }
}

impl<const N: usize> Reduced<'_, N> {
    /// The solve at the sizes of the usual mechanical systems with loop
    /// bounds known to the compiler (unrolled), others at run-time size.
    fn solve(&self, r: &SVector<f64, N>) -> SVector<f64, N> {
        match self.n {
            1 => self.solve_any(r, 1),
            2 => self.solve_any(r, 2),
            3 => self.solve_any(r, 3),
            4 => self.solve_any(r, 4),
            6 => self.solve_any(r, 6),
            n => self.solve_any(r, n),
        }
    }

    #[inline(always)]
    fn solve_any(&self, r: &SVector<f64, N>, n: usize) -> SVector<f64, N> {
        let (jac, inv_c) = (self.jac, self.inv_c);
        // r_v + A r_q / c
        let mut rhs = [0.0; N];
        for i in 0..n {
            let mut a_rq = 0.0;
            for k in 0..n {
                a_rq += jac[(n + i, k)] * r[k];
            }
            rhs[i] = r[n + i] + a_rq * inv_c;
        }
        let mut u_v = [0.0; N];
        self.lu.solve_block(&rhs, &mut u_v, n);
        let mut u = SVector::<f64, N>::zeros();
        for i in 0..n {
            u[n + i] = u_v[i];
            u[i] = (r[i] + u_v[i]) * inv_c;
        }
        for i in 2 * n..N {
            let mut s = r[i];
            for k in 0..2 * n {
                s += jac[(i, k)] * u[k];
            }
            u[i] = s * inv_c;
        }
        u
    }
}

impl<'j, const N: usize> Blocks<'j, N> {
    /// Factorizes `cI − J₀`, `J₀` the leading `n × n` block of `jac`;
    /// `None` if it is singular or not finite.
    fn new(jac: &'j SMatrix<f64, N, N>, c: f64, n: usize) -> Option<Self> {
        let block = nalgebra::DMatrix::from_fn(n, n, |i, j| {
            if i == j {
                c - jac[(i, j)]
            } else {
                -jac[(i, j)]
            }
        });
        if !block.iter().all(|v| v.is_finite()) {
            return None;
        }
        let lu = block.lu();
        let u = lu.u();
        if (0..n).any(|i| u[(i, i)] == 0.0 || !u[(i, i)].is_finite()) {
            return None;
        }
        Some(Blocks { n, jac, lu })
    }

    /// Solves `(cI − J) u = r` block by block, in place in `u` (no
    /// allocation).
    fn solve(&self, r: &SVector<f64, N>) -> SVector<f64, N> {
        let n = self.n;
        let mut u = *r;
        self.lu.solve_mut(&mut u.rows_mut(0, n));
        for k in 1..N / n {
            for i in 0..n {
                let row = k * n + i;
                for j in 0..n {
                    u[row] += self.jac[(row, j)] * u[j];
                }
            }
            self.lu.solve_mut(&mut u.rows_mut(k * n, n));
        }
        u
    }
}

/// Whether `jac` has the block form of a state with its sensitivities in
/// blocks of `n` ([`crate::system::OdeSystem::variational_blocks`]): every
/// diagonal block equal to the first, zero blocks off the diagonal but in
/// the first block column.
fn has_variational_blocks<const N: usize>(jac: &SMatrix<f64, N, N>, n: usize) -> bool {
    if n == 0 || N % n != 0 || N / n < 2 {
        return false;
    }
    for row in n..N {
        let diagonal = row / n * n;
        for col in n..N {
            let expected = if (diagonal..diagonal + n).contains(&col) {
                jac[(row % n, col - diagonal)]
            } else {
                0.0
            };
            if jac[(row, col)] != expected {
                return false;
            }
        }
    }
    (0..n).all(|row| (n..N).all(|col| jac[(row, col)] == 0.0))
}

/// `Some(n)` when `jac` has the block form of the module docs: rows
/// `0..n` are the unit rows `e_{n+i}` exactly and columns `2n..N` are zero.
pub fn second_order_split<const N: usize>(jac: &SMatrix<f64, N, N>) -> Option<usize> {
    if N < 2 {
        return None;
    }
    let n = (0..N).find(|&j| jac[(0, j)] != 0.0)?;
    if n == 0 || 2 * n > N {
        return None;
    }
    for i in 0..n {
        for j in 0..N {
            let unit = if j == n + i { 1.0 } else { 0.0 };
            if jac[(i, j)] != unit {
                return None;
            }
        }
    }
    for i in n..N {
        for j in 2 * n..N {
            if jac[(i, j)] != 0.0 {
                return None;
            }
        }
    }
    Some(n)
}
