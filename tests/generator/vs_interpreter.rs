//! Every generated function computes what the interpreter computes.
//!
//! For each registered model, and for the emitter-coverage model that
//! exercises every emission path, each function is called through the
//! build-generated call table on seeded random inputs and on special inputs
//! (0, −0, ±∞, NaN), and compared with `FnSpec::interpret` (the `eval::Tape`
//! interpreter over the same, canonical DAG). The generated code is the
//! lowered form of that DAG (`codegen::lower`: sums factored, shared
//! sub-products), so this test is also the check that lowering preserves
//! values. The two forms differ in rounding only, so the outputs agree to
//! a few ulps times the condition of the value: where they differ by more
//! than `TOL`, the difference must stay within the spread of the
//! interpreted value under relative input perturbations of `PERTURB`
//! (an estimate of how well the value is determined at all in f64; random
//! inputs far from the physical range make some sums ill-conditioned). A
//! wrong lowering changes values by their own size and fails either way.
//! NaN must appear in exactly the same places.

use pegdyn_equations::codegen::coverage;
use pegdyn_equations::graph::SymKind;
use pegdyn_equations::model::{FnSpec, Module};
use pegdyn_equations::{Graph, models};

use crate::common;
use common::Rng;

#[allow(clippy::all, dead_code)]
mod calls {
    include!(concat!(env!("OUT_DIR"), "/generated_calls.rs"));
}
use calls::CALLS;
use pegdyn::generated::registry::FUNCTIONS;

/// Random inputs: states in [-2, 2], parameters in [0.5, 2] (masses and
/// lengths are positive), time in [0, 10].
fn random_inputs(g: &Graph, f: &FnSpec, rng: &mut Rng) -> Vec<Vec<f64>> {
    f.inputs
        .iter()
        .map(|i| {
            i.syms
                .iter()
                .map(|&s| match g.sym_info(s).kind {
                    SymKind::Var => rng.uniform(-2.0, 2.0),
                    SymKind::Param => rng.uniform(0.5, 2.0),
                    SymKind::Time => rng.uniform(0.0, 10.0),
                })
                .collect()
        })
        .collect()
}

/// Every input component set to `v`.
fn constant_inputs(f: &FnSpec, v: f64) -> Vec<Vec<f64>> {
    f.inputs.iter().map(|i| vec![v; i.syms.len()]).collect()
}

const TRIALS: usize = 200;
/// Agreement required, relative to max(1, |interpreted value|).
const TOL: f64 = 1e-13;
const SPECIAL: [f64; 6] = [0.0, -0.0, 1.0, f64::INFINITY, f64::NEG_INFINITY, f64::NAN];

fn agree(a: f64, b: f64) -> bool {
    (a.is_nan() && b.is_nan()) || a == b || (a - b).abs() <= TOL * b.abs().max(1.0)
}

/// Relative size of the input perturbations that estimate conditioning.
const PERTURB: f64 = 1e-14;
/// Perturbed evaluations per estimate.
const SPREAD_SAMPLES: usize = 8;

/// The largest change of each output of `f` under relative perturbations
/// of every input by up to `PERTURB` (seeded).
fn spread(g: &Graph, f: &FnSpec, inputs: &[Vec<f64>], rng: &mut Rng) -> Vec<f64> {
    let base: Vec<f64> = {
        let slices: Vec<&[f64]> = inputs.iter().map(Vec::as_slice).collect();
        f.interpret(g, &slices).concat()
    };
    let mut out = vec![0.0f64; base.len()];
    for _ in 0..SPREAD_SAMPLES {
        let moved: Vec<Vec<f64>> = inputs
            .iter()
            .map(|v| {
                v.iter()
                    .map(|x| x * (1.0 + rng.uniform(-PERTURB, PERTURB)))
                    .collect()
            })
            .collect();
        let slices: Vec<&[f64]> = moved.iter().map(Vec::as_slice).collect();
        for (o, (m, b)) in out
            .iter_mut()
            .zip(f.interpret(g, &slices).concat().iter().zip(&base))
        {
            *o = o.max((m - b).abs());
        }
    }
    out
}

/// A generated function called on slices, outputs flattened.
type Caller = fn(&[&[f64]]) -> Vec<f64>;

/// The caller of `module::name` on slices: a registered model's from the
/// generated registry (the one list of generated functions), the
/// `coverage` module's from the test call table.
fn call(module: &str, name: &str) -> Option<Caller> {
    let registered = FUNCTIONS
        .iter()
        .find(|f| f.module == module && f.name == name)
        .map(|f| f.eval_f64);
    registered.or_else(|| {
        CALLS
            .iter()
            .find(|(m, n, _)| *m == module && *n == name)
            .map(|c| c.2)
    })
}

/// Checks every function of `m`; returns how many it checked.
fn check_module(g: &Graph, m: &Module, rng: &mut Rng) -> usize {
    for f in &m.functions {
        let call = call(&m.name, &f.name)
            .unwrap_or_else(|| panic!("{}::{} missing from the registry", m.name, f.name));
        let random: Vec<_> = (0..TRIALS).map(|_| random_inputs(g, f, rng)).collect();
        let special = SPECIAL.iter().map(|&v| constant_inputs(f, v));
        for inputs in random.into_iter().chain(special) {
            let slices: Vec<&[f64]> = inputs.iter().map(Vec::as_slice).collect();
            let want: Vec<f64> = f.interpret(g, &slices).concat();
            let got = call(&slices);
            assert_eq!(
                got.len(),
                want.len(),
                "{}::{}: output length",
                m.name,
                f.name
            );
            let mut within: Option<Vec<f64>> = None;
            for (k, (&a, &b)) in got.iter().zip(&want).enumerate() {
                if !agree(a, b) && a.is_finite() && b.is_finite() {
                    let s = within.get_or_insert_with(|| spread(g, f, &inputs, rng));
                    assert!(
                        (a - b).abs() <= 100.0 * s[k] + TOL * b.abs().max(1.0),
                        "{}::{} output[{k}]: generated {a:e}, interpreted {b:e}, \
                         spread under {PERTURB:e} input perturbation {:e}, inputs {inputs:?}",
                        m.name,
                        f.name,
                        s[k]
                    );
                    continue;
                }
                assert!(
                    agree(a, b),
                    "{}::{} output[{k}]: generated {a:e}, interpreted {b:e}, inputs {inputs:?}",
                    m.name,
                    f.name
                );
            }
        }
    }
    m.functions.len()
}

#[test]
fn every_generated_function_matches_the_interpreter() {
    let mut rng = Rng(0);
    let mut checked = 0;
    for build in models::ALL {
        let g = Graph::new();
        checked += check_module(&g, &build.module(&g), &mut rng);
    }
    let g = Graph::new();
    checked += check_module(&g, &coverage::module(&g), &mut rng);
    assert_eq!(
        checked,
        FUNCTIONS.len() + CALLS.len(),
        "registry + coverage call table and the models disagree"
    );
}
