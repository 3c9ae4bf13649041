//! Random expression trees for the property tests, with a naive reference
//! evaluator that does not use the crate (no simplifier, no `eval` module).
//!
//! A [`Tree`] is a plain recursive value; [`build`] turns it into a DAG
//! through the simplifying constructors, [`reference`] evaluates it directly
//! with `f64` methods and a first-order running error bound.

#![allow(dead_code)] // each test binary uses a different part

use pegdyn_equations::graph::Unary;
use pegdyn_equations::{Expr, Graph};
use proptest::prelude::*;

/// Names of the leaves: state variables, then parameters, then time.
pub const VARS: [&str; 3] = ["x", "y", "z"];
pub const PARAMS: [&str; 2] = ["a", "b"];

/// All one-argument functions of the crate.
pub const UNARY: [Unary; 15] = [
    Unary::Sin,
    Unary::Cos,
    Unary::Tan,
    Unary::Asin,
    Unary::Acos,
    Unary::Atan,
    Unary::Exp,
    Unary::Expm1,
    Unary::Ln,
    Unary::Ln1p,
    Unary::Abs,
    Unary::Sign,
    Unary::Tanh,
    Unary::Max0,
    Unary::Step,
];

/// Stops compiling when a node kind is added to the crate, as a reminder
/// to add it to [`UNARY`] or to [`Tree`].
#[allow(clippy::match_single_binding)]
pub fn covers_every_kind(u: Unary, b: pegdyn_equations::graph::Binary) {
    use pegdyn_equations::graph::Binary as B;
    match u {
        Unary::Sin | Unary::Cos | Unary::Tan | Unary::Asin | Unary::Acos | Unary::Atan => {}
        Unary::Exp | Unary::Expm1 | Unary::Ln | Unary::Ln1p | Unary::Abs | Unary::Sign => {}
        Unary::Tanh | Unary::Max0 | Unary::Step => {}
    }
    match b {
        B::Atan2 | B::Hypot => {}
    }
}

/// An unsimplified expression.
#[derive(Clone, Debug)]
pub enum Tree {
    Const(f64),
    Var(usize),
    Param(usize),
    Time,
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    Div(Box<Tree>, Box<Tree>),
    Neg(Box<Tree>),
    Powi(Box<Tree>, i32),
    Powf(Box<Tree>, f64),
    Sqrt(Box<Tree>),
    /// `x ^ y` with a non-constant exponent.
    Pow(Box<Tree>, Box<Tree>),
    Un(Unary, Box<Tree>),
    Atan2(Box<Tree>, Box<Tree>),
    Hypot(Box<Tree>, Box<Tree>),
}

use Tree::*;

fn leaf() -> impl Strategy<Value = Tree> {
    prop_oneof![
        2 => prop::sample::select(vec![0.0, 1.0, -1.0, 2.0, 0.5, 3.0]).prop_map(Const),
        1 => (-3.0..3.0f64).prop_map(Const),
        5 => (0..VARS.len()).prop_map(Var),
        2 => (0..PARAMS.len()).prop_map(Param),
        1 => Just(Time),
    ]
}

/// Random trees over every node kind, with extra weight on the shapes the
/// simplifier has laws for (repeated subtrees, sin²+cos², 1 − cos, squares
/// under roots, negated arguments).
pub fn tree() -> impl Strategy<Value = Tree> {
    leaf().prop_recursive(5, 48, 2, |inner| {
        let b = |t: Tree| Box::new(t);
        let pair = (inner.clone(), inner.clone());
        prop_oneof![
            3 => pair.clone().prop_map(move |(x, y)| Add(b(x), b(y))),
            2 => pair.clone().prop_map(move |(x, y)| Sub(b(x), b(y))),
            3 => pair.clone().prop_map(move |(x, y)| Mul(b(x), b(y))),
            2 => pair.clone().prop_map(move |(x, y)| Div(b(x), b(y))),
            1 => inner.clone().prop_map(move |x| Neg(b(x))),
            2 => (inner.clone(), -3..=4i32).prop_map(move |(x, n)| Powi(b(x), n)),
            1 => (inner.clone(), prop::sample::select(vec![0.5, -0.5, 1.5, -1.5, 2.5, 1.0 / 3.0, 2.0]))
                .prop_map(move |(x, p)| Powf(b(x), p)),
            1 => inner.clone().prop_map(move |x| Sqrt(b(x))),
            1 => pair.clone().prop_map(move |(x, y)| Pow(b(x), b(y))),
            6 => (prop::sample::select(UNARY.to_vec()), inner.clone()).prop_map(move |(f, x)| Un(f, b(x))),
            1 => pair.clone().prop_map(move |(y, x)| Atan2(b(y), b(x))),
            1 => pair.clone().prop_map(move |(x, y)| Hypot(b(x), b(y))),
            // Law-shaped compounds.
            1 => inner.clone().prop_map(move |x| Sub(b(x.clone()), b(x))),
            1 => inner.clone().prop_map(move |x| Div(b(x.clone()), b(x))),
            1 => (inner.clone(), inner.clone()).prop_map(move |(x, c)| Add(
                b(Mul(b(c.clone()), b(Powi(b(Un(Unary::Sin, b(x.clone()))), 2)))),
                b(Mul(b(c), b(Powi(b(Un(Unary::Cos, b(x))), 2)))),
            )),
            1 => (inner.clone(), inner.clone()).prop_map(move |(x, c)| Sub(
                b(c.clone()),
                b(Mul(b(c), b(Un(Unary::Cos, b(x))))),
            )),
            1 => (inner.clone(), inner.clone()).prop_map(move |(x, c)| Sub(
                b(c.clone()),
                b(Mul(b(c), b(Powi(b(Un(Unary::Cos, b(x))), 2)))),
            )),
            1 => (inner.clone(), inner.clone(), inner.clone(), any::<bool>()).prop_map(move |(x, y, c, minus)| {
                let cc = Mul(b(Un(Unary::Cos, b(x.clone()))), b(Un(Unary::Cos, b(y.clone()))));
                let ss = Mul(b(Un(Unary::Sin, b(x))), b(Un(Unary::Sin, b(y))));
                let (l, r) = (Mul(b(c.clone()), b(cc)), Mul(b(c), b(ss)));
                if minus { Sub(b(l), b(r)) } else { Add(b(l), b(r)) }
            }),
            1 => (inner.clone(), inner.clone(), inner.clone(), any::<bool>()).prop_map(move |(x, y, c, minus)| {
                let sc = Mul(b(Un(Unary::Sin, b(x.clone()))), b(Un(Unary::Cos, b(y.clone()))));
                let cs = Mul(b(Un(Unary::Cos, b(x))), b(Un(Unary::Sin, b(y))));
                let (l, r) = (Mul(b(c.clone()), b(sc)), Mul(b(c), b(cs)));
                if minus { Sub(b(l), b(r)) } else { Add(b(l), b(r)) }
            }),
            1 => inner.clone().prop_map(move |x| Sqrt(b(Powi(b(x), 2)))),
            1 => (prop::sample::select(UNARY.to_vec()), inner.clone())
                .prop_map(move |(f, x)| Un(f, b(Neg(b(x))))),
            1 => pair.prop_map(move |(x, y)| Mul(b(Add(b(x.clone()), b(y.clone()))), b(Sub(b(y), b(x))))),
        ]
    })
}

/// The tree built through the simplifying constructors of `g`.
pub fn build<'g>(g: &'g Graph, t: &Tree) -> Expr<'g> {
    match t {
        Const(c) => g.constant(*c),
        Var(i) => g.var(VARS[*i]),
        Param(i) => g.param(PARAMS[*i]),
        Time => g.time(),
        Add(x, y) => build(g, x) + build(g, y),
        Sub(x, y) => build(g, x) - build(g, y),
        Mul(x, y) => build(g, x) * build(g, y),
        Div(x, y) => build(g, x) / build(g, y),
        Neg(x) => -build(g, x),
        Powi(x, n) => build(g, x).powi(*n),
        Powf(x, p) => build(g, x).powf(*p),
        Sqrt(x) => build(g, x).sqrt(),
        Pow(x, y) => build(g, x).pow(build(g, y)),
        Un(f, x) => build(g, x).apply(*f),
        Atan2(y, x) => build(g, y).atan2(build(g, x)),
        Hypot(x, y) => build(g, x).hypot(build(g, y)),
    }
}

/// Values of the leaves: `vars[i]`, `params[i]`, `t`.
#[derive(Clone, Copy, Debug)]
pub struct Point {
    pub vars: [f64; 3],
    pub params: [f64; 2],
    pub t: f64,
}

impl Point {
    /// The point as the interpreter wants it: values by symbol index of `g`.
    pub fn by_symbol(&self, g: &Graph) -> Vec<f64> {
        g.symbols()
            .into_iter()
            .map(|(_, info)| {
                if let Some(i) = VARS.iter().position(|&n| n == info.name) {
                    self.vars[i]
                } else if let Some(i) = PARAMS.iter().position(|&n| n == info.name) {
                    self.params[i]
                } else {
                    self.t
                }
            })
            .collect()
    }
}

pub fn point() -> impl Strategy<Value = Point> {
    let v = -2.5..2.5f64;
    ([v.clone(), v.clone(), v.clone()], [v.clone(), v.clone()], v)
        .prop_map(|(vars, params, t)| Point { vars, params, t })
}

const U: f64 = f64::EPSILON / 2.0;

/// Value of `t` at `p`, computed naively, and a first-order bound on its
/// rounding error (absolute). The bound is infinite where the value is
/// unstable: a jump (sign, step) or a branch cut (atan2) within the error of
/// its argument.
pub fn reference(t: &Tree, p: &Point) -> (f64, f64) {
    let r = |x: &Tree| reference(x, p);
    match t {
        Const(c) => (*c, 0.0),
        Var(i) => (p.vars[*i], 0.0),
        Param(i) => (p.params[*i], 0.0),
        Time => (p.t, 0.0),
        Add(x, y) | Sub(x, y) => {
            let ((a, ea), (b, eb)) = (r(x), r(y));
            let v = if matches!(t, Add(..)) { a + b } else { a - b };
            (v, ea + eb + U * v.abs())
        }
        Mul(x, y) => {
            let ((a, ea), (b, eb)) = (r(x), r(y));
            let v = a * b;
            (v, b.abs() * ea + a.abs() * eb + U * v.abs())
        }
        Div(x, y) => {
            let ((a, ea), (b, eb)) = (r(x), r(y));
            let v = a / b;
            (v, (ea + v.abs() * eb) / b.abs() + U * v.abs())
        }
        Neg(x) => {
            let (a, ea) = r(x);
            (-a, ea)
        }
        Powi(x, n) => {
            let (a, ea) = r(x);
            let v = a.powi(*n);
            let d = f64::from(*n) * a.powi(n - 1);
            (v, d.abs() * ea + 4.0 * U * v.abs())
        }
        Powf(x, q) => {
            let (a, ea) = r(x);
            let v = a.powf(*q);
            (v, (q * a.powf(q - 1.0)).abs() * ea + 2.0 * U * v.abs())
        }
        Sqrt(x) => {
            let (a, ea) = r(x);
            let v = a.sqrt();
            (v, ea / (2.0 * v) + U * v)
        }
        Pow(x, y) => {
            let ((a, ea), (q, eq)) = (r(x), r(y));
            let v = a.powf(q);
            let e = (q * a.powf(q - 1.0)).abs() * ea + (v * a.ln()).abs() * eq + 2.0 * U * v.abs();
            (v, e)
        }
        Un(f, x) => {
            let (a, ea) = r(x);
            let (v, d) = unary(*f, a);
            let jump = matches!(f, Unary::Sign | Unary::Step) && a.abs() <= ea;
            // Lipschitz constant 1 for the kinks, whose derivative jumps.
            let lip = if matches!(f, Unary::Abs | Unary::Max0) {
                1.0
            } else {
                d.abs()
            };
            let e = if jump {
                f64::INFINITY
            } else {
                lip * ea + 2.0 * U * v.abs()
            };
            (v, e)
        }
        Atan2(y, x) => {
            let ((b, eb), (a, ea)) = (r(y), r(x));
            let v = b.atan2(a);
            let cut = a < 0.0 && b.abs() <= eb;
            let e = (a.abs() * eb + b.abs() * ea) / (a * a + b * b) + 2.0 * U * v.abs();
            (v, if cut { f64::INFINITY } else { e })
        }
        Hypot(x, y) => {
            let ((a, ea), (b, eb)) = (r(x), r(y));
            let v = a.hypot(b);
            (v, (a.abs() * ea + b.abs() * eb) / v + U * v)
        }
    }
}

/// `f(a)` and `f'(a)`, from the standard library's definitions.
pub fn unary(f: Unary, a: f64) -> (f64, f64) {
    match f {
        Unary::Sin => (a.sin(), a.cos()),
        Unary::Cos => (a.cos(), -a.sin()),
        Unary::Tan => (a.tan(), 1.0 / (a.cos() * a.cos())),
        Unary::Asin => (a.asin(), 1.0 / (1.0 - a * a).sqrt()),
        Unary::Acos => (a.acos(), -1.0 / (1.0 - a * a).sqrt()),
        Unary::Atan => (a.atan(), 1.0 / (1.0 + a * a)),
        Unary::Exp => (a.exp(), a.exp()),
        Unary::Expm1 => (a.exp_m1(), a.exp()),
        Unary::Ln => (a.ln(), 1.0 / a),
        Unary::Ln1p => (a.ln_1p(), 1.0 / (1.0 + a)),
        Unary::Abs => (a.abs(), if a > 0.0 { 1.0 } else { -1.0 }),
        Unary::Sign => (
            if a.is_nan() {
                a
            } else if a > 0.0 {
                1.0
            } else if a < 0.0 {
                -1.0
            } else {
                0.0
            },
            0.0,
        ),
        Unary::Tanh => (a.tanh(), 1.0 - a.tanh() * a.tanh()),
        Unary::Max0 => (
            if a.is_nan() || a > 0.0 { a } else { 0.0 },
            if a > 0.0 { 1.0 } else { 0.0 },
        ),
        Unary::Step => (
            if a.is_nan() {
                a
            } else if a > 0.0 {
                1.0
            } else {
                0.0
            },
            0.0,
        ),
    }
}
