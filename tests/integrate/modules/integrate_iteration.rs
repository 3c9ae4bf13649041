//! The items of `src/integrate/iteration.rs`.

use nalgebra::{SMatrix, SVector};
use pegdyn::internals::integrate::*;

use pegdyn::internals::integrate::Lu;

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
    let r = SVector::<f64, 8>::from_fn(|i, _| (1.0 + i as f64).sin() * 10f64.powi(i as i32 - 4));
    // c = 1/(hγ) from huge steps to tiny ones
    for c in [1e-3, 1.0, 4e2, 1e5, 1e9] {
        let reduced = IterationLu::new(&j, c, None, None).expect("regular");
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
    use pegdyn::system::OdeSystem;
    let setup =
        pegdyn::jamming::dynamic::SweepSetup::new(pegdyn::jamming::dynamic::SweepSpec::reference())
            .expect("the reference sweep is valid");
    let load = pegdyn::compliant_peg::Load {
        axial: 20.0,
        radial: 5.0,
        torque: 0.1,
    };
    let sys = pegdyn::compliant_peg::CompliantSystem::new(&setup.params, &load);
    let j = sys.jacobian(0.0, &setup.start.to_vector());
    assert_eq!(second_order_split(&j), Some(3));
    assert!(
        IterationLu::new(&j, 1e3, None, None)
            .expect("regular")
            .is_reduced()
    );
}

#[test]
fn a_singular_reduced_matrix_is_reported() {
    // v' = q + v at c = ... : cI - B - A/c = c - 1 - 1/c = 0 at c = golden ratio
    let j = nalgebra::Matrix2::new(0.0, 1.0, 1.0, 1.0);
    let golden = 0.5 * (1.0 + 5f64.sqrt());
    let w = IterationLu::new(&j, golden, None, None);
    // the pivot is a rounding residue or exactly zero: either refused
    // or tiny enough to be; the full matrix is singular there too
    if let Some(w) = w {
        let u = w.solve(&nalgebra::Vector2::new(1.0, 0.0));
        assert!(u.amax() > 1e12, "{u}");
    }
    let mut nan = j;
    nan[(1, 1)] = f64::NAN;
    assert!(IterationLu::new(&nan, 1.0, None, None).is_none());
}

/// A state of 3 components with 2 sensitivity columns: `J₀` on the
/// diagonal blocks, coupling blocks `B₁`, `B₂` in the first block column.
fn variational_like() -> SMatrix<f64, 9, 9> {
    let j0 = |i: usize, j: usize| (((i * 5 + j * 3) % 7) as f64 - 3.0) * 10f64.powi(i as i32 - 1);
    SMatrix::<f64, 9, 9>::from_fn(|i, j| {
        let (bi, bj) = (i / 3, j / 3);
        if bi == bj {
            j0(i % 3, j % 3)
        } else if bj == 0 {
            ((i * 11 + j * 7) % 13) as f64 - 6.0
        } else {
            0.0
        }
    })
}

#[test]
fn the_variational_block_solve_agrees_with_the_full_factorization() {
    let j = variational_like();
    let r =
        SVector::<f64, 9>::from_fn(|i, _| (2.0 + i as f64).cos() * 10f64.powi(i as i32 % 4 - 2));
    for c in [1e-3, 1.0, 4e2, 1e5, 1e9] {
        let blocks = IterationLu::new(&j, c, None, Some(3)).expect("regular");
        assert!(blocks.is_reduced(), "c = {c}: the block form is used");
        let full = Lu::new(SMatrix::<f64, 9, 9>::identity() * c - j).expect("regular");
        let (u, v) = (blocks.solve(&r), full.solve(&r));
        assert!((u - v).amax() <= 1e-11 * v.amax(), "c = {c}: {u} vs {v}");
    }
}

#[test]
fn a_jacobian_not_of_the_declared_block_form_is_factorized_whole() {
    let j = variational_like();
    // a coupling outside the first block column, a diagonal block that
    // differs from the first, a block size that does not divide N, and
    // the state's block alone: the full factorization, the same solution
    let mut upper = j;
    upper[(1, 4)] = 0.25;
    let mut coupled = j;
    coupled[(7, 4)] = 0.5;
    let mut diagonal = j;
    diagonal[(4, 4)] += 1e-9;
    let r = SVector::<f64, 9>::from_fn(|i, _| 1.0 + i as f64);
    for (m, blocks) in [(upper, 3), (coupled, 3), (diagonal, 3), (j, 2), (j, 9)] {
        let w = IterationLu::new(&m, 10.0, None, Some(blocks)).expect("regular");
        assert!(!w.is_reduced(), "block size {blocks}: factorized whole");
        let full = Lu::new(SMatrix::<f64, 9, 9>::identity() * 10.0 - m).expect("regular");
        assert_eq!(w.solve(&r), full.solve(&r));
    }
}
