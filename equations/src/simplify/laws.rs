//! The functions behind the rows of [`super::rules::RULES`]. Each one is
//! documented by its row (law, domain, termination); comments here explain
//! only how it finds its pattern.

use std::collections::HashMap;

use super::{
    add, const_of, is_negative, konst, mul, neg, pow, scale, split_coeff, term_parts, unary,
};
use crate::graph::{Binary, Const, Graph, Id, Node, Unary};

/// `u` when `f` is `op(u)^2`; only looks up nodes, never interns.
fn square_of(g: &Graph, f: Id, op: Unary) -> Option<Id> {
    let Node::Pow(b, e) = g.node(f) else {
        return None;
    };
    if const_of(g, e) != Some(2.0) {
        return None;
    }
    match g.node(b) {
        Node::Unary(o, u) if o == op => Some(u),
        _ => None,
    }
}

/// The terms of `terms` other than those at `i` and `j`.
pub(super) fn without(terms: &[Id], i: usize, j: usize) -> Vec<Id> {
    terms
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != i && k != j)
        .map(|(_, &t)| t)
        .collect()
}

/// True when `t` is, or has a factor, for which `pred` holds. Reads nodes
/// in place (this runs on every sum built, so it must be cheap).
fn has_factor(g: &Graph, t: Id, pred: &impl Fn(&Node) -> bool) -> bool {
    g.with_node(t, |n| match n {
        Node::Mul(fs) => fs.iter().any(|&f| g.with_node(f, pred)),
        other => pred(other),
    })
}

/// The id of the term `c·f₁·…·fₙ` (factors non-constant, in canonical
/// order) if it is stored; never interns.
pub(super) fn find_term(g: &Graph, c: f64, fs: &[Id]) -> Option<Id> {
    let k = || g.find(&Node::Const(Const::new(c)?));
    match (fs, c == 1.0) {
        ([], _) => k(),
        ([f], true) => Some(*f),
        (_, true) => g.find(&Node::Mul(fs.into())),
        (_, false) => {
            let mut v = Vec::with_capacity(fs.len() + 1);
            v.push(k()?);
            v.extend_from_slice(fs);
            g.find(&Node::Mul(v.into()))
        }
    }
}

/// Finds the first term `terms[i]` with a factor `f` (at position `k` of
/// its factors) for which `partner(c, factors, k)` names another term of
/// the sum; returns `(i, j, c, factors, k)`. Linear in the number of terms:
/// only terms with a matching factor are split, partners are looked up by
/// id.
pub(super) fn find_pair(
    g: &Graph,
    terms: &[Id],
    pred: impl Fn(&Node) -> bool,
    partner: impl Fn(f64, &[Id], usize) -> Option<Id>,
) -> Option<(usize, usize, f64, Vec<Id>, usize)> {
    let mut index: Option<std::collections::HashMap<Id, usize>> = None;
    for (i, &t) in terms.iter().enumerate() {
        if !has_factor(g, t, &pred) {
            continue;
        }
        let (c, fs) = term_parts(g, t);
        for k in 0..fs.len() {
            if !g.with_node(fs[k], &pred) {
                continue;
            }
            let Some(p) = partner(c, &fs, k) else {
                continue;
            };
            let index = index
                .get_or_insert_with(|| terms.iter().enumerate().map(|(j, &t)| (t, j)).collect());
            if let Some(&j) = index.get(&p).filter(|&&j| j != i) {
                return Some((i, j, c, fs, k));
            }
        }
    }
    None
}

/// `fs` without the element at `k`.
pub(super) fn remove(fs: &[Id], k: usize) -> Vec<Id> {
    let mut v = fs.to_vec();
    v.remove(k);
    v
}

/// `c·F·sin(u)^2 + c·F·cos(u)^2 → c·F`.
pub(super) fn pythagorean(g: &Graph, terms: &[Id]) -> Option<Vec<Id>> {
    if terms.len() < 2 {
        return None;
    }
    let two = g.find(&Node::Const(Const::new(2.0)?))?;
    let sin_square = |n: &Node| match n {
        Node::Pow(b, e) => {
            *e == two && g.with_node(*b, |b| matches!(b, Node::Unary(Unary::Sin, _)))
        }
        _ => false,
    };
    let partner = |c: f64, fs: &[Id], k: usize| {
        let u = square_of(g, fs[k], Unary::Sin)?;
        let cos_u = g.find(&Node::Unary(Unary::Cos, u))?;
        let mut p = fs.to_vec();
        p[k] = g.find(&Node::Pow(cos_u, two))?;
        p.sort_unstable();
        find_term(g, c, &p)
    };
    let (i, j, c, fs, k) = find_pair(g, terms, sin_square, partner)?;
    let mut rest = remove(&fs, k);
    rest.push(konst(g, c));
    let mut next = without(terms, i, j);
    next.push(mul(g, &rest));
    Some(next)
}

/// `c·F − c·F·cos(u)^2 → c·F·sin(u)^2`.
pub(super) fn one_minus_cos_squared(g: &Graph, terms: &[Id]) -> Option<Vec<Id>> {
    if terms.len() < 2 {
        return None;
    }
    let two = g.find(&Node::Const(Const::new(2.0)?))?;
    let cos_square = |n: &Node| match n {
        Node::Pow(b, e) => {
            *e == two && g.with_node(*b, |b| matches!(b, Node::Unary(Unary::Cos, _)))
        }
        _ => false,
    };
    let partner = |c: f64, fs: &[Id], k: usize| find_term(g, -c, &remove(fs, k));
    let (i, j, c, fs, k) = find_pair(g, terms, cos_square, partner)?;
    let u = square_of(g, fs[k], Unary::Cos)?;
    // cj·F + c·F·cos²u with cj = −c is −c·F·(1 − cos²u) = −c·F·sin²u.
    let mut fs2 = remove(&fs, k);
    fs2.push(pow(g, unary(g, Unary::Sin, u), konst(g, 2.0)));
    fs2.push(konst(g, -c));
    let mut next = without(terms, i, j);
    next.push(mul(g, &fs2));
    Some(next)
}

/// `c·F − c·F·cos(u) → 2·c·F·sin(u/2)^2`, where `F` may be 1 (then the
/// partner is the constant term).
pub(super) fn one_minus_cos(g: &Graph, terms: &[Id]) -> Option<Vec<Id>> {
    if terms.len() < 2 {
        return None;
    }
    let is_cos = |n: &Node| matches!(n, Node::Unary(Unary::Cos, _));
    let partner = |c: f64, fs: &[Id], k: usize| find_term(g, -c, &remove(fs, k));
    let (i, j, c, fs, k) = find_pair(g, terms, is_cos, partner)?;
    let Node::Unary(_, u) = g.node(fs[k]) else {
        return None;
    };
    // cj·F + c·F·cos u with cj = −c is −c·F·(1 − cos u) = −2c·F·sin²(u/2).
    let half = mul(g, &[konst(g, 0.5), u]);
    let mut fs2 = remove(&fs, k);
    fs2.push(pow(g, unary(g, Unary::Sin, half), konst(g, 2.0)));
    fs2.push(konst(g, -2.0 * c));
    let mut next = without(terms, i, j);
    next.push(mul(g, &fs2));
    Some(next)
}

/// `c·(a + b) → c·a + c·b` for a product of a constant and one sum.
pub(super) fn distribute_scalar(g: &Graph, c: f64, factors: &[Id]) -> Option<Id> {
    if c == 1.0 || factors.len() != 1 {
        return None;
    }
    let Node::Add(xs) = g.node(factors[0]) else {
        return None;
    };
    let k = konst(g, c);
    let scaled: Vec<Id> = xs.iter().map(|&t| mul(g, &[k, t])).collect();
    Some(add(g, &scaled))
}

/// The value of `id` when it is a constant integer.
fn integer(g: &Graph, id: Id) -> Option<f64> {
    const_of(g, id).filter(|v| v.fract() == 0.0)
}

/// `(x^a)^n → x^(a·n)` for integer `n`.
pub(super) fn pow_of_pow_int(g: &Graph, base: Id, e: Id) -> Option<Id> {
    let n = integer(g, e)?;
    let Node::Pow(x, a) = g.node(base) else {
        return None;
    };
    let a = const_of(g, a)?;
    Some(pow(g, x, konst(g, a * n)))
}

/// `(x^n)^e → |x|^(n·e)` for even integer `n` and integer `n·e`.
pub(super) fn even_root(g: &Graph, base: Id, e: Id) -> Option<Id> {
    let e = const_of(g, e)?;
    let Node::Pow(x, n) = g.node(base) else {
        return None;
    };
    let n = integer(g, n)?;
    let m = n * e;
    if n % 2.0 != 0.0 || m.fract() != 0.0 {
        return None;
    }
    Some(pow(g, unary(g, Unary::Abs, x), konst(g, m)))
}

/// `|x|^n → x^n` for even integer `n`.
pub(super) fn abs_even_pow(g: &Graph, base: Id, e: Id) -> Option<Id> {
    let n = integer(g, e)?;
    let Node::Unary(Unary::Abs, x) = g.node(base) else {
        return None;
    };
    (n % 2.0 == 0.0).then(|| pow(g, x, e))
}

/// `(x·y)^n → x^n·y^n` for integer `n`.
pub(super) fn pow_of_product_int(g: &Graph, base: Id, e: Id) -> Option<Id> {
    integer(g, e)?;
    let Node::Mul(xs) = g.node(base) else {
        return None;
    };
    let fs: Vec<Id> = xs.iter().map(|&x| pow(g, x, e)).collect();
    Some(mul(g, &fs))
}

/// `(c·s)^e → c^e·s^e` for a sum `c·s` whose coefficients are all `±c`,
/// `c` the coefficient of its leading term (the one [`is_negative`] looks
/// at); for a non-integer `e` only when `c > 0`.
pub(super) fn pow_sum_content(g: &Graph, base: Id, e: Id) -> Option<Id> {
    let ev = const_of(g, e)?;
    let Node::Add(xs) = g.node(base) else {
        return None;
    };
    let parts: Vec<(f64, Vec<Id>)> = xs.iter().map(|&t| term_parts(g, t)).collect();
    let (c, _) = parts
        .iter()
        .filter(|(_, fs)| !fs.is_empty())
        .min_by(|a, b| a.1.cmp(&b.1))?;
    let c = *c;
    if c == 1.0 || parts.iter().any(|(ct, _)| ct.abs() != c.abs()) || (ev.fract() != 0.0 && c < 0.0)
    {
        return None;
    }
    // Every quotient ct / c is exactly ±1.
    let terms: Vec<Id> = xs
        .iter()
        .map(|&t| match const_of(g, t) {
            Some(v) => konst(g, v / c),
            None => {
                let (ct, b) = split_coeff(g, t);
                scale(g, ct / c, b)
            }
        })
        .collect();
    let s = add(g, &terms);
    Some(mul(g, &[pow(g, konst(g, c), e), pow(g, s, e)]))
}

/// `f(−u) → −f(u)` for an odd `f`.
pub(super) fn odd(g: &Graph, op: Unary, x: Id) -> Option<Id> {
    is_negative(g, x).then(|| neg(g, unary(g, op, neg(g, x))))
}

/// `f(−u) → f(u)` for an even `f`.
pub(super) fn even(g: &Graph, op: Unary, x: Id) -> Option<Id> {
    is_negative(g, x).then(|| unary(g, op, neg(g, x)))
}

/// `|c·u| → |c|·|u|`, `|−u| → |u|`.
pub(super) fn abs_scale(g: &Graph, op: Unary, x: Id) -> Option<Id> {
    let (c, fs) = term_parts(g, x);
    if matches!(g.node(x), Node::Mul(_)) && c != 1.0 {
        let inner = unary(g, op, mul(g, &fs));
        return Some(mul(g, &[konst(g, c.abs()), inner]));
    }
    even(g, op, x)
}

/// `| |u| | → |u|`, `|u^n| → u^n` for even `n`.
pub(super) fn abs_of_nonneg(g: &Graph, _op: Unary, x: Id) -> Option<Id> {
    match g.node(x) {
        Node::Unary(Unary::Abs, _) => Some(x),
        Node::Pow(_, e) if integer(g, e).is_some_and(|n| n % 2.0 == 0.0) => Some(x),
        _ => None,
    }
}

/// Strips negative signs from both operands of `hypot` and sorts them.
pub(super) fn hypot_canonical(g: &Graph, op: Binary, a: Id, b: Id) -> Option<Id> {
    let positive = |x: Id| match const_of(g, x) {
        Some(v) if v < 0.0 => Some(konst(g, -v)),
        Some(_) => None,
        None => is_negative(g, x).then(|| neg(g, x)),
    };
    let (pa, pb) = (positive(a), positive(b));
    let (a2, b2) = (pa.unwrap_or(a), pb.unwrap_or(b));
    let (lo, hi) = if a2 <= b2 { (a2, b2) } else { (b2, a2) };
    if pa.is_none() && pb.is_none() && (lo, hi) == (a, b) {
        return None;
    }
    Some(super::binary(g, op, lo, hi))
}

/// The termination measure of the sum rules: occurrences of `cos` and
/// `exp` in the terms, counted as a tree (saturating).
pub(crate) fn sum_measure(g: &Graph, terms: &[Id]) -> u64 {
    fn count(g: &Graph, id: Id, memo: &mut HashMap<Id, u64>) -> u64 {
        if let Some(&n) = memo.get(&id) {
            return n;
        }
        let node = g.node(id);
        let mut n = u64::from(matches!(node, Node::Unary(Unary::Cos | Unary::Exp, _)));
        node.for_each_child(|c| n = n.saturating_add(count(g, c, memo)));
        memo.insert(id, n);
        n
    }
    let mut memo = HashMap::new();
    terms
        .iter()
        .fold(0, |n, &t| n.saturating_add(count(g, t, &mut memo)))
}
