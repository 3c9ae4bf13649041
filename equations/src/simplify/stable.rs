//! Stable numerical forms: rewrites that keep the value and remove a
//! cancellation, an overflow or a NaN from the *floating-point* evaluation.
//! Each is a row of [`super::rules::RULES`] with `stable: true` (so that
//! `Graph::with_stable_rewrites(false)` can switch it off to measure what it
//! buys); each is shown by a hard case in `tests/generator/hard_cases_rewrites.rs`.

use super::laws::{find_pair, find_term, remove, sum_measure, without};
use super::{add, all_params, const_of, konst, mul, pow, term_parts, unary};
use crate::graph::{Binary, Const, Graph, Id, Node, Unary};

/// The position of a factor `cos(u)` in `fs`, and `u`.
fn cos_factor(g: &Graph, fs: &[Id]) -> Option<(usize, Id)> {
    fs.iter().enumerate().find_map(|(k, &f)| match g.node(f) {
        Node::Unary(Unary::Cos, u) => Some((k, u)),
        _ => None,
    })
}

/// The numbers of factors of the parameter products in a cofactor `b` of
/// `cos(u)`: `[n]` when `b` is a product of `n` parameters, the lengths of
/// the parameter-product terms when `b` is one sum, else none.
fn param_shapes(g: &Graph, b: &[Id]) -> Vec<usize> {
    if all_params(g, b) {
        return vec![b.len()];
    }
    match b {
        [s] => match g.node(*s) {
            Node::Add(xs) => xs
                .iter()
                .map(|&t| term_parts(g, t).1)
                .filter(|fs| all_params(g, fs))
                .map(|fs| fs.len())
                .collect(),
            _ => Vec::new(),
        },
        _ => Vec::new(),
    }
}

/// `a − b·cos(u) → (a − b) + 2b·sin²(u/2)` in a sum that holds a term
/// `c·B·cos(u)` and a term `A` without `cos(u)` where `A` and `B` (or a
/// term of `B` when `B` is a sum) are products of as many parameters (so
/// `a` and `b` are alike: two lengths, say `r` and `D/2`). Every `cos(u)`
/// term of the sum is rewritten with `cos u = 1 − 2 sin²(u/2)`, so that
/// `a − b` is formed from the inputs (exactly, when they are close, and
/// symbolically cancelled terms vanish) instead of after multiplying by a
/// rounded `cos u`.
pub(super) fn cos_near_equal(g: &Graph, terms: &[Id]) -> Option<Vec<Id>> {
    if terms.len() < 2 {
        return None;
    }
    let parts: Vec<(f64, Vec<Id>)> = terms.iter().map(|&t| term_parts(g, t)).collect();
    let u = parts.iter().find_map(|(_, fs)| {
        let (k, u) = cos_factor(g, fs)?;
        let shapes = param_shapes(g, &remove(fs, k));
        let partner = parts
            .iter()
            .any(|(_, a)| shapes.contains(&a.len()) && all_params(g, a));
        partner.then_some(u)
    })?;
    let cos_u = g.find(&Node::Unary(Unary::Cos, u))?;
    let half = mul(g, &[konst(g, 0.5), u]);
    let sin2 = pow(g, unary(g, Unary::Sin, half), konst(g, 2.0));
    let mut next = Vec::with_capacity(terms.len() + 2);
    for ((c, fs), &t) in parts.iter().zip(terms) {
        match fs.iter().position(|&f| f == cos_u) {
            Some(k) => {
                // c·F·cos u = c·F − 2c·F·sin²(u/2)
                let mut f = remove(fs, k);
                f.push(konst(g, *c));
                next.push(mul(g, &f));
                f.push(konst(g, -2.0));
                f.push(sin2);
                next.push(mul(g, &f));
            }
            None => next.push(t),
        }
    }
    // A cofactor that itself holds cos(u) would keep the count: no rewrite.
    let fewer = sum_measure(g, &next) < sum_measure(g, terms);
    fewer.then_some(next)
}

/// `c·F·exp(u) − c·F → c·F·exp_m1(u)` (`F` may be 1).
pub(super) fn exp_minus_one(g: &Graph, terms: &[Id]) -> Option<Vec<Id>> {
    if terms.len() < 2 {
        return None;
    }
    let is_exp = |n: &Node| matches!(n, Node::Unary(Unary::Exp, _));
    let partner = |c: f64, fs: &[Id], k: usize| find_term(g, -c, &remove(fs, k));
    let (i, j, c, fs, k) = find_pair(g, terms, is_exp, partner)?;
    let Node::Unary(_, u) = g.node(fs[k]) else {
        return None;
    };
    let mut f = remove(&fs, k);
    f.push(unary(g, Unary::Expm1, u));
    f.push(konst(g, c));
    let mut next = without(terms, i, j);
    next.push(mul(g, &f));
    Some(next)
}

/// `ln(1 + x) → ln_1p(x)`.
pub(super) fn ln_one_plus(g: &Graph, _op: Unary, x: Id) -> Option<Id> {
    let Node::Add(xs) = g.node(x) else {
        return None;
    };
    let one = g.find(&Node::Const(Const::new(1.0)?))?;
    let k = xs.iter().position(|&t| t == one)?;
    Some(unary(g, Unary::Ln1p, add(g, &remove(&xs, k))))
}

/// `(x₁² + … + xₙ²)^e → hypot(…hypot(x₁, x₂)…, xₙ)^(2e)` for a
/// non-integer constant `e` (square roots and their powers).
pub(super) fn hypot_of_squares(g: &Graph, base: Id, e: Id) -> Option<Id> {
    let ev = const_of(g, e)?;
    if ev.fract() == 0.0 {
        return None;
    }
    let Node::Add(xs) = g.node(base) else {
        return None;
    };
    let mut roots = Vec::with_capacity(xs.len());
    for &t in xs.iter() {
        let Node::Pow(x, two) = g.node(t) else {
            return None;
        };
        if const_of(g, two) != Some(2.0) {
            return None;
        }
        roots.push(x);
    }
    let h = roots[1..]
        .iter()
        .fold(roots[0], |acc, &x| super::binary(g, Binary::Hypot, acc, x));
    Some(pow(g, h, konst(g, 2.0 * ev)))
}

/// True when `id` is never negative: `|x|`, `hypot`, `exp`, an even power,
/// a square root.
fn non_negative(g: &Graph, id: Id) -> bool {
    match g.node(id) {
        Node::Unary(Unary::Abs | Unary::Exp, _) | Node::Binary(Binary::Hypot, ..) => true,
        Node::Pow(_, e) => const_of(g, e).is_some_and(|v| v == 0.5 || v % 2.0 == 0.0),
        _ => false,
    }
}

/// `atan(n / d) → atan2(n, d)` for a denominator `d` that is never
/// negative (then both are the same angle in (−π/2, π/2); for a `d` of
/// unknown sign they differ by π, so the rule does not apply).
pub(super) fn atan_of_ratio(g: &Graph, _op: Unary, x: Id) -> Option<Id> {
    let (c, fs) = term_parts(g, x);
    let k = fs.iter().position(|&f| match g.node(f) {
        Node::Pow(d, e) => const_of(g, e) == Some(-1.0) && non_negative(g, d),
        _ => false,
    })?;
    let Node::Pow(d, _) = g.node(fs[k]) else {
        return None;
    };
    let mut num = remove(&fs, k);
    num.push(konst(g, c));
    Some(super::binary(g, Binary::Atan2, mul(g, &num), d))
}
