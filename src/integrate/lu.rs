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
pub(crate) struct Lu<const N: usize> {
    lu: SMatrix<f64, N, N>,
    /// Row `i` of `P A` is row `perm[i]` of `A` (`i < n`).
    perm: [usize; N],
    /// Size of the factorized leading block.
    n: usize,
}

impl<const N: usize> Lu<N> {
    /// Factorizes `a`; `None` if a pivot is zero or not finite (singular or
    /// non-finite matrix).
    pub(crate) fn new(a: SMatrix<f64, N, N>) -> Option<Self> {
        Self::leading(a, N)
    }

    /// Factorizes the leading `n × n` block of `a` (`n ≤ N`; the rest of
    /// `a` is ignored); `None` if a pivot is zero or not finite.
    pub(crate) fn leading(mut a: SMatrix<f64, N, N>, n: usize) -> Option<Self> {
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
    pub(crate) fn solve(&self, b: &SVector<f64, N>) -> SVector<f64, N> {
        let mut y = [0.0; N];
        self.solve_leading(b.as_slice(), &mut y);
        SVector::from(y)
    }

    /// Solves the leading block's system: `y[..n]` from `b[..n]` (the rest
    /// of `y` is left as it is).
    pub(crate) fn solve_leading(&self, b: &[f64], y: &mut [f64; N]) {
        self.solve_block(b, y, self.n);
    }

    /// [`Lu::solve_leading`] with the block size `n` (equal to the
    /// factorized one) passed in, so that a caller with a constant size
    /// gets loops of constant length.
    #[inline(always)]
    pub(crate) fn solve_block(&self, b: &[f64], y: &mut [f64; N], n: usize) {
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

#[cfg(test)]
mod tests {
    use super::Lu;
    use nalgebra::{Matrix3, Vector3};

    #[test]
    fn solves_like_nalgebra_lu_with_pivoting() {
        // Zero leading entry forces a row swap.
        let a = Matrix3::new(0.0, 2.0, 1.0, 1.0, -1.0, 4.0, 3.0, 0.5, -2.0);
        let b = Vector3::new(1.0, -2.0, 0.25);
        let ours = Lu::new(a).expect("regular").solve(&b);
        let theirs = a.lu().solve(&b).expect("regular");
        assert!((ours - theirs).amax() < 1e-14);
        assert!((a * ours - b).amax() < 1e-14);
    }

    #[test]
    fn solves_an_eight_by_eight_system_like_nalgebra() {
        // The compliant planar peg's size; entries from a fixed sequence,
        // small diagonal so that rows are swapped.
        let a = nalgebra::SMatrix::<f64, 8, 8>::from_fn(|i, j| {
            let v = ((i * 7 + j * 3) % 11) as f64 - 5.0;
            if i == j {
                0.01 * v
            } else {
                v / (1.0 + (i + j) as f64)
            }
        });
        let b = nalgebra::SVector::<f64, 8>::from_fn(|i, _| (i as f64).sin());
        let ours = Lu::new(a).expect("regular").solve(&b);
        let theirs = a.lu().solve(&b).expect("regular");
        assert!(
            (ours - theirs).amax() < 1e-12 * theirs.amax(),
            "{ours} {theirs}"
        );
        assert!((a * ours - b).amax() < 1e-12);
    }

    #[test]
    fn a_leading_block_is_solved_alone() {
        // The leading 3 x 3 block of an 8 x 8 matrix, the rest garbage.
        let a = nalgebra::SMatrix::<f64, 8, 8>::from_fn(|i, j| {
            if i < 3 && j < 3 {
                [[0.0, 2.0, 1.0], [1.0, -1.0, 4.0], [3.0, 0.5, -2.0]][i][j]
            } else {
                f64::NAN
            }
        });
        let lu = Lu::leading(a, 3).expect("regular block");
        let mut b = [0.0; 8];
        b[..3].copy_from_slice(&[1.0, -2.0, 0.25]);
        let mut y = [7.0; 8];
        lu.solve_leading(&b, &mut y);
        let block = Matrix3::new(0.0, 2.0, 1.0, 1.0, -1.0, 4.0, 3.0, 0.5, -2.0);
        let x = Vector3::new(y[0], y[1], y[2]);
        assert!((block * x - Vector3::new(1.0, -2.0, 0.25)).amax() < 1e-14);
        assert_eq!(&y[3..], &[7.0; 5]);
    }

    #[test]
    fn reports_singular_and_non_finite_matrices() {
        let singular = Matrix3::new(1.0, 2.0, 3.0, 2.0, 4.0, 6.0, 0.0, 1.0, 1.0);
        assert!(Lu::new(singular).is_none());
        let mut nan = Matrix3::identity();
        nan[(1, 1)] = f64::NAN;
        assert!(Lu::new(nan).is_none());
    }
}
