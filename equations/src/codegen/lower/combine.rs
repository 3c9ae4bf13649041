//! Like terms meet: after the sign folding two canonical terms can be one
//! value (a sum `S` and its negation `−S` are both `S⁺` now), which the
//! canonical simplifier never saw as alike. A sum adds the coefficients of
//! terms with the same factors (`x − x → 0`, `x + x → 2x`, `1 + 1 → 2`)
//! and drops the terms that come to zero; a product with a zero factor is
//! zero. Exact on the values the canonical DAG computes: only terms equal
//! as expressions are merged.

use std::collections::HashMap;

use super::{Term, factors_of, rebuild, sum_node, term_node};
use crate::graph::{Graph, Id, Node};
use crate::simplify::{const_of, konst};

/// The roots with the like terms of every reachable sum combined, and
/// sums of the same terms in another order made one value (the first in
/// evaluation order): `r − ρ` and `−ρ + r` are bound once.
pub(super) fn combine_like_terms(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let mut sums: HashMap<Vec<Id>, Id> = HashMap::new();
    rebuild(g, roots, |g, _, node, _| match node {
        Node::Add(xs) => {
            let id = combine_sum(g, &xs);
            match g.node(id) {
                Node::Add(ys) => {
                    let mut key = ys.to_vec();
                    key.sort_unstable();
                    *sums.entry(key).or_insert(id)
                }
                _ => id,
            }
        }
        Node::Mul(xs) if xs.iter().any(|&x| const_of(g, x) == Some(0.0)) => konst(g, 0.0),
        node => g.intern(node),
    })
}

/// One sum with its like terms combined, in the place of the first.
fn combine_sum(g: &Graph, xs: &[Id]) -> Id {
    let keyed: Vec<(Id, Term)> = xs
        .iter()
        .map(|&x| {
            let (c, mut fs) = factors_of(g, x);
            fs.sort_unstable();
            (x, (c, fs))
        })
        .collect();
    let alike = |k: usize| keyed[..k].iter().any(|(_, t)| t.1 == keyed[k].1.1);
    if !(0..keyed.len()).any(alike) && !xs.iter().any(|&x| const_of(g, x) == Some(0.0)) {
        return sum_node(g, xs.to_vec());
    }
    let mut out: Vec<Id> = Vec::with_capacity(xs.len());
    for (k, (x, (c, fs))) in keyed.iter().enumerate() {
        if alike(k) {
            continue; // added into the first of its kind
        }
        let total: f64 = keyed[k..]
            .iter()
            .filter(|(_, t)| t.1 == *fs)
            .map(|(_, t)| t.0)
            .sum();
        if total == 0.0 {
            continue;
        }
        out.push(if total == *c {
            *x
        } else {
            term_node(g, (total, fs.clone()))
        });
    }
    match out.len() {
        0 => konst(g, 0.0),
        _ => sum_node(g, out),
    }
}

/// A term `−c·x` of a sum (`c ≠ 1`) whose positive `c·x` the code computes
/// anyway written as the negation of that value (`a − ½γ` subtracts the
/// bound `half_gamma` instead of computing `−½γ` again): a free sign flip
/// for a multiplication.
pub(super) fn reuse_positive_terms(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let live = g.reachable(roots);
    let is_live = |id: Id| live.get(id.index()).copied().unwrap_or(false);
    rebuild(g, roots, |g, _, node, _| match node {
        Node::Add(xs) => {
            let mut changed = false;
            let terms: Vec<Id> = xs
                .iter()
                .map(|&t| {
                    let (c, fs) = crate::simplify::term_parts(g, t);
                    if c >= 0.0 || c == -1.0 || fs.is_empty() {
                        return t;
                    }
                    let mut pos = vec![konst(g, -c)];
                    pos.extend(fs);
                    match g.find(&Node::Mul(pos.into_boxed_slice())) {
                        Some(p) if is_live(p) => {
                            changed = true;
                            g.intern(Node::Mul(vec![konst(g, -1.0), p].into_boxed_slice()))
                        }
                        _ => t,
                    }
                })
                .collect();
            if changed {
                sum_node(g, terms)
            } else {
                g.intern(Node::Add(xs))
            }
        }
        node => g.intern(node),
    })
}
