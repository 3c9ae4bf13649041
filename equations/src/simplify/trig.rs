//! Angle-sum laws: a pair of like terms `c·F·cos a·cos b ± c·F·sin a·sin b`
//! or `c·F·sin a·cos b ± c·F·cos a·sin b` becomes one term with a cosine or
//! sine of `a ∓ b` / `a ± b`. Kinetic energies of chains (the double
//! pendulum's `cos(θ₁ − θ₂)`) come out of Cartesian coordinates in the
//! expanded form; these rows fold them back. Each is a row of
//! [`super::rules::RULES`].
//!
//! Termination: the rewritten pair holds `cos` twice (plus twice the `cos`
//! inside `a` and `b`, one of each pair of `sin`/`cos` holding `a`, the
//! other `b`); the result holds `a` and `b` once, under at most one `cos`,
//! so the sum rules' measure ([`super::laws::sum_measure`]) strictly falls.

use std::collections::HashMap;

use super::laws::{find_term, without};
use super::{add, konst, mul, neg, term_parts, unary};
use crate::graph::{Graph, Id, Node, Unary};

/// `u` when `f` is `op(u)`.
fn arg_of(g: &Graph, f: Id, op: Unary) -> Option<Id> {
    g.with_node(f, |n| match n {
        Node::Unary(o, u) if *o == op => Some(*u),
        _ => None,
    })
}

/// True when a factor of `fs` is `f` itself or a power of `f`.
fn mentions(g: &Graph, fs: &[Id], f: Id) -> bool {
    fs.iter().any(|&x| {
        x == f
            || g.with_node(x, |n| match n {
                Node::Pow(b, _) => *b == f,
                _ => false,
            })
    })
}

/// The pair found: term indices, the coefficient and cofactor `F` of the
/// first term, the angles `a`, `b`, and the sign of the partner's
/// coefficient relative to the first one.
struct Pair {
    i: usize,
    j: usize,
    c: f64,
    rest: Vec<Id>,
    a: Id,
    b: Id,
    same_sign: bool,
}

/// Finds a term `c·F·p(a)·q(b)` (`a ≠ b`) whose partner `±c·F·p'(a)·q'(b)`
/// is another term of the sum, where `(p, q) → (p', q')` is
/// `(cos, cos) → (sin, sin)` or `(sin, cos) → (cos, sin)`.
fn find(g: &Graph, terms: &[Id], p: Unary, q: Unary, p2: Unary, q2: Unary) -> Option<Pair> {
    let mut index: Option<HashMap<Id, usize>> = None;
    for (i, &t) in terms.iter().enumerate() {
        let quick = g.with_node(t, |n| match n {
            Node::Mul(fs) => fs.len() >= 2,
            _ => false,
        });
        if !quick {
            continue;
        }
        let (c, fs) = term_parts(g, t);
        for (kp, &fp) in fs.iter().enumerate() {
            let Some(a) = arg_of(g, fp, p) else { continue };
            for (kq, &fq) in fs.iter().enumerate() {
                if kq == kp {
                    continue;
                }
                let Some(b) = arg_of(g, fq, q) else { continue };
                if a == b {
                    continue;
                }
                let (Some(pa), Some(qb)) =
                    (g.find(&Node::Unary(p2, a)), g.find(&Node::Unary(q2, b)))
                else {
                    continue;
                };
                let rest: Vec<Id> = fs
                    .iter()
                    .enumerate()
                    .filter(|&(k, _)| k != kp && k != kq)
                    .map(|(_, &f)| f)
                    .collect();
                if mentions(g, &rest, pa) || mentions(g, &rest, qb) {
                    continue;
                }
                let mut partner = rest.clone();
                partner.push(pa);
                partner.push(qb);
                partner.sort_unstable();
                let index = index.get_or_insert_with(|| {
                    terms.iter().enumerate().map(|(j, &t)| (t, j)).collect()
                });
                for same_sign in [true, false] {
                    let cp = if same_sign { c } else { -c };
                    let Some(pt) = find_term(g, cp, &partner) else {
                        continue;
                    };
                    if let Some(&j) = index.get(&pt).filter(|&&j| j != i) {
                        return Some(Pair {
                            i,
                            j,
                            c,
                            rest,
                            a,
                            b,
                            same_sign,
                        });
                    }
                }
            }
        }
    }
    None
}

/// The terms without the pair, plus `c·F·op(angle)`.
fn replace(g: &Graph, terms: &[Id], pair: Pair, op: Unary, angle: Id) -> Vec<Id> {
    let mut f = pair.rest;
    f.push(konst(g, pair.c));
    f.push(unary(g, op, angle));
    let mut next = without(terms, pair.i, pair.j);
    next.push(mul(g, &f));
    next
}

/// `c·F·cos a·cos b + c·F·sin a·sin b → c·F·cos(a − b)`;
/// `c·F·cos a·cos b − c·F·sin a·sin b → c·F·cos(a + b)`.
pub(super) fn cos_angle_sum(g: &Graph, terms: &[Id]) -> Option<Vec<Id>> {
    if terms.len() < 2 {
        return None;
    }
    let pair = find(g, terms, Unary::Cos, Unary::Cos, Unary::Sin, Unary::Sin)?;
    let angle = if pair.same_sign {
        add(g, &[pair.a, neg(g, pair.b)])
    } else {
        add(g, &[pair.a, pair.b])
    };
    Some(replace(g, terms, pair, Unary::Cos, angle))
}

/// `c·F·sin a·cos b + c·F·cos a·sin b → c·F·sin(a + b)`;
/// `c·F·sin a·cos b − c·F·cos a·sin b → c·F·sin(a − b)`.
pub(super) fn sin_angle_sum(g: &Graph, terms: &[Id]) -> Option<Vec<Id>> {
    if terms.len() < 2 {
        return None;
    }
    let pair = find(g, terms, Unary::Sin, Unary::Cos, Unary::Cos, Unary::Sin)?;
    let angle = if pair.same_sign {
        add(g, &[pair.a, pair.b])
    } else {
        add(g, &[pair.a, neg(g, pair.b)])
    };
    Some(replace(g, terms, pair, Unary::Sin, angle))
}
