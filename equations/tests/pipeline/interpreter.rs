//! The interpreter (`eval::Tape`) computes what the emitted code computes:
//! the same special cases for powers, NaN propagation through the contact
//! laws, sums and products left to right in canonical operand order. These
//! are the semantics the generated-vs-interpreter tests rely on.

use pegdyn_equations::eval::{self, Tape};
use pegdyn_equations::graph::{Binary, Unary};
use pegdyn_equations::{Graph, Node};

fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

#[test]
fn pow_special_cases_match_the_emitter() {
    for b in [0.0, 0.3, 2.0, 7.5, -2.0, -0.0] {
        assert!(same(eval::pow(b, 0.5), b.sqrt()), "sqrt {b}");
        assert!(same(eval::pow(b, -0.5), 1.0 / b.sqrt()), "1/sqrt {b}");
        assert!(same(eval::pow(b, 1.5), b * b.sqrt()), "b sqrt(b) {b}");
        assert!(same(eval::pow(b, 2.0), b * b), "b*b {b}");
        assert!(same(eval::pow(b, 3.0), b * b * b), "b*b*b {b}");
        assert!(same(eval::pow(b, 1.0 / 3.0), b.cbrt()), "cbrt {b}");
        assert!(
            same(eval::pow(b, 2.0 / 3.0), b.cbrt().powi(2)),
            "cbrt^2 {b}"
        );
        for n in [-64, -3, -1, 2, 3, 17, 64] {
            assert!(same(eval::pow(b, f64::from(n)), b.powi(n)), "powi {b} {n}");
        }
        for e in [2.5, -1.5, -1.0 / 3.0, 0.25, 65.0, -65.0, 100.0] {
            assert!(same(eval::pow(b, e), b.powf(e)), "powf {b} {e}");
        }
    }
}

#[test]
fn tape_factors_sums_as_the_emitter_does() {
    // a·c + b·c is emitted as c·(a + b); at a = 0, b = 1, c = ∞ that is ∞,
    // where the unfactored sum would be 0·∞ + ∞ = NaN.
    let g = Graph::new();
    let (a, b, c) = (g.var("a"), g.var("b"), g.var("c"));
    let tape = Tape::new(&g, &[(a * c + b * c).id()]);
    let out = tape.eval(&[0.0, 1.0, f64::INFINITY]);
    assert_eq!(out[0], f64::INFINITY);
    let out = tape.eval(&[0.1, 0.7, 3.0]);
    assert!(same(out[0], 3.0 * (0.1 + 0.7)), "{out:?}");
    // A product that is also an output (a `let`) is not split: a·c + b·c
    // then adds the two products, 0·∞ + ∞ = NaN, as the emitted code does.
    let ac = a * c;
    let tape = Tape::new(&g, &[(ac + b * c).id(), ac.id()]);
    let out = tape.eval(&[0.0, 1.0, f64::INFINITY]);
    assert!(out[0].is_nan(), "{out:?}");
}

#[test]
fn tape_powers_use_the_same_special_cases() {
    let g = Graph::new();
    let x = g.var("x");
    let roots = [
        x.sqrt(),
        x.powf(-0.5),
        x.powi(3),
        x.powf(2.5),
        x.powi(-2),
        x.powf(1.0 / 3.0),
        x.powf(2.0 / 3.0),
    ];
    let tape = Tape::new(&g, &roots.map(|e| e.id()));
    let v = 1.7f64;
    let out = tape.eval(&[v]);
    let want = [
        v.sqrt(),
        1.0 / v.sqrt(),
        v.powi(3),
        v.powf(2.5),
        v.powi(-2),
        v.cbrt(),
        v.cbrt() * v.cbrt(),
    ];
    for (o, w) in out.iter().zip(want) {
        assert!(same(*o, w), "{o} vs {w}");
    }
}

#[test]
fn contact_laws_propagate_nan() {
    let nan = f64::NAN;
    for op in [Unary::Max0, Unary::Step, Unary::Sign] {
        assert!(eval::unary(op, nan).is_nan(), "{op:?}(NaN)");
    }
    assert_eq!(eval::unary(Unary::Max0, -1.0), 0.0);
    assert_eq!(eval::unary(Unary::Max0, 2.5), 2.5);
    assert!(same(eval::unary(Unary::Max0, -0.0), 0.0));
    assert_eq!(eval::unary(Unary::Step, 0.0), 0.0);
    assert_eq!(eval::unary(Unary::Step, 1e-300), 1.0);
    assert_eq!(eval::unary(Unary::Sign, 0.0), 0.0);
    assert_eq!(eval::unary(Unary::Sign, -3.0), -1.0);
}

#[test]
fn functions_are_the_standard_library_ones() {
    type Case = (Unary, fn(f64) -> f64);
    let cases: [Case; 11] = [
        (Unary::Sin, f64::sin),
        (Unary::Cos, f64::cos),
        (Unary::Tan, f64::tan),
        (Unary::Asin, f64::asin),
        (Unary::Acos, f64::acos),
        (Unary::Atan, f64::atan),
        (Unary::Exp, f64::exp),
        (Unary::Expm1, f64::exp_m1),
        (Unary::Ln, f64::ln),
        (Unary::Ln1p, f64::ln_1p),
        (Unary::Tanh, f64::tanh),
    ];
    for (op, f) in cases {
        for x in [-0.9, -0.1, 0.0, 0.4, 0.99] {
            assert!(same(eval::unary(op, x), f(x)), "{op:?}({x})");
        }
    }
    assert!(same(
        eval::binary(Binary::Atan2, -1.0, -2.0),
        (-1f64).atan2(-2.0)
    ));
    assert!(same(eval::binary(Binary::Hypot, 3.0, 4.0), 5.0));
}

#[test]
fn sums_and_products_run_left_to_right_in_operand_order() {
    let g = Graph::new();
    let (x, y, z) = (g.var("x"), g.var("y"), g.var("z"));
    let (s, p) = (x + y + z, x * y * z);
    let vals = [1e16, 1.0, -1e16];
    let out = Tape::new(&g, &[s.id(), p.id()]).eval(&vals);
    let fold = |id, f: fn(f64, f64) -> f64| match g.node(id) {
        Node::Add(xs) | Node::Mul(xs) => {
            let v = |k: usize| match g.node(xs[k]) {
                Node::Sym(s) => vals[s.index()],
                _ => unreachable!(),
            };
            (1..xs.len()).fold(v(0), |acc, k| f(acc, v(k)))
        }
        _ => unreachable!(),
    };
    assert!(same(out[0], fold(s.id(), |a, b| a + b)));
    assert!(same(out[1], fold(p.id(), |a, b| a * b)));
}

#[test]
fn tape_evaluates_a_pendulum_lagrangian() {
    let g = Graph::new();
    let (th, w) = (g.var("theta"), g.var("thetadot"));
    let (m, l, gr) = (g.param("m"), g.param("l"), g.param("g"));
    let lag = 0.5 * m * (l * w).square() + m * gr * l * th.cos();
    let dl = lag.diff(th);
    let tape = Tape::new(&g, &[lag.id(), dl.id()]);
    assert_eq!(tape.n_roots(), 2);
    let mut vals = vec![0.0; tape.n_syms()];
    let (tv, wv, mv, lv, gv) = (0.3, -1.2, 2.0, 0.5, 9.81);
    for (s, info) in g.symbols() {
        vals[s.index()] = match info.name.as_str() {
            "theta" => tv,
            "thetadot" => wv,
            "m" => mv,
            "l" => lv,
            _ => gv,
        };
    }
    let mut scratch = Vec::new();
    let mut out = [0.0; 2];
    tape.eval_into(&vals, &mut scratch, &mut out);
    let want = [
        0.5 * mv * (lv * wv).powi(2) + mv * gv * lv * tv.cos(),
        -mv * gv * lv * tv.sin(),
    ];
    for (o, w) in out.iter().zip(want) {
        assert!((o - w).abs() <= 1e-14 * w.abs(), "{o} vs {w}");
    }
    // A reused scratch buffer gives the same bits.
    let mut again = [0.0; 2];
    tape.eval_into(&vals, &mut scratch, &mut again);
    assert_eq!(out.map(f64::to_bits), again.map(f64::to_bits));
    assert!(same(eval::eval(&g, lag.id(), |s| vals[s.index()]), out[0]));
}

#[test]
fn tape_holds_only_reachable_nodes() {
    let g = Graph::new();
    let (x, y) = (g.var("x"), g.var("y"));
    let _unrelated = (y.exp() + y.cos()) * 3.0;
    let e = x.sin() + x; // x, sin(x), sum
    let tape = Tape::new(&g, &[e.id()]);
    assert_eq!(tape.len(), 3);
    assert!(same(tape.eval(&[0.7, f64::NAN])[0], 0.7f64.sin() + 0.7));
}
