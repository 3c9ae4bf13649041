//! A model that exercises every emission path: every function kind, the
//! branchy `max0` / `step` / `sign`, every power form (`x²`, `x³`, `powi`,
//! reciprocal powers, `sqrt`, `1/sqrt`, `x^1.5`, `cbrt`, `powf`, variable exponent),
//! multi-factor denominators, negative coefficients, constant and symbol
//! outputs, shared subexpressions.
//!
//! It is not part of `pegdyn::generated`: `build.rs` emits it only into the
//! test call table (`generated_calls.rs`), where
//! `tests/generator/vs_interpreter.rs` checks it against the interpreter
//! on random and special (0, −0, ±∞, NaN) inputs.

use crate::graph::Graph;
use crate::model::{FnSpec, Input, Module, Output};

/// The coverage module (`emit_coverage`).
pub fn module(g: &Graph) -> Module {
    let (a, b, c) = (g.var("a"), g.var("b"), g.var("c"));
    let k = g.param("k");
    let x = Input::new("x", &[a, b, c]);
    let p = Input::new("p", &[k]);
    let one = g.constant(1.0);
    let pos = a * a + one; // > 0 for real a
    let shared = a * b + c;
    let spec = |name: &str, inputs: Vec<Input>, outputs: Vec<(&str, Output)>| {
        FnSpec::new(name, format!("Emitter coverage: {name}."), inputs, outputs)
    };
    let branches = spec(
        "branches",
        vec![x.clone()],
        vec![(
            "v",
            Output::vector(&[
                a.max0(),
                b.step(),
                c.signum(),
                a.abs(),
                (a - b).max0() * k.powi(0) + shared.step() * shared,
            ]),
        )],
    );
    let calls = spec(
        "calls",
        vec![x.clone()],
        vec![(
            "v",
            Output::vector(&[
                a.sin() + b.cos() - c.tan(),
                (a / 3.0).asin() * (b / 3.0).acos() + a.atan(),
                a.exp() - b.exp_m1() + (a * a).ln_1p() + pos.ln(),
                a.tanh() + a.atan2(b) + b.hypot(c),
            ]),
        )],
    );
    let powers = spec(
        "powers",
        vec![x.clone(), p.clone()],
        vec![
            (
                "v",
                Output::vector(&[
                    a.square() + b.powi(3) + c.powi(5),
                    a.powi(-1) + b.powi(-2) - 2.0 * c.powi(-3) + a.powi(-7),
                    pos.sqrt()
                        + pos.powf(-0.5)
                        + pos.powf(1.5)
                        + pos.powf(0.3)
                        + pos.pow(k)
                        + pos.powf(1.0 / 3.0)
                        + a.powf(2.0 / 3.0),
                    (shared + 1.0).square() * (shared - 2.0).powi(-2),
                ]),
            ),
            (
                "m",
                Output::matrix(&[
                    vec![a / (b * c), -2.0 * a / b.square(), -a, g.constant(-1.5)],
                    vec![
                        g.constant(0.0),
                        c,
                        -(a * b) / k,
                        (a - b) * (b - c) / (k * pos),
                    ],
                ]),
            ),
            ("s", Output::scalar(-a + b - c * k / (1.0 + k))),
        ],
    );
    Module::new(
        "emit_coverage",
        "Emitter coverage model (test only).",
        vec![branches, calls, powers],
    )
}
