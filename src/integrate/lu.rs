//! LU factorization with partial pivoting on fixed-size matrices, for the
//! iteration matrix `I/(hγ) − J` of the Rosenbrock stepper.
//!
//! nalgebra's `SMatrix::lu()` needs the bound
//! `Const<N>: DimMin<Const<N>, Output = Const<N>>`, which would then have to
//! appear on every function generic over the state dimension (the solver,
//! the CLI). This Doolittle elimination works for any `N`, allocates
//! nothing, and reports a zero or non-finite pivot instead of dividing by it.

use nalgebra::{SMatrix, SVector};

/// `P A = L U` packed in one matrix (unit `L` below the diagonal), of the
/// leading `n × n` block of an `N × N` matrix (`n = N` for the whole).
#[derive(Debug, Clone)]
pub struct Lu<const N: usize> {
    lu: SMatrix<f64, N, N>,
    /// Row `i` of `P A` is row `perm[i]` of `A` (`i < n`).
    perm: [usize; N],
    /// Size of the factorized leading block.
    n: usize,
}

impl<const N: usize> Lu<N> {
    /// Factorizes `a`; `None` if a pivot is zero or not finite (singular or
    /// non-finite matrix).
    pub fn new(a: SMatrix<f64, N, N>) -> Option<Self> {
        Self::leading(a, N)
    }

    /// Factorizes the leading `n × n` block of `a` (`n ≤ N`; the rest of
    /// `a` is ignored); `None` if a pivot is zero or not finite.
    pub fn leading(a: SMatrix<f64, N, N>, n: usize) -> Option<Self> {
        Self::leading_block(a, n)
    }

    /// [`Lu::leading`] inlined into its caller, so that a caller with a
    /// constant size gets loops of constant length.
    #[inline(always)]
    pub fn leading_block(mut a: SMatrix<f64, N, N>, n: usize) -> Option<Self> {
        let n = n.min(N);
        let mut perm = [0; N];
        for (i, p) in perm.iter_mut().enumerate() {
            *p = i;
        }
        for k in 0..n {
            let pivot_row = (k..n)
                .max_by(|&i, &j| a[(i, k)].abs().total_cmp(&a[(j, k)].abs()))
                .unwrap_or(k);
            let pivot = a[(pivot_row, k)];
            if pivot == 0.0 || !pivot.is_finite() {
                return None;
            }
            if pivot_row != k {
                for j in 0..n {
                    a.swap((k, j), (pivot_row, j));
                }
                perm.swap(k, pivot_row);
            }
            for i in k + 1..n {
                let l = a[(i, k)] / pivot;
                a[(i, k)] = l;
                for j in k + 1..n {
                    a[(i, j)] -= l * a[(k, j)];
                }
            }
        }
        Some(Lu { lu: a, perm, n })
    }

    /// Solves `A y = b`: `L z = P b` forward, then `U y = z` backward, both
    /// column by column (the packed factors are stored column-major, so
    /// each update reads one contiguous column).
    pub fn solve(&self, b: &SVector<f64, N>) -> SVector<f64, N> {
        let mut y = [0.0; N];
        self.solve_leading(b.as_slice(), &mut y);
        SVector::from(y)
    }

    /// Solves the leading block's system: `y[..n]` from `b[..n]` (the rest
    /// of `y` is left as it is).
    pub fn solve_leading(&self, b: &[f64], y: &mut [f64; N]) {
        self.solve_block(b, y, self.n);
    }

    /// [`Lu::solve_leading`] with the block size `n` (equal to the
    /// factorized one) passed in, so that a caller with a constant size
    /// gets loops of constant length.
    #[inline(always)]
    pub fn solve_block(&self, b: &[f64], y: &mut [f64; N], n: usize) {
        debug_assert_eq!(n, self.n);
        for (yi, &p) in y[..n].iter_mut().zip(&self.perm[..n]) {
            *yi = b[p];
        }
        let lu = self.lu.as_slice();
        for j in 0..n {
            let col = &lu[j * N..j * N + n];
            let yj = y[j];
            for (yi, &l) in y[j + 1..n].iter_mut().zip(&col[j + 1..]) {
                *yi -= l * yj;
            }
        }
        for j in (0..n).rev() {
            let col = &lu[j * N..j * N + n];
            let yj = y[j] / col[j];
            y[j] = yj;
            for (yi, &u) in y[..j].iter_mut().zip(&col[..j]) {
                *yi -= u * yj;
            }
        }
    }
}
