//! Pass 0: one value per ± pair. A sum `S` and its negation `−S` are two
//! canonical nodes (`½H − ½a` and `−½H + ½a`); each sum is rewritten so
//! that most of its terms are positive, on a tie its pivot term (the term
//! whose non-constant factors come first, the same term in `S` and `−S`),
//! and a sum that was negative in that sense becomes `(−1)·S⁺`. The sign then folds into the
//! user: a product takes it into its coefficient, a sum subtracts, an even
//! power drops it, an odd power passes it out. Both `S` and `−S` are then
//! the one value `S⁺`, bound once; the emitted `-x` costs nothing (a sign
//! flip), and `−(a − b)` is `b − a` bit for bit (rounding is symmetric).

use std::cmp::Ordering;

use super::{Term, rebuild, sum_node, term_node};
use crate::graph::{Graph, Id, Node, PowForm};
use crate::schedule::{negated, pow_form};
use crate::simplify::{konst, term_parts};

/// The roots with every sum sign-normalized and every negation folded
/// into its user.
pub(super) fn fold_negations(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let uses = use_counts(g, roots);
    rebuild(g, roots, |g, old, node, _| match node {
        Node::Add(xs) => {
            // A scaled term `c·x` used elsewhere too stays as it is: its
            // negation `(−c)·x` would be a product of its own.
            let kept = g.with_node(old, |n| match n {
                Node::Add(ys) => ys.iter().any(|&y| {
                    uses[y.index()] > 1 && negated(g, y).is_none() && {
                        let (c, fs) = term_parts(g, y);
                        c.abs() != 1.0 && !fs.is_empty()
                    }
                }),
                _ => false,
            });
            if kept {
                sum_node(g, xs.to_vec())
            } else {
                normalize_sum(g, &xs)
            }
        }
        Node::Mul(xs) => fold_product(g, &xs),
        Node::Pow(b, e) => match (negated(g, b), pow_form(g, e)) {
            (Some(x), PowForm::Int(n)) if n % 2 == 0 => g.intern(Node::Pow(x, e)),
            (Some(x), PowForm::Int(_)) => negate(g, g.intern(Node::Pow(x, e))),
            _ => g.intern(Node::Pow(b, e)),
        },
        node => g.intern(node),
    })
}

/// The roots with every even power of a negation taken of its operand,
/// `(−x)^{2k} = x^{2k}` (exact: the sign of a product of equal factors),
/// so that no `let` binds a negation only to square it. The last lowering
/// passes (sharing sub-products, reusing named terms) can leave such a
/// power behind the sign folding.
pub(super) fn fold_even_powers(g: &Graph, roots: &[Id]) -> Vec<Id> {
    rebuild(g, roots, |g, _, node, _| match node {
        Node::Pow(b, e) => match (negated(g, b), pow_form(g, e)) {
            (Some(x), PowForm::Int(n)) if n % 2 == 0 => g.intern(Node::Pow(x, e)),
            _ => g.intern(Node::Pow(b, e)),
        },
        node => g.intern(node),
    })
}

/// How many users each node reachable from `roots` has.
pub(super) fn use_counts(g: &Graph, roots: &[Id]) -> Vec<u32> {
    let live = g.reachable(roots);
    let mut uses = vec![0u32; live.len()];
    for r in roots {
        uses[r.index()] += 1;
    }
    for (i, _) in live.iter().enumerate().filter(|(_, l)| **l) {
        g.with_node(Id(i as u32), |n| n.for_each_child(|c| uses[c.index()] += 1));
    }
    uses
}

/// `(−1)·x`, or `y` when `x` is `(−1)·y`.
fn negate(g: &Graph, x: Id) -> Id {
    match negated(g, x) {
        Some(y) => y,
        None => g.intern(Node::Mul(vec![konst(g, -1.0), x].into_boxed_slice())),
    }
}

/// A sum with its pivot term positive; `(−1)·S⁺` when it was negative.
fn normalize_sum(g: &Graph, xs: &[Id]) -> Id {
    let terms: Vec<Term> = xs.iter().map(|&t| term_parts(g, t)).collect();
    let pivot = terms
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.1.cmp(&b.1.1))
        .map(|(k, _)| k);
    let Some(k) = pivot else {
        return sum_node(g, xs.to_vec());
    };
    let negative = terms.iter().filter(|t| t.0 < 0.0).count();
    let flip = match (2 * negative).cmp(&terms.len()) {
        Ordering::Greater => true,
        Ordering::Less => false,
        Ordering::Equal => terms[k].0 < 0.0,
    };
    if !flip {
        return sum_node(g, xs.to_vec());
    }
    let flipped: Vec<Id> = xs
        .iter()
        .zip(terms)
        .map(|(&t, (c, fs))| match negated(g, t) {
            Some(x) => x,
            None => term_node(g, (-c, fs)),
        })
        .collect();
    negate(g, sum_node(g, flipped))
}

/// A product with the signs of its negated factors taken into its
/// coefficient.
fn fold_product(g: &Graph, xs: &[Id]) -> Id {
    if !xs.iter().any(|&f| negated(g, f).is_some()) {
        return g.intern(Node::Mul(xs.into()));
    }
    let mut c = 1.0;
    let mut fs = Vec::with_capacity(xs.len());
    for &f in xs {
        if let Some(v) = crate::simplify::const_of(g, f) {
            c *= v;
        } else if let Some(x) = negated(g, f) {
            c = -c;
            fs.push(x);
        } else {
            fs.push(f);
        }
    }
    if c == -1.0 && fs.len() == 1 {
        return negate(g, fs[0]);
    }
    term_node(g, (c, fs))
}
