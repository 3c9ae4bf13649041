//! Simplification at construction.
//!
//! Every [`Expr`](crate::Expr) operator calls one of the constructors here,
//! which canonicalize and simplify before interning. The constructors do the
//! bookkeeping every computer-algebra system does (constant folding, the 0
//! and 1 identities, flattening and id ordering of sums and products,
//! collecting like terms into coefficients and like factors into powers);
//! every other law is a row of the table [`rules::RULES`], which also lists
//! the constructor laws with their domains so that one table documents all
//! rewrites.
//!
//! ```
//! use pegdyn_equations::Graph;
//! let g = Graph::new();
//! let (x, y) = (g.var("x"), g.var("y"));
//! assert_eq!(x + x, 2.0 * x);
//! assert_eq!((x - y) - (x - y), g.constant(0.0));
//! assert_eq!(x.sin().square() + x.cos().square(), g.constant(1.0));
//! assert_eq!((1.0 - x.cos()).to_string(), "2*sin(x/2)^2");
//! assert_eq!(x.square().sqrt(), x.abs()); // never x
//! ```
//!
//! A law may turn an undefined value (NaN, a division by zero) into a defined
//! one (`x/x → 1` at `x = 0`), but never changes a value where the input
//! expression is defined and finite.

mod laws;
pub mod rules;
mod stable;
mod trig;

use std::collections::BTreeMap;

use crate::graph::{Binary, Const, Graph, Id, Node, PowForm, Unary};

pub(crate) fn konst(g: &Graph, v: f64) -> Id {
    g.intern(Node::Const(Const::new(v).expect("NaN constant")))
}

pub(crate) fn const_of(g: &Graph, id: Id) -> Option<f64> {
    g.with_node(id, |n| match n {
        Node::Const(c) => Some(c.value()),
        _ => None,
    })
}

/// Splits a term into `(coefficient, rest)`: `3·x·y → (3, x·y)`, `x → (1, x)`.
pub(crate) fn split_coeff(g: &Graph, id: Id) -> (f64, Id) {
    enum Split {
        Plain,
        One(f64, Id),
        Many(f64, Box<[Id]>),
    }
    let split = g.with_node(id, |n| match n {
        Node::Mul(fs) => match const_of(g, fs[0]) {
            Some(c) if fs.len() == 2 => Split::One(c, fs[1]),
            Some(c) => Split::Many(c, fs[1..].into()),
            None => Split::Plain,
        },
        _ => Split::Plain,
    });
    match split {
        Split::Plain => (1.0, id),
        Split::One(c, b) => (c, b),
        Split::Many(c, rest) => (c, g.intern(Node::Mul(rest))),
    }
}

/// Splits a term into its coefficient and its non-constant factors, without
/// interning anything: `3·x·y → (3, [x, y])`, `x → (1, [x])`, `5 → (5, [])`.
/// The factors are in canonical (id) order.
pub(crate) fn term_parts(g: &Graph, id: Id) -> (f64, Vec<Id>) {
    g.with_node(id, |n| match n {
        Node::Const(c) => (c.value(), Vec::new()),
        Node::Mul(fs) => match g.with_node(fs[0], |f| match f {
            Node::Const(c) => Some(c.value()),
            _ => None,
        }) {
            Some(c) => (c, fs[1..].to_vec()),
            None => (1.0, fs.to_vec()),
        },
        _ => (1.0, vec![id]),
    })
}

/// True when `id` is a parameter symbol.
pub(crate) fn is_param(g: &Graph, id: Id) -> bool {
    g.with_node(id, |n| match n {
        Node::Sym(s) => g.sym_info(*s).kind == crate::graph::SymKind::Param,
        _ => false,
    })
}

/// True when `fs` is not empty and every factor in it is a parameter symbol.
pub(crate) fn all_params(g: &Graph, fs: &[Id]) -> bool {
    !fs.is_empty() && fs.iter().all(|&f| is_param(g, f))
}

/// `c · base` for a base that is not a constant, in canonical form.
pub(crate) fn scale(g: &Graph, c: f64, base: Id) -> Id {
    if c == 0.0 {
        return konst(g, 0.0);
    }
    if c == 1.0 {
        return base;
    }
    let mut fs = vec![konst(g, c)];
    flatten_into(g, base, false, &mut fs);
    g.intern(Node::Mul(fs.into()))
}

/// Pushes the operands of `id` onto `out` if it is a sum (`sum`) or a
/// product (`!sum`), else `id` itself. Reads the node in place.
fn flatten_into(g: &Graph, id: Id, sum: bool, out: &mut Vec<Id>) {
    g.with_node(id, |n| match n {
        Node::Add(xs) if sum => out.extend_from_slice(xs),
        Node::Mul(xs) if !sum => out.extend_from_slice(xs),
        _ => out.push(id),
    })
}

/// The sum of `terms`.
pub fn add(g: &Graph, terms: &[Id]) -> Id {
    let mut flat = Vec::with_capacity(terms.len());
    for &t in terms {
        flatten_into(g, t, true, &mut flat);
    }
    let mut c0 = 0.0;
    let mut coeffs: BTreeMap<Id, f64> = BTreeMap::new();
    for t in flat {
        if let Some(v) = const_of(g, t) {
            c0 += v;
            continue;
        }
        let (c, base) = split_coeff(g, t);
        *coeffs.entry(base).or_insert(0.0) += c;
    }
    let mut out: Vec<Id> = coeffs
        .into_iter()
        .filter(|&(_, c)| c != 0.0)
        .map(|(b, c)| scale(g, c, b))
        .collect();
    if c0 != 0.0 || c0.is_nan() {
        out.push(konst(g, c0));
    }
    if let Some(next) = rules::rewrite_sum(g, &out) {
        return add(g, &next);
    }
    finish_sum(g, out)
}

/// Interns an already simplified list of sum terms.
pub(crate) fn finish_sum(g: &Graph, mut out: Vec<Id>) -> Id {
    out.sort_unstable();
    match out.len() {
        0 => konst(g, 0.0),
        1 => out[0],
        _ => g.intern(Node::Add(out.into())),
    }
}

/// `a − b`.
pub fn sub(g: &Graph, a: Id, b: Id) -> Id {
    let nb = neg(g, b);
    add(g, &[a, nb])
}

/// `−a`.
pub fn neg(g: &Graph, a: Id) -> Id {
    mul(g, &[konst(g, -1.0), a])
}

/// `a / b`.
pub fn div(g: &Graph, a: Id, b: Id) -> Id {
    let inv = pow(g, b, konst(g, -1.0));
    mul(g, &[a, inv])
}

/// Splits a factor into `(base, constant exponent)`: `x^3 → (x, 3)`.
fn split_pow(g: &Graph, id: Id) -> (Id, f64) {
    match g.node(id) {
        Node::Pow(b, e) => match const_of(g, e) {
            Some(v) => (b, v),
            None => (id, 1.0),
        },
        _ => (id, 1.0),
    }
}

/// The product of `factors`.
pub fn mul(g: &Graph, factors: &[Id]) -> Id {
    let mut flat = Vec::with_capacity(factors.len());
    for &f in factors {
        flatten_into(g, f, false, &mut flat);
    }
    let mut c = 1.0;
    let mut exps: BTreeMap<Id, f64> = BTreeMap::new();
    for f in flat {
        if let Some(v) = const_of(g, f) {
            c *= v;
            continue;
        }
        let (b, e) = split_pow(g, f);
        *exps.entry(b).or_insert(0.0) += e;
    }
    if c == 0.0 {
        return konst(g, 0.0);
    }
    let mut out = Vec::with_capacity(exps.len() + 1);
    let mut nested = false;
    for (b, e) in exps {
        if e == 0.0 {
            continue;
        }
        let f = if e == 1.0 { b } else { pow(g, b, konst(g, e)) };
        // A power may fold to a constant, or to a product (x^a·x^b with a
        // product x), whose factors must be collected again.
        match const_of(g, f) {
            Some(v) => c *= v,
            None => {
                nested |= g.with_node(f, |n| matches!(n, Node::Mul(_)));
                out.push(f);
            }
        }
    }
    if c == 0.0 {
        return konst(g, 0.0);
    }
    if !nested {
        // A power may also rewrite to a power of another base (|x|^2 → x^2)
        // that collides with a factor collected separately (x^2): collect
        // again. Terminates: merging two factors leaves strictly fewer.
        let mut bases: Vec<Id> = out.iter().map(|&f| split_pow(g, f).0).collect();
        bases.sort_unstable();
        nested = bases.windows(2).any(|w| w[0] == w[1]);
    }
    if nested {
        // Terminates: the nested products are factors of strictly smaller
        // expressions (a power's base), so this recursion descends.
        out.push(konst(g, c));
        return mul(g, &out);
    }
    out.sort_unstable();
    if let Some(r) = rules::rewrite_product(g, c, &out) {
        return r;
    }
    match (out.len(), c == 1.0) {
        (0, _) => konst(g, c),
        (1, true) => out[0],
        (_, true) => g.intern(Node::Mul(out.into())),
        (_, false) => {
            out.insert(0, konst(g, c));
            g.intern(Node::Mul(out.into()))
        }
    }
}

/// `base ^ exponent`.
pub fn pow(g: &Graph, base: Id, exponent: Id) -> Id {
    let eb = const_of(g, base);
    let ee = const_of(g, exponent);
    if let (Some(b), Some(e)) = (eb, ee) {
        let v = PowForm::of(Some(e)).eval(b, e);
        if v.is_finite() {
            return konst(g, v);
        }
    }
    match ee {
        Some(0.0) => return konst(g, 1.0),
        Some(1.0) => return base,
        _ => {}
    }
    if eb == Some(1.0) {
        return konst(g, 1.0);
    }
    rules::rewrite_pow(g, base, exponent).unwrap_or_else(|| g.intern(Node::Pow(base, exponent)))
}

/// A one-argument function.
pub fn unary(g: &Graph, op: Unary, x: Id) -> Id {
    if let Some(v) = const_of(g, x) {
        let r = (op.spec().eval)(v);
        if r.is_finite() {
            return konst(g, r);
        }
    }
    rules::rewrite_unary(g, op, x).unwrap_or_else(|| g.intern(Node::Unary(op, x)))
}

/// A two-argument function other than `pow`.
pub fn binary(g: &Graph, op: Binary, a: Id, b: Id) -> Id {
    if let (Some(x), Some(y)) = (const_of(g, a), const_of(g, b)) {
        let r = (op.spec().eval)(x, y);
        if r.is_finite() {
            return konst(g, r);
        }
    }
    rules::rewrite_binary(g, op, a, b).unwrap_or_else(|| g.intern(Node::Binary(op, a, b)))
}

/// True when `id` is "negative" in the canonical sense the odd/even rules
/// use: a product with a negative coefficient, or a sum whose term with the
/// smallest factor list has a negative coefficient. Exactly one of `u` and
/// `−u` is negative for every non-constant `u` that is a sum or a product
/// with a coefficient, so rewriting `f(−u)` to `±f(u)` cannot loop.
pub(crate) fn is_negative(g: &Graph, id: Id) -> bool {
    match g.node(id) {
        Node::Mul(_) => term_parts(g, id).0 < 0.0,
        Node::Add(xs) => xs
            .iter()
            .map(|&t| term_parts(g, t))
            .filter(|(_, fs)| !fs.is_empty())
            .min_by(|a, b| a.1.cmp(&b.1))
            .is_some_and(|(c, _)| c < 0.0),
        _ => false,
    }
}
