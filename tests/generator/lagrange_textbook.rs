//! The generated textbook models agree with their closed forms.
//!
//! - Simple pendulum: M = m l², f = −m g l sin θ, E = ½ m l² θ̇² − m g l cos θ.
//! - Double pendulum (absolute angles, point masses), δ = θ1 − θ2:
//!   M = [[(m1+m2) l1², m2 l1 l2 cos δ], [m2 l1 l2 cos δ, m2 l2²]],
//!   f1 = −m2 l1 l2 θ̇2² sin δ − (m1+m2) g l1 sin θ1,
//!   f2 =  m2 l1 l2 θ̇1² sin δ − m2 g l2 sin θ2.
//! - Cart-pole (θ from the downward vertical, push force u):
//!   M = [[mc + m, m l cos θ], [m l cos θ, m l²]],
//!   f = (u + m l θ̇² sin θ, −m g l sin θ).
//! - For each, the state Jacobian assembled from the generated pieces,
//!   J = [[0, I], [M⁻¹ G(q̈)]], matches central finite differences of the
//!   generated right-hand side.
//!
//! Values are compared relative to the magnitude of the closed form's terms
//! (a sum that cancels is judged against its summands, not its result).

use nalgebra::{DMatrix, SVector};
use pegdyn::generated::{cart_pole, double_pendulum as dp, pendulum};

use crate::common;
use common::Rng;

const TRIALS: usize = 100;
const REL: f64 = 1e-13;

/// |a − b| ≤ REL · scale, where `scale` is the magnitude of the terms of b.
fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= REL * scale.max(f64::MIN_POSITIVE)
}

#[test]
fn pendulum_matches_textbook() {
    let mut rng = Rng(1);
    for _ in 0..TRIALS {
        let x: SVector<f64, 2> = rng.vector(-3.0, 3.0);
        let p: SVector<f64, 3> = rng.vector(0.2, 5.0);
        let (th, w, m, l, g) = (x[0], x[1], p[0], p[1], p[2]);
        let pendulum::DynamicsOut { mass, forcing } = pendulum::dynamics(&x, &p);
        assert!(close(mass[(0, 0)], m * l * l, m * l * l), "M = {mass}");
        let f = -m * g * l * th.sin();
        assert!(close(forcing[0], f, f.abs()), "f = {forcing} want {f}");
        let xdot = pendulum::rhs(&x, &p);
        assert_eq!(xdot[0], w);
        let a = -g / l * th.sin();
        assert!(close(xdot[1], a, a.abs()), "thetaddot {} want {a}", xdot[1]);
        let (kin, pot) = (0.5 * m * l * l * w * w, -m * g * l * th.cos());
        let e = pendulum::energy(&x, &p);
        assert!(
            close(e, kin + pot, kin.abs() + pot.abs()),
            "E = {e} want {}",
            kin + pot
        );
    }
}

#[test]
fn double_pendulum_matches_textbook() {
    let mut rng = Rng(2);
    for _ in 0..TRIALS {
        let x: SVector<f64, 4> = rng.vector(-3.0, 3.0);
        let p: SVector<f64, 5> = rng.vector(0.2, 5.0);
        let (t1, t2, w1, w2) = (x[0], x[1], x[2], x[3]);
        let (m1, m2, l1, l2, g) = (p[0], p[1], p[2], p[3], p[4]);
        let d = t1 - t2;
        let dp::DynamicsOut { mass, forcing } = dp::dynamics(&x, &p);
        let want_m = [
            [(m1 + m2) * l1 * l1, m2 * l1 * l2 * d.cos()],
            [m2 * l1 * l2 * d.cos(), m2 * l2 * l2],
        ];
        let scale_m = [
            [(m1 + m2) * l1 * l1, m2 * l1 * l2],
            [m2 * l1 * l2, m2 * l2 * l2],
        ];
        for i in 0..2 {
            for j in 0..2 {
                assert!(
                    close(mass[(i, j)], want_m[i][j], scale_m[i][j]),
                    "M[{i}{j}] = {} want {}",
                    mass[(i, j)],
                    want_m[i][j]
                );
            }
        }
        let (a1, b1) = (
            -m2 * l1 * l2 * w2 * w2 * d.sin(),
            -(m1 + m2) * g * l1 * t1.sin(),
        );
        let (a2, b2) = (m2 * l1 * l2 * w1 * w1 * d.sin(), -m2 * g * l2 * t2.sin());
        assert!(
            close(forcing[0], a1 + b1, a1.abs() + b1.abs()),
            "f1 = {} want {}",
            forcing[0],
            a1 + b1
        );
        assert!(
            close(forcing[1], a2 + b2, a2.abs() + b2.abs()),
            "f2 = {} want {}",
            forcing[1],
            a2 + b2
        );
    }
}

#[test]
fn cart_pole_matches_textbook() {
    let mut rng = Rng(5);
    for _ in 0..TRIALS {
        let x: SVector<f64, 4> = rng.vector(-3.0, 3.0);
        let p = SVector::<f64, 5>::from_fn(|i, _| {
            if i == 4 {
                rng.uniform(-10.0, 10.0)
            } else {
                rng.uniform(0.2, 5.0)
            }
        });
        let (th, w) = (x[1], x[3]);
        let (mc, m, l, g, u) = (p[0], p[1], p[2], p[3], p[4]);
        let cart_pole::DynamicsOut { mass, forcing } = cart_pole::dynamics(&x, &p);
        let want_m = [[mc + m, m * l * th.cos()], [m * l * th.cos(), m * l * l]];
        let scale_m = [[mc + m, m * l], [m * l, m * l * l]];
        for i in 0..2 {
            for j in 0..2 {
                assert!(
                    close(mass[(i, j)], want_m[i][j], scale_m[i][j]),
                    "M[{i}{j}] = {} want {}",
                    mass[(i, j)],
                    want_m[i][j]
                );
            }
        }
        let a1 = m * l * w * w * th.sin();
        assert!(
            close(forcing[0], u + a1, u.abs() + a1.abs()),
            "f1 = {} want {}",
            forcing[0],
            u + a1
        );
        let f2 = -m * g * l * th.sin();
        assert!(
            close(forcing[1], f2, f2.abs()),
            "f2 = {} want {f2}",
            forcing[1]
        );
    }
}

/// J = [[0, I], [M⁻¹ G]] from the generated pieces, G at q̈ from `rhs`.
fn assembled_jacobian<const N: usize, const Q: usize>(
    rhs: impl Fn(&SVector<f64, N>) -> SVector<f64, N>,
    mass: DMatrix<f64>,
    g_at: impl Fn(&SVector<f64, Q>) -> DMatrix<f64>,
    x: &SVector<f64, N>,
) -> DMatrix<f64> {
    let qdd = SVector::<f64, Q>::from_fn(|i, _| rhs(x)[Q + i]);
    let lower = mass
        .lu()
        .solve(&g_at(&qdd))
        .expect("mass matrix is regular");
    let mut j = DMatrix::zeros(N, N);
    for i in 0..Q {
        j[(i, Q + i)] = 1.0;
    }
    j.view_mut((Q, 0), (Q, N)).copy_from(&lower);
    j
}

/// Central differences of `rhs` at `x`.
fn finite_difference<const N: usize>(
    rhs: impl Fn(&SVector<f64, N>) -> SVector<f64, N>,
    x: &SVector<f64, N>,
) -> DMatrix<f64> {
    let mut j = DMatrix::zeros(N, N);
    for k in 0..N {
        let h = 1e-6 * x[k].abs().max(1.0);
        let (mut xp, mut xm) = (*x, *x);
        xp[k] += h;
        xm[k] -= h;
        let col = (rhs(&xp) - rhs(&xm)) / (2.0 * h);
        j.column_mut(k).copy_from(&col);
    }
    j
}

fn assert_jacobians_close(exact: &DMatrix<f64>, fd: &DMatrix<f64>, what: &str) {
    let scale = exact.amax().max(1.0);
    let err = (exact - fd).amax();
    assert!(
        err <= 1e-7 * scale,
        "{what}: |J - J_fd| = {err:e} (scale {scale:e})\nJ = {exact}\nJ_fd = {fd}"
    );
}

#[test]
fn pendulum_jacobian_matches_finite_differences() {
    let mut rng = Rng(3);
    for _ in 0..TRIALS {
        let x: SVector<f64, 2> = rng.vector(-3.0, 3.0);
        let p: SVector<f64, 3> = rng.vector(0.2, 5.0);
        let rhs = |x: &SVector<f64, 2>| pendulum::rhs(x, &p);
        let mass = DMatrix::from_column_slice(1, 1, pendulum::dynamics(&x, &p).mass.as_slice());
        let g_at = |qdd: &SVector<f64, 1>| {
            DMatrix::from_column_slice(1, 2, pendulum::jacobian_terms(&x, qdd, &p).as_slice())
        };
        let exact = assembled_jacobian::<2, 1>(rhs, mass, g_at, &x);
        assert_jacobians_close(&exact, &finite_difference(rhs, &x), "pendulum");
    }
}

#[test]
fn double_pendulum_jacobian_matches_finite_differences() {
    let mut rng = Rng(4);
    for _ in 0..TRIALS {
        let x: SVector<f64, 4> = rng.vector(-3.0, 3.0);
        let p: SVector<f64, 5> = rng.vector(0.5, 2.0);
        let rhs = |x: &SVector<f64, 4>| dp::rhs(x, &p);
        let mass = DMatrix::from_column_slice(2, 2, dp::dynamics(&x, &p).mass.as_slice());
        let g_at = |qdd: &SVector<f64, 2>| {
            DMatrix::from_column_slice(2, 4, dp::jacobian_terms(&x, qdd, &p).as_slice())
        };
        let exact = assembled_jacobian::<4, 2>(rhs, mass, g_at, &x);
        assert_jacobians_close(&exact, &finite_difference(rhs, &x), "double pendulum");
    }
}

#[test]
fn cart_pole_jacobian_matches_finite_differences() {
    let mut rng = Rng(6);
    for _ in 0..TRIALS {
        let x: SVector<f64, 4> = rng.vector(-3.0, 3.0);
        let p: SVector<f64, 5> = rng.vector(0.5, 2.0);
        let rhs = |x: &SVector<f64, 4>| cart_pole::rhs(x, &p);
        let mass = DMatrix::from_column_slice(2, 2, cart_pole::dynamics(&x, &p).mass.as_slice());
        let g_at = |qdd: &SVector<f64, 2>| {
            DMatrix::from_column_slice(2, 4, cart_pole::jacobian_terms(&x, qdd, &p).as_slice())
        };
        let exact = assembled_jacobian::<4, 2>(rhs, mass, g_at, &x);
        assert_jacobians_close(&exact, &finite_difference(rhs, &x), "cart-pole");
    }
}
