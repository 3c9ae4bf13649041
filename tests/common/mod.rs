//! Shared by the integration tests: each group's `main.rs` declares this
//! module once (`#[path = "../common/mod.rs"] mod common;`) and its files take
//! what they need (`use crate::common::peg3d;`). Here: a double-double
//! evaluation of any expression graph (the reference for the `f64`
//! interpreter) with ulps; the submodules hold a seeded SplitMix64 source of
//! inputs ([`rng`]), the rigid peg fixtures ([`rigid`], [`prescribed_rigid`]),
//! the compliant 3-D peg's ([`peg3d`]), the wrist insertion's ([`rcc`]), the
//! Rosenbrock tableau checks ([`rosenbrock`]), running the `pegdyn` binary
//! ([`cli`]), the scene fuzzer's strategies ([`fuzz`]), the numeric
//! fields of a scene text by path and line ([`fields`]) and shipped scene
//! texts ([`scene_text`]).

#![allow(dead_code)]

use std::collections::HashMap;

use pegdyn::accuracy::entry_error;
use pegdyn::scalar::{Dd, Real};
use pegdyn_equations::graph::{Binary, Node};
use pegdyn_equations::{Graph, Id};

pub mod cli;
pub mod differences;
pub mod fields;
pub mod fuzz;
pub mod peg3d;
pub mod prescribed_rigid;
pub mod rcc;
pub mod rigid;
pub mod rosenbrock;
pub mod scene_text;
pub mod search_reference;

pub mod rng;
#[allow(unused_imports)]
pub use rng::Rng;

/// `root` evaluated in double-double with symbol values from `value`
/// (by name), with the emitter's choices for powers (0.5 → sqrt, integer →
/// powi, ...), so that it is the same formula as the `f64` evaluation.
pub fn eval_dd(g: &Graph, root: Id, value: &dyn Fn(&str) -> f64) -> Dd {
    fn go(g: &Graph, id: Id, value: &dyn Fn(&str) -> f64, memo: &mut HashMap<Id, Dd>) -> Dd {
        if let Some(&v) = memo.get(&id) {
            return v;
        }
        let mut ev = |c: Id| go(g, c, value, memo);
        let v = match g.node(id) {
            Node::Const(c) => Dd::from(c.value()),
            Node::Sym(s) => Dd::from(value(&g.sym_info(s).name)),
            Node::Add(xs) => xs[1..].iter().fold(ev(xs[0]), |a, &x| a + ev(x)),
            Node::Mul(xs) => xs[1..].iter().fold(ev(xs[0]), |a, &x| a * ev(x)),
            Node::Pow(b, e) => {
                let (b, e) = (ev(b), ev(e));
                let n = e.hi();
                if n == 0.5 {
                    b.sqrt()
                } else if n == -0.5 {
                    Dd::ONE / b.sqrt()
                } else if n == 1.5 {
                    b * b.sqrt()
                } else if n.fract() == 0.0 && n.abs() <= 64.0 {
                    b.powi(n as i32)
                } else {
                    b.powf(e)
                }
            }
            Node::Unary(op, a) => {
                let a = ev(a);
                use pegdyn_equations::graph::Unary as U;
                match op {
                    U::Sin => a.sin(),
                    U::Cos => a.cos(),
                    U::Tan => Real::tan(a),
                    U::Asin => Real::asin(a),
                    U::Acos => Real::acos(a),
                    U::Atan => Real::atan(a),
                    U::Exp => a.exp(),
                    U::Expm1 => a.exp_m1(),
                    U::Ln => a.ln(),
                    U::Ln1p => a.ln_1p(),
                    U::Abs => a.abs(),
                    U::Sign => Real::sign(a),
                    U::Tanh => Real::tanh(a),
                    U::Max0 => Real::max0(a),
                    U::Step => Real::step(a),
                }
            }
            Node::Binary(op, a, b) => {
                let (a, b) = (ev(a), ev(b));
                match op {
                    Binary::Atan2 => a.atan2(b),
                    Binary::Hypot => a.hypot(b),
                }
            }
        };
        memo.insert(id, v);
        v
    }
    go(g, root, value, &mut HashMap::new())
}

/// `root` evaluated by the generator's `f64` interpreter.
pub fn eval_f64(g: &Graph, root: Id, value: &dyn Fn(&str) -> f64) -> f64 {
    pegdyn_equations::eval::eval(g, root, |s| value(&g.sym_info(s).name))
}

/// Error of `value` against `reference` in ulps of the reference.
pub fn ulps(value: f64, reference: Dd) -> f64 {
    entry_error(value, reference).ulps
}
