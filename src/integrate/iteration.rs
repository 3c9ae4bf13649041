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
    pub fn new(jac: &'j SMatrix<f64, N, N>, c: f64, split: Option<KinematicSplit>) -> Option<Self> {
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
