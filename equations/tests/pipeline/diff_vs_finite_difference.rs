//! Symbolic derivatives against numbers: random trees over every node kind
//! against central finite differences of the raw tree, a table of known
//! derivatives against hand-written ones, and the total time derivative
//! against a finite difference along a trajectory.
//!
//! Finite differences: central differences `D(h)` at `h`, `h/2`, `h/4` with
//! `h = 1e-3·max(1, |x|)`, combined by Richardson extrapolation into two
//! estimates `R1`, `R2` of error O(h⁴). Where the two estimates disagree by
//! more than a quarter of the tolerance the function is not smooth at that
//! scale (a kink, a jump, a pole nearby) and the point is skipped and
//! counted; elsewhere the symbolic derivative must match `R2` to
//! `1e-6·max(1, |R2|)`.

use crate::common;

use common::{Point, Tree, build, point, reference, tree};
use pegdyn_equations::eval::Tape;
use pegdyn_equations::{Expr, Graph};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::cell::Cell;

/// Tolerance of a comparison with a derivative of size `d`.
fn tol(d: f64) -> f64 {
    1e-6 * d.abs().max(1.0)
}

/// The derivative of `f` at 0 by extrapolated central differences, if `f`
/// is smooth there at the scale `h`.
fn finite_difference(f: impl Fn(f64) -> f64, h: f64) -> Option<f64> {
    let d = |h: f64| (f(h) - f(-h)) / (2.0 * h);
    let (d1, d2, d3) = (d(h), d(h / 2.0), d(h / 4.0));
    let (r1, r2) = ((4.0 * d2 - d1) / 3.0, (4.0 * d3 - d2) / 3.0);
    (r1.is_finite() && r2.is_finite() && (r1 - r2).abs() <= tol(r2) / 4.0).then_some(r2)
}

/// The leaf a random derivative is taken with respect to.
fn wrt() -> impl Strategy<Value = Tree> {
    prop_oneof![
        4 => (0..3usize).prop_map(Tree::Var),
        2 => (0..2usize).prop_map(Tree::Param),
        1 => Just(Tree::Time),
    ]
}

/// `p` with the coordinate `leaf` moved by `h`, and that coordinate's value.
fn shifted(p: &Point, leaf: &Tree, h: f64) -> (Point, f64) {
    let mut q = *p;
    let c = match leaf {
        Tree::Var(i) => &mut q.vars[*i],
        Tree::Param(i) => &mut q.params[*i],
        _ => &mut q.t,
    };
    let x0 = *c;
    *c += h;
    (q, x0)
}

#[derive(Default, Debug)]
struct Tally {
    points: Cell<usize>,
    compared: Cell<usize>,
    not_smooth: Cell<usize>,
    symbolic_undefined: Cell<usize>,
}

fn bump(c: &Cell<usize>) {
    c.set(c.get() + 1);
}

#[test]
fn random_derivatives_match_finite_differences() {
    let config = Config {
        cases: 2000,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    let tally = Tally::default();
    let strategy = (tree(), wrt(), prop::collection::vec(point(), 3));
    let result = runner.run(&strategy, |(t, x, pts)| {
        let g = Graph::new();
        let d = build(&g, &t).diff(build(&g, &x));
        let tape = Tape::new(&g, &[d.id()]);
        for p in &pts {
            bump(&tally.points);
            let x0 = shifted(p, &x, 0.0).1;
            let h = 1e-3 * x0.abs().max(1.0);
            let Some(fd) = finite_difference(|s| reference(&t, &shifted(p, &x, s).0).0, h) else {
                bump(&tally.not_smooth);
                continue;
            };
            let sym = tape.eval(&p.by_symbol(&g))[0];
            if !sym.is_finite() {
                bump(&tally.symbolic_undefined);
                continue;
            }
            bump(&tally.compared);
            prop_assert!(
                (sym - fd).abs() <= tol(fd),
                "d/d{x:?} of {t:?} = {d}: {sym} vs fd {fd} at {p:?}"
            );
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    eprintln!("{tally:?}");
    let n = tally.points.get() as f64;
    assert!(
        tally.compared.get() as f64 >= 0.5 * n,
        "too few compared: {tally:?}"
    );
    assert!(
        tally.symbolic_undefined.get() as f64 <= 0.01 * n,
        "symbolic NaN where smooth: {tally:?}"
    );
}

/// One known derivative: `f`, its derivative written by hand, points.
struct Known {
    name: &'static str,
    f: for<'g> fn(Expr<'g>) -> Expr<'g>,
    df: fn(f64) -> f64,
    at: &'static [f64],
}

const KNOWN: &[Known] = &[
    Known {
        name: "sin",
        f: |x| x.sin(),
        df: f64::cos,
        at: &[-1.0, 0.3, 2.0],
    },
    Known {
        name: "cos",
        f: |x| x.cos(),
        df: |x| -x.sin(),
        at: &[-1.0, 0.3, 2.0],
    },
    Known {
        name: "tan",
        f: |x| x.tan(),
        df: |x| 1.0 / x.cos().powi(2),
        at: &[-1.0, 0.3],
    },
    Known {
        name: "asin",
        f: |x| x.asin(),
        df: |x| 1.0 / (1.0 - x * x).sqrt(),
        at: &[-0.7, 0.3],
    },
    Known {
        name: "acos",
        f: |x| x.acos(),
        df: |x| -1.0 / (1.0 - x * x).sqrt(),
        at: &[-0.7, 0.3],
    },
    Known {
        name: "atan",
        f: |x| x.atan(),
        df: |x| 1.0 / (1.0 + x * x),
        at: &[-3.0, 0.3],
    },
    Known {
        name: "exp",
        f: |x| x.exp(),
        df: f64::exp,
        at: &[-1.0, 2.0],
    },
    Known {
        name: "exp_m1",
        f: |x| x.exp_m1(),
        df: f64::exp,
        at: &[-1.0, 1e-9],
    },
    Known {
        name: "ln",
        f: |x| x.ln(),
        df: |x| 1.0 / x,
        at: &[0.5, 3.0],
    },
    Known {
        name: "ln_1p",
        f: |x| x.ln_1p(),
        df: |x| 1.0 / (1.0 + x),
        at: &[-0.5, 2.0],
    },
    Known {
        name: "abs",
        f: |x| x.abs(),
        df: |x| {
            if x > 0.0 {
                1.0
            } else if x < 0.0 {
                -1.0
            } else {
                0.0
            }
        },
        at: &[-2.0, 0.0, 3.0],
    },
    Known {
        name: "sign",
        f: |x| x.signum(),
        df: |_| 0.0,
        at: &[-2.0, 3.0],
    },
    Known {
        name: "step",
        f: |x| x.step(),
        df: |_| 0.0,
        at: &[-2.0, 3.0],
    },
    Known {
        name: "max0",
        f: |x| x.max0(),
        df: |x| if x > 0.0 { 1.0 } else { 0.0 },
        at: &[-2.0, 0.0, 3.0],
    },
    Known {
        name: "tanh",
        f: |x| x.tanh(),
        df: |x| 1.0 / x.cosh().powi(2),
        at: &[-1.0, 0.5],
    },
    Known {
        name: "cube",
        f: |x| x.powi(3),
        df: |x| 3.0 * x * x,
        at: &[-1.5, 2.0],
    },
    Known {
        name: "inverse_square",
        f: |x| x.powi(-2),
        df: |x| -2.0 / x.powi(3),
        at: &[-1.5, 2.0],
    },
    Known {
        name: "pow_2_5",
        f: |x| x.powf(2.5),
        df: |x| 2.5 * x.powf(1.5),
        at: &[0.5, 2.0],
    },
    Known {
        name: "sqrt",
        f: |x| x.sqrt(),
        df: |x| 0.5 / x.sqrt(),
        at: &[0.5, 2.0],
    },
    Known {
        name: "inv_sqrt",
        f: |x| 1.0 / x.sqrt(),
        df: |x| -0.5 * x.powf(-1.5),
        at: &[0.5, 2.0],
    },
    Known {
        name: "x_pow_x",
        f: |x| x.pow(x),
        df: |x| x.powf(x) * (x.ln() + 1.0),
        at: &[0.5, 2.0],
    },
    Known {
        name: "two_pow_x",
        f: |x| x.graph().constant(2.0).pow(x),
        df: |x| 2f64.powf(x) * 2f64.ln(),
        at: &[-1.0, 3.0],
    },
    Known {
        name: "sin_of_square",
        f: |x| x.square().sin(),
        df: |x| 2.0 * x * (x * x).cos(),
        at: &[-1.0, 0.7],
    },
    Known {
        name: "x_sin_x",
        f: |x| x * x.sin(),
        df: |x| x.sin() + x * x.cos(),
        at: &[-1.0, 0.7],
    },
    Known {
        name: "quotient",
        f: |x| x / (1.0 + x.square()),
        df: |x| (1.0 - x * x) / (1.0 + x * x).powi(2),
        at: &[-1.0, 0.7],
    },
    Known {
        name: "atan2_y",
        f: |x| x.atan2(x.graph().constant(2.0)),
        df: |x| 2.0 / (4.0 + x * x),
        at: &[-1.0, 0.7],
    },
    Known {
        name: "atan2_x",
        f: |x| x.graph().constant(1.0).atan2(x),
        df: |x| -1.0 / (1.0 + x * x),
        at: &[-1.0, 0.7],
    },
    Known {
        name: "hypot",
        f: |x| x.hypot(x.graph().constant(3.0)),
        df: |x| x / x.hypot(3.0),
        at: &[-1.0, 0.7],
    },
    Known {
        name: "sqrt_of_square",
        f: |x| x.square().sqrt(),
        df: |x| x.signum(),
        at: &[-1.0, 0.7],
    },
    Known {
        name: "one_minus_cos",
        f: |x| 1.0 - x.cos(),
        df: f64::sin,
        at: &[-1.0, 1e-3, 0.7],
    },
    Known {
        name: "exp_sin",
        f: |x| x.sin().exp(),
        df: |x| x.cos() * x.sin().exp(),
        at: &[-1.0, 0.7],
    },
];

#[test]
fn known_derivatives() {
    for k in KNOWN {
        let g = Graph::new();
        let x = g.var("x");
        let d = (k.f)(x).diff(x);
        let tape = Tape::new(&g, &[d.id()]);
        for &v in k.at {
            let got = tape.eval(&[v])[0];
            let want = (k.df)(v);
            assert!(
                (got - want).abs() <= 1e-12 * want.abs().max(1e-300),
                "d {}({v}) = {d}: {got} vs {want}",
                k.name
            );
        }
    }
}

#[test]
fn derivative_forms() {
    let g = Graph::new();
    let (x, y) = (g.var("x"), g.var("y"));
    assert_eq!(x.sin().diff(x), x.cos());
    assert_eq!((x * y).diff(x), y);
    assert_eq!(x.square().diff(x), 2.0 * x);
    assert_eq!((x.sin() * y).diff(y), x.sin());
    assert_eq!(x.max0().diff(x), x.step());
    assert_eq!(x.abs().diff(x), x.signum());
    assert_eq!(x.sin().diff(y), g.constant(0.0));
}

#[test]
fn time_derivative_forms() {
    let g = Graph::new();
    let (q, qd, qdd, t) = (g.var("q"), g.var("qd"), g.var("qdd"), g.time());
    let pairs = [(q, qd), (qd, qdd)];
    assert_eq!(q.sin().dt(&pairs), q.cos() * qd);
    assert_eq!(qd.square().dt(&pairs), 2.0 * qd * qdd);
    assert_eq!((t * q).dt(&pairs), q + t * qd);
    assert_eq!(g.param("m").dt(&pairs), g.constant(0.0));
}

/// d/dt along the trajectory x' = y, y' = z, z' = 0 (parameters fixed,
/// time advancing), for random trees: x(τ) = x0 + y0 τ + z0 τ²/2.
#[test]
fn random_time_derivatives_match_finite_differences() {
    let config = Config {
        cases: 1000,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    let (points, compared) = (Cell::new(0usize), Cell::new(0usize));
    let result = runner.run(&(tree(), point()), |(t, p)| {
        let g = Graph::new();
        let (x, y, z) = (g.var("x"), g.var("y"), g.var("z"));
        let d = build(&g, &t).dt(&[(x, y), (y, z)]);
        let along = |s: f64| {
            let mut q = p;
            let [x0, y0, z0] = p.vars;
            q.vars = [x0 + y0 * s + z0 * s * s / 2.0, y0 + z0 * s, z0];
            q.t += s;
            reference(&t, &q).0
        };
        bump(&points);
        let Some(fd) = finite_difference(along, 1e-3) else {
            return Ok(());
        };
        let sym = Tape::new(&g, &[d.id()]).eval(&p.by_symbol(&g))[0];
        if sym.is_finite() {
            bump(&compared);
            prop_assert!(
                (sym - fd).abs() <= tol(fd),
                "d/dt {t:?} = {d}: {sym} vs fd {fd} at {p:?}"
            );
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    eprintln!(
        "time derivative: {} of {} points compared",
        compared.get(),
        points.get()
    );
    assert!(
        compared.get() * 2 >= points.get(),
        "{} of {} compared",
        compared.get(),
        points.get()
    );
}
