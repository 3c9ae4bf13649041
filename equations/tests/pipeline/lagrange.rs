//! `lagrange::derive` against hand-derived equations of motion.
//!
//! Each case states T, V and Q, the M and f a textbook derivation gives,
//! and checks the symbolic result with the interpreter at seeded random
//! points. The cases are chosen so that every term of
//! f_i = Q_i − ∂V/∂q_i + ∂T/∂q_i − Σ_j ∂²T/∂q̇_i∂q_j q̇_j − ∂²T/∂q̇_i∂t
//! matters in at least one of them.

use pegdyn_equations::lagrange::{self, Lagrange};
use pegdyn_equations::{Expr, Graph, Node, eval};

/// SplitMix64 in [lo, hi).
struct Rng(u64);
impl Rng {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        lo + (hi - lo) * ((z >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// Random values for every symbol of `g`, in [0.5, 2].
fn point(g: &Graph, rng: &mut Rng) -> Vec<f64> {
    g.symbols().iter().map(|_| rng.uniform(0.5, 2.0)).collect()
}

fn at(e: Expr<'_>, vals: &[f64]) -> f64 {
    eval::eval(e.graph(), e.id(), |s| vals[s.index()])
}

fn assert_close(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= 1e-13 * want.abs().max(1.0),
        "{what}: got {got}, want {want}"
    );
}

/// Checks `lag.mass` and `lag.forcing` against closures of the symbol values.
fn check(
    g: &Graph,
    lag: &Lagrange<'_>,
    mass: impl Fn(&[f64]) -> Vec<Vec<f64>>,
    forcing: impl Fn(&[f64]) -> Vec<f64>,
) {
    let mut rng = Rng(7);
    for _ in 0..50 {
        let v = point(g, &mut rng);
        for (i, row) in mass(&v).iter().enumerate() {
            for (j, &want) in row.iter().enumerate() {
                assert_close(at(lag.mass[i][j], &v), want, &format!("M[{i}][{j}]"));
            }
        }
        for (i, want) in forcing(&v).into_iter().enumerate() {
            assert_close(at(lag.forcing[i], &v), want, &format!("f[{i}]"));
        }
    }
}

fn idx(e: Expr<'_>) -> usize {
    match e.node() {
        Node::Sym(s) => s.index(),
        _ => unreachable!("not a symbol"),
    }
}

#[test]
fn polar_free_particle_has_centrifugal_and_coriolis_terms() {
    // T = ½ m (ṙ² + r² φ̇²): M = diag(m, m r²), f = (m r φ̇², −2 m r ṙ φ̇).
    let g = Graph::new();
    let (r, rd, rdd) = (g.var("r"), g.var("rdot"), g.var("rddot"));
    let (phi, phid, phidd) = (g.var("phi"), g.var("phidot"), g.var("phiddot"));
    let m = g.param("m");
    let t = 0.5 * m * (rd.square() + r.square() * phid.square());
    let zero = g.constant(0.0);
    let lag = lagrange::derive(
        &g,
        &[(r, rd, rdd), (phi, phid, phidd)],
        t,
        zero,
        &[zero, zero],
    );
    let (ir, ird, iphid, im) = (idx(r), idx(rd), idx(phid), idx(m));
    check(
        &g,
        &lag,
        |v| vec![vec![v[im], 0.0], vec![0.0, v[im] * v[ir] * v[ir]]],
        |v| {
            vec![
                v[im] * v[ir] * v[iphid] * v[iphid],
                -2.0 * v[im] * v[ir] * v[ird] * v[iphid],
            ]
        },
    );
}

#[test]
fn explicit_time_dependence_enters_through_the_momentum() {
    // Mass in a uniformly accelerating frame: T = ½ m (q̇ + a t)², V = ½ k q²,
    // Q = −c q̇. Then M = m and f = −c q̇ − k q − m a (the −∂²T/∂q̇∂t term).
    let g = Graph::new();
    let (q, qd, qdd) = (g.var("q"), g.var("qdot"), g.var("qddot"));
    let (m, a, k, c) = (g.param("m"), g.param("a"), g.param("k"), g.param("c"));
    let time = g.time();
    let t = 0.5 * m * (qd + a * time).square();
    let v = 0.5 * k * q.square();
    let lag = lagrange::derive(&g, &[(q, qd, qdd)], t, v, &[-c * qd]);
    let (iq, iqd, im, ia, ik, ic) = (idx(q), idx(qd), idx(m), idx(a), idx(k), idx(c));
    check(
        &g,
        &lag,
        |v| vec![vec![v[im]]],
        |v| vec![-v[ic] * v[iqd] - v[ik] * v[iq] - v[im] * v[ia]],
    );
}

#[test]
fn configuration_dependent_mass_gives_velocity_squared_forcing() {
    // T = ½ (1 + q²) q̇²: M = 1 + q², f = ∂T/∂q − ∂²T/∂q̇∂q q̇ = q q̇² − 2 q q̇² = −q q̇².
    // G = [∂f/∂q − ∂M/∂q q̈, ∂f/∂q̇] = [−q̇² − 2 q q̈, −2 q q̇].
    let g = Graph::new();
    let (q, qd, qdd) = (g.var("q"), g.var("qdot"), g.var("qddot"));
    let t = 0.5 * (1.0 + q.square()) * qd.square();
    let zero = g.constant(0.0);
    let lag = lagrange::derive(&g, &[(q, qd, qdd)], t, zero, &[zero]);
    let (iq, iqd, iqdd) = (idx(q), idx(qd), idx(qdd));
    check(
        &g,
        &lag,
        |v| vec![vec![1.0 + v[iq] * v[iq]]],
        |v| vec![-v[iq] * v[iqd] * v[iqd]],
    );
    let gm = lag.accel_jacobian_terms();
    let mut rng = Rng(8);
    for _ in 0..50 {
        let v = point(&g, &mut rng);
        let (q, qd, qdd) = (v[iq], v[iqd], v[iqdd]);
        assert_close(at(gm[0][0], &v), -qd * qd - 2.0 * q * qdd, "G[0][0]");
        assert_close(at(gm[0][1], &v), -2.0 * q * qd, "G[0][1]");
    }
}

#[test]
fn mass_matrix_is_symmetric_by_identity() {
    let g = Graph::new();
    let (q1, w1, a1) = (g.var("q1"), g.var("w1"), g.var("a1"));
    let (q2, w2, a2) = (g.var("q2"), g.var("w2"), g.var("a2"));
    let t = 0.5 * (w1.square() + (w1 * q2.cos() + w2).square() + q1.square() * w2.square());
    let zero = g.constant(0.0);
    let lag = lagrange::derive(&g, &[(q1, w1, a1), (q2, w2, a2)], t, zero, &[zero, zero]);
    assert_eq!(lag.mass[0][1], lag.mass[1][0]);
}

#[test]
fn cramer_solution_satisfies_the_equations_of_motion() {
    // Three masses on a line in relative coordinates: x_i = q_1 + .. + q_i,
    // T = ½ Σ m_i ẋ_i² (a full constant M), springs V = ½ Σ k_i q_i² plus a
    // q-dependent coupling so that f is not linear.
    let g = Graph::new();
    let coords: Vec<_> = (1..=3)
        .map(|i| {
            (
                g.var(&format!("q{i}")),
                g.var(&format!("q{i}dot")),
                g.var(&format!("q{i}ddot")),
            )
        })
        .collect();
    let m: Vec<Expr<'_>> = (1..=3).map(|i| g.param(&format!("m{i}"))).collect();
    let k: Vec<Expr<'_>> = (1..=3).map(|i| g.param(&format!("k{i}"))).collect();
    let xdot = |i: usize| g.sum(coords[..=i].iter().map(|c| c.1));
    let t = g.sum((0..3).map(|i| 0.5 * m[i] * xdot(i).square()));
    let v = g.sum((0..3).map(|i| 0.5 * k[i] * coords[i].0.square()))
        + (coords[0].0 * coords[2].0).cos();
    let zero = g.constant(0.0);
    let lag = lagrange::derive(&g, &coords, t, v, &[zero, zero, zero]);
    let qdd = lag
        .accelerations_solved()
        .expect("3 DOF is solved in closed form");
    let mut rng = Rng(9);
    for _ in 0..50 {
        let vals = point(&g, &mut rng);
        let a: Vec<f64> = qdd.iter().map(|&e| at(e, &vals)).collect();
        for i in 0..3 {
            let lhs: f64 = (0..3).map(|j| at(lag.mass[i][j], &vals) * a[j]).sum();
            assert_close(
                lhs,
                at(lag.forcing[i], &vals),
                &format!("(M q̈)[{i}] = f[{i}]"),
            );
        }
    }
}
