//! The items of `src/integrate/lu.rs`.

use nalgebra::{Matrix3, Vector3};
use pegdyn::internals::integrate::Lu;

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
