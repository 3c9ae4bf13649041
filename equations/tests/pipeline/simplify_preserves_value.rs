//! Simplification preserves values: random expression trees over every node
//! kind, built (a) through the simplifying constructors and evaluated by the
//! interpreter, and (b) evaluated as the raw tree by a naive reference
//! evaluator, agree wherever the raw tree is defined.
//!
//! Agreement means a relative difference of at most 1e-12, or, where the raw
//! tree itself cancels (`x + y - x` with large `x`), a difference within a
//! small multiple of the raw tree's first-order rounding-error bound. Points
//! where the raw tree is undefined (NaN, infinite) are skipped and counted;
//! the test asserts that most points are actually compared.

use crate::common;

use common::{Point, Tree, build, point, reference, tree};
use pegdyn_equations::Graph;
use pegdyn_equations::eval::Tape;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::cell::Cell;

/// Relative tolerance for agreement where the raw tree is well conditioned.
const REL: f64 = 1e-12;
/// Multiple of the raw tree's rounding-error bound accepted otherwise.
const BOUND_FACTOR: f64 = 16.0;

#[derive(Default, Debug)]
struct Tally {
    points: Cell<usize>,
    /// Agree to `REL`.
    tight: Cell<usize>,
    /// Agree within the raw tree's error bound.
    by_bound: Cell<usize>,
    /// Raw tree NaN or infinite there.
    undefined: Cell<usize>,
    /// A jump or branch cut within rounding error.
    unstable: Cell<usize>,
}

fn bump(c: &Cell<usize>) {
    c.set(c.get() + 1);
}

fn check(t: &Tree, pts: &[Point], tally: &Tally) -> Result<(), TestCaseError> {
    let g = Graph::new();
    let e = build(&g, t);
    let tape = Tape::new(&g, &[e.id()]);
    for p in pts {
        bump(&tally.points);
        let (naive, err) = reference(t, p);
        if !naive.is_finite() {
            bump(&tally.undefined);
            continue;
        }
        if !err.is_finite() {
            bump(&tally.unstable);
            continue;
        }
        let simple = tape.eval(&p.by_symbol(&g))[0];
        let diff = (simple - naive).abs();
        if diff <= REL * naive.abs() {
            bump(&tally.tight);
        } else {
            prop_assert!(
                diff <= BOUND_FACTOR * err,
                "simplified {e} = {simple}, raw {t:?} = {naive} (error bound {err:e}) at {p:?}"
            );
            bump(&tally.by_bound);
        }
    }
    Ok(())
}

#[test]
fn simplified_trees_evaluate_like_raw_trees() {
    let config = Config {
        cases: 3000,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    let tally = Tally::default();
    let strategy = (tree(), prop::collection::vec(point(), 4));
    if let Err(e) = runner.run(&strategy, |(t, pts)| check(&t, &pts, &tally)) {
        panic!("{e}");
    }
    eprintln!("{tally:?}");
    let n = tally.points.get() as f64;
    let compared = (tally.tight.get() + tally.by_bound.get()) as f64;
    assert!(
        compared >= 0.6 * n,
        "only {compared} of {n} points compared: {tally:?}"
    );
    assert!(
        tally.tight.get() as f64 >= 0.5 * n,
        "only {} of {n} points agree tightly",
        tally.tight.get()
    );
}
