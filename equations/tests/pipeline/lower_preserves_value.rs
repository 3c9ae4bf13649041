//! Lowering preserves values (`codegen::lower`: factored sums, shared
//! sub-products, merged powers).
//!
//! 1. Random expression trees over every node kind: the lowered DAG,
//!    evaluated by the interpreter, agrees with the raw tree's naive value
//!    to 1e-12 relative, or within a small multiple of the raw tree's
//!    rounding-error bound where the raw tree cancels (the criterion of
//!    `simplify_preserves_value.rs`).
//! 2. Sums of products of random trees, several roots lowered together (so
//!    that factoring and pair extraction act across roots): the lowered and
//!    the canonical DAG agree to 1e-12 relative, or within 100× the spread of
//!    the canonical value under 1e-14 relative input perturbations (how well
//!    the value is determined in f64 at all).

use crate::common;

use common::{Point, build, point, reference, tree};
use pegdyn_equations::codegen::lower::lower;
use pegdyn_equations::eval::Tape;
use pegdyn_equations::{Expr, Graph};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::cell::Cell;

const REL: f64 = 1e-12;
const BOUND_FACTOR: f64 = 16.0;

fn runner(cases: u32) -> TestRunner {
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha))
}

#[test]
fn lowered_trees_evaluate_like_raw_trees() {
    let (points, compared) = (Cell::new(0usize), Cell::new(0usize));
    let strategy = (tree(), prop::collection::vec(point(), 4));
    let result = runner(2000).run(&strategy, |(t, pts)| {
        let g = Graph::new();
        let e = build(&g, &t);
        let lowered = lower(&g, &[e.id()]);
        let tape = Tape::new(&g, &lowered);
        for p in &pts {
            points.set(points.get() + 1);
            let (naive, err) = reference(&t, p);
            if !naive.is_finite() || !err.is_finite() {
                continue;
            }
            compared.set(compared.get() + 1);
            let got = tape.eval(&p.by_symbol(&g))[0];
            let diff = (got - naive).abs();
            prop_assert!(
                diff <= REL * naive.abs() || diff <= BOUND_FACTOR * err,
                "lowered {e} = {got}, raw {t:?} = {naive} (error bound {err:e}) at {p:?}"
            );
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    assert!(
        compared.get() as f64 >= 0.6 * points.get() as f64,
        "only {} of {} points compared",
        compared.get(),
        points.get()
    );
}

/// Roots that give the lowering something to do: pairwise products and
/// sums of products of the trees `a`, `b`, `c`, sharing factors.
fn sums_of_products<'g>(g: &'g Graph, a: Expr<'g>, b: Expr<'g>, c: Expr<'g>) -> Vec<Expr<'g>> {
    let two = g.constant(2.0);
    let half = g.constant(0.5);
    vec![
        a * b + a * c + b * c,
        a * b * c - two * a * b + half * c * a,
        (a * b + c) * (a * c - b),
        half * a * a + half * b * b - a * b * c,
        a * b * c,
    ]
}

fn spread(tape: &Tape, p: &Point, g: &Graph, rng: &mut u64) -> Vec<f64> {
    let base = tape.eval(&p.by_symbol(g));
    let mut out = vec![0.0f64; base.len()];
    for _ in 0..8 {
        let moved: Vec<f64> = p
            .by_symbol(g)
            .iter()
            .map(|x| {
                *rng = rng
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let u = (*rng >> 11) as f64 / (1u64 << 53) as f64;
                x * (1.0 + 1e-14 * (2.0 * u - 1.0))
            })
            .collect();
        for (o, (m, b)) in out.iter_mut().zip(tape.eval(&moved).iter().zip(&base)) {
            *o = o.max((m - b).abs());
        }
    }
    out
}

#[test]
fn lowered_sums_of_products_evaluate_like_the_canonical_dag() {
    let (points, compared) = (Cell::new(0usize), Cell::new(0usize));
    let strategy = (tree(), tree(), tree(), prop::collection::vec(point(), 3));
    let result = runner(1000).run(&strategy, |(ta, tb, tc, pts)| {
        let g = Graph::new();
        let (a, b, c) = (build(&g, &ta), build(&g, &tb), build(&g, &tc));
        let roots: Vec<_> = sums_of_products(&g, a, b, c).iter().map(|e| e.id()).collect();
        let canonical = Tape::new(&g, &roots);
        let lowered = Tape::new(&g, &lower(&g, &roots));
        let mut rng = 0x2545_F491_4F6C_DD1Du64;
        for p in &pts {
            let want = canonical.eval(&p.by_symbol(&g));
            let got = lowered.eval(&p.by_symbol(&g));
            let mut s: Option<Vec<f64>> = None;
            for (k, (&x, &y)) in got.iter().zip(&want).enumerate() {
                points.set(points.get() + 1);
                if !y.is_finite() {
                    continue;
                }
                compared.set(compared.get() + 1);
                let diff = (x - y).abs();
                if diff <= REL * y.abs().max(f64::MIN_POSITIVE) {
                    continue;
                }
                let s = s.get_or_insert_with(|| spread(&canonical, p, &g, &mut rng));
                prop_assert!(
                    diff <= 100.0 * s[k],
                    "root {k}: lowered {x}, canonical {y}, spread {:e}, trees {ta:?} {tb:?} {tc:?} at {p:?}",
                    s[k]
                );
            }
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    assert!(
        compared.get() as f64 >= 0.5 * points.get() as f64,
        "only {} of {} values compared",
        compared.get(),
        points.get()
    );
}
