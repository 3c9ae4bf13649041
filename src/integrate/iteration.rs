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
pub(crate) enum IterationLu<'j, const N: usize> {
    /// `cI − J` factorized whole.
    Dense(Lu<N>),
    /// The reduced `n × n` system of a second-order Jacobian.
    SecondOrder(Reduced<'j, N>),
    /// The velocity block of a state with a kinematic split.
    Kinematic(Kinematic<'j, N>),
}

/// The reduced system `(cI − B − A/c) u_v = r_v + A r_q / c`.
#[derive(Debug, Clone)]
pub(crate) struct Reduced<'j, const N: usize> {
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
    pub(crate) fn new(
        jac: &'j SMatrix<f64, N, N>,
        c: f64,
        split: Option<KinematicSplit>,
    ) -> Option<Self> {
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
    pub(crate) fn solve(&self, r: &SVector<f64, N>) -> SVector<f64, N> {
        match self {
            IterationLu::Dense(lu) => lu.solve(r),
            IterationLu::SecondOrder(reduced) => reduced.solve(r),
            IterationLu::Kinematic(k) => k.solve(r),
        }
    }

    /// `true` when the reduced system is used.
    #[cfg(test)]
    fn is_reduced(&self) -> bool {
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
fn second_order_split<const N: usize>(jac: &SMatrix<f64, N, N>) -> Option<usize> {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A second-order Jacobian with 3 positions and 2 integrals, entries
    /// from a fixed sequence.
    fn planar_peg_like() -> SMatrix<f64, 8, 8> {
        SMatrix::<f64, 8, 8>::from_fn(|i, j| match (i, j) {
            (0..3, _) => f64::from(u8::from(j == i + 3)),
            (_, 6..) => 0.0,
            _ => (((i * 7 + j * 3) % 11) as f64 - 5.0) * 10f64.powi((i + j) as i32 % 5 - 1),
        })
    }

    #[test]
    fn the_second_order_form_is_recognized_exactly() {
        let j = planar_peg_like();
        assert_eq!(second_order_split(&j), Some(3));
        // a pendulum: x' = v, v' = -sin x
        let p = nalgebra::Matrix2::new(0.0, 1.0, -0.5, -0.1);
        assert_eq!(second_order_split(&p), Some(1));
        // not exact unit rows (a finite-difference Jacobian), feedback from
        // an integral, a general matrix: the full factorization
        let mut fd = j;
        fd[(1, 4)] = 1.0 + 1e-9;
        assert_eq!(second_order_split(&fd), None);
        let mut feedback = j;
        feedback[(4, 7)] = 1e-12;
        assert_eq!(second_order_split(&feedback), None);
        let mut general = j;
        general[(2, 0)] = 0.5;
        assert_eq!(second_order_split(&general), None);
        assert_eq!(second_order_split(&SMatrix::<f64, 4, 4>::identity()), None);
    }

    #[test]
    fn the_reduced_solve_agrees_with_the_full_factorization() {
        let j = planar_peg_like();
        let r =
            SVector::<f64, 8>::from_fn(|i, _| (1.0 + i as f64).sin() * 10f64.powi(i as i32 - 4));
        // c = 1/(hγ) from huge steps to tiny ones
        for c in [1e-3, 1.0, 4e2, 1e5, 1e9] {
            let reduced = IterationLu::new(&j, c, None).expect("regular");
            assert!(reduced.is_reduced());
            let full = Lu::new(SMatrix::<f64, 8, 8>::identity() * c - j).expect("regular");
            let (u, v) = (reduced.solve(&r), full.solve(&r));
            let scale = v.amax();
            assert!((u - v).amax() <= 1e-12 * scale, "c = {c}: {u} vs {v}");
            // and it solves the system
            let w = SMatrix::<f64, 8, 8>::identity() * c - j;
            let residual = (w * u - r).amax();
            assert!(
                residual <= 1e-12 * (w.amax() * u.amax()).max(r.amax()),
                "c = {c}: {residual}"
            );
        }
    }

    #[test]
    fn the_generated_planar_peg_jacobian_takes_the_reduced_solve() {
        use crate::system::OdeSystem;
        let setup = crate::jamming::dynamic::SweepSetup::new(
            crate::jamming::dynamic::SweepSpec::reference(),
        )
        .expect("the reference sweep is valid");
        let load = crate::compliant_peg::Load {
            axial: 20.0,
            radial: 5.0,
            torque: 0.1,
        };
        let sys = crate::compliant_peg::CompliantSystem::new(&setup.params, &load);
        let j = sys.jacobian(0.0, &setup.start.to_vector());
        assert_eq!(second_order_split(&j), Some(3));
        assert!(
            IterationLu::new(&j, 1e3, None)
                .expect("regular")
                .is_reduced()
        );
    }

    #[test]
    fn a_singular_reduced_matrix_is_reported() {
        // v' = q + v at c = ... : cI - B - A/c = c - 1 - 1/c = 0 at c = golden ratio
        let j = nalgebra::Matrix2::new(0.0, 1.0, 1.0, 1.0);
        let golden = 0.5 * (1.0 + 5f64.sqrt());
        let w = IterationLu::new(&j, golden, None);
        // the pivot is a rounding residue or exactly zero: either refused
        // or tiny enough to be; the full matrix is singular there too
        if let Some(w) = w {
            let u = w.solve(&nalgebra::Vector2::new(1.0, 0.0));
            assert!(u.amax() > 1e12, "{u}");
        }
        let mut nan = j;
        nan[(1, 1)] = f64::NAN;
        assert!(IterationLu::new(&nan, 1.0, None).is_none());
    }
}
