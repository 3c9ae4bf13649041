//! The items of `src/integrate/kinematic.rs`.

use nalgebra::{SMatrix, SVector};
use pegdyn::internals::integrate::Lu;
use pegdyn::internals::integrate::*;
use pegdyn::system::KinematicSplit;

/// A rigid body's Jacobian: `ṗ = v`, `q̇ = ½ Ξ(q) ω` (its exact blocks
/// at `q`, `ω`), the velocity rows and two integrals from a fixed
/// sequence.
fn rigid_body_like(q: [f64; 4], w: [f64; 3]) -> SMatrix<f64, 15, 15> {
    let xi = [
        [-q[1], -q[2], -q[3]],
        [q[0], -q[3], q[2]],
        [q[3], q[0], -q[1]],
        [-q[2], q[1], q[0]],
    ];
    let om = [
        [0.0, -w[0], -w[1], -w[2]],
        [w[0], 0.0, w[2], -w[1]],
        [w[1], -w[2], 0.0, w[0]],
        [w[2], w[1], -w[0], 0.0],
    ];
    SMatrix::<f64, 15, 15>::from_fn(|i, j| match (i, j) {
        (0..3, _) => f64::from(u8::from(j == i + 7)),
        (3..7, 3..7) => 0.5 * om[i - 3][j - 3],
        (3..7, 10..13) => 0.5 * xi[i - 3][j - 10],
        (3..7, _) => 0.0,
        (_, 13..) => 0.0,
        _ => (((i * 7 + j * 3) % 11) as f64 - 5.0) * 10f64.powi((i + j) as i32 % 6 - 1),
    })
}

#[test]
fn the_reduced_solve_agrees_with_the_full_factorization() {
    let n = 0.5f64.sqrt();
    let j = rigid_body_like(
        [n, 0.5, -0.1 * n, (0.5 - 0.01 * 0.5f64).sqrt()],
        [3.0, -40.0, 700.0],
    );
    let r =
        SVector::<f64, 15>::from_fn(|i, _| (1.0 + i as f64).sin() * 10f64.powi(i as i32 % 5 - 4));
    let split = KinematicSplit {
        positions: 7,
        velocities: 6,
    };
    for c in [1e-3, 1.0, 4e2, 1e5, 1e9] {
        let reduced = Kinematic::new(&j, c, split).expect("regular");
        let full = Lu::new(SMatrix::<f64, 15, 15>::identity() * c - j).expect("regular");
        let (u, v) = (reduced.solve(&r), full.solve(&r));
        assert!((u - v).amax() <= 1e-11 * v.amax(), "c = {c}: {u} vs {v}");
        let w = SMatrix::<f64, 15, 15>::identity() * c - j;
        let residual = (w * u - r).amax();
        assert!(
            residual <= 1e-12 * (w.amax() * u.amax()).max(r.amax()),
            "c = {c}: {residual}"
        );
    }
}

#[test]
fn the_closed_form_of_the_quaternion_block_is_what_the_elimination_computes() {
    // E⁻¹ of the quaternion rows: (cI + ½Ω)/(c² + |ω|²/4), so M's
    // quaternion block is that times ½ Ξ(q).
    let (q, w) = ([0.6, 0.0, 0.8, 0.0], [2.0, -3.0, 5.0]);
    let j = rigid_body_like(q, w);
    let c = 7.0;
    let k = Kinematic::new(
        &j,
        c,
        KinematicSplit {
            positions: 7,
            velocities: 6,
        },
    )
    .unwrap();
    let om = nalgebra::Matrix4::new(
        0.0, -w[0], -w[1], -w[2], w[0], 0.0, w[2], -w[1], w[1], -w[2], 0.0, w[0], w[2], w[1],
        -w[0], 0.0,
    );
    let xi = nalgebra::Matrix4x3::new(
        -q[1], -q[2], -q[3], q[0], -q[3], q[2], q[3], q[0], -q[1], -q[2], q[1], q[0],
    );
    let w2 = w.iter().map(|v| v * v).sum::<f64>();
    let closed = (nalgebra::Matrix4::identity() * c + om * 0.5) * xi * 0.5 / (c * c + 0.25 * w2);
    for a in 0..4 {
        for b in 0..3 {
            assert!(
                (k.m[(3 + a, 3 + b)] - closed[(a, b)]).abs() < 1e-15,
                "{a} {b}"
            );
        }
    }
    for a in 0..3 {
        assert!((k.m[(a, a)] - 1.0 / c).abs() < 1e-16);
    }
}

#[test]
fn a_split_that_does_not_fit_is_refused() {
    let j = rigid_body_like([1.0, 0.0, 0.0, 0.0], [1.0, 2.0, 3.0]);
    let sizes = |nx, nu| KinematicSplit {
        positions: nx,
        velocities: nu,
    };
    assert_eq!(
        Kinematic::new(&j, 1.0, sizes(7, 9)).err(),
        Some(Refused::NotThisForm)
    );
    assert_eq!(
        Kinematic::new(&j, 1.0, sizes(0, 6)).err(),
        Some(Refused::NotThisForm)
    );
    // an integral read by a rate
    let mut fed = j;
    fed[(8, 14)] = 1e-9;
    assert_eq!(
        Kinematic::new(&fed, 1.0, sizes(7, 6)).err(),
        Some(Refused::NotThisForm)
    );
    let mut nan = j;
    nan[(9, 9)] = f64::NAN;
    assert_eq!(
        Kinematic::new(&nan, 1.0, sizes(7, 6)).err(),
        Some(Refused::Singular)
    );
}
