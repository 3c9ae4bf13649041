//! Lowering before emission: the canonical DAG (flat, expanded sums and
//! products) rewritten into the shape a person would write by hand, so
//! that the emitted code does the same work as a hand-derived form.
//!
//! Three rewrites, each over the nodes reachable from a function's outputs,
//! with the signs of sums normalized before and after the first (`sign`:
//! one value per ± pair, so that `S` and `−S` are one `let`):
//!
//! 1. **Sums are factored** greedily (multivariate Horner, `horner`): in a
//!    sum of products, the factor shared by the most terms is taken out,
//!    `a·x + a·y + z → a·(x + y) + z`, and the rule is applied again inside
//!    and outside the bracket; terms without a shared factor but with the
//!    same coefficient are scaled once (`½a + ½b → ½(a + b)`). The sub-sums
//!    it creates are hash-consed, so `(m₁ + m₂)` built in two places is one
//!    value, bound once.
//! 2. **Parameters cancel** (`cancel`): in a product with one reciprocal
//!    factor, powers of parameters common to numerator and denominator
//!    cancel (Cramer's rule: `l₁ l₂² S / (l₁² l₂² S₂) → S / (l₁ S₂)`).
//! 3. **Sub-products are shared** (`pairs`): the pair of factors that occurs
//!    together in the most products (at least two) becomes a product of its
//!    own and replaces the pair everywhere; repeated until no pair recurs
//!    (greedy pair extraction). `m₂·l₁·l₂` in five terms is computed once.
//!
//! After the second sign folding, like terms meet (`combine`): two terms
//! that the folding made one value add their coefficients (`x − x` is
//! gone, `x + x` is `2x`), and sums of the same terms in another order are
//! one value.
//!
//! The new nodes are interned without simplification (the simplifier would
//! flatten them back), so they live beside the canonical ones in the same
//! arena and only the emitter sees them. The interpreter
//! ([`crate::eval::Tape`]) keeps evaluating the canonical DAG: it is the
//! independent oracle that `tests/generator/vs_interpreter.rs` checks the
//! lowered code against. None of the rewrites adds a multiplication.

mod cancel;
mod combine;
mod horner;
mod pairs;
pub(crate) mod sign;

use std::collections::HashMap;

use crate::graph::{Graph, Id, Node};
use crate::simplify::{konst, term_parts};

/// The lowered roots of `roots` (same values, same order).
pub fn lower(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let signed = sign::fold_negations(g, roots);
    let factored = rebuild(g, &signed, |g, _, node, _| match node {
        Node::Add(xs) => horner::factor_sum(g, &xs),
        Node::Mul(xs)
            if xs
                .iter()
                .any(|&x| crate::simplify::const_of(g, x) == Some(0.0)) =>
        {
            konst(g, 0.0) // a factor cancelled to zero (`horner::like_terms`)
        }
        node => g.intern(node),
    });
    let factored = combine::combine_like_terms(g, &sign::fold_negations(g, &factored));
    let cancelled = rebuild(g, &factored, |g, _, node, _| match node {
        Node::Mul(_) => cancel::cancel_parameters(g, g.intern(node)),
        node => g.intern(node),
    });
    let shared = pairs::share_products(g, &cancelled);
    let reused = combine::reuse_positive_terms(g, &reuse_reciprocals(g, &shared));
    sign::fold_even_powers(g, &reused)
}

/// `b⁻²` written `(b⁻¹)²` where the function binds `b⁻¹` anyway: the
/// reciprocal is computed once (a multiplication instead of a second
/// division).
fn reuse_reciprocals(g: &Graph, roots: &[Id]) -> Vec<Id> {
    // Only a reciprocal bound to a `let` of its own (more users than the
    // scheduler turns into divisions) is worth reusing.
    let uses = sign::use_counts(g, roots);
    let is_live = |id: Id| uses.get(id.index()).copied().unwrap_or(0) > 2;
    rebuild(g, roots, |g, _, node, _| {
        if let Node::Pow(b, e) = node
            && crate::simplify::const_of(g, e) == Some(-2.0)
            && let Some(r) = g.find(&Node::Pow(b, konst(g, -1.0)))
            && is_live(r)
        {
            return g.intern(Node::Pow(r, konst(g, 2.0)));
        }
        g.intern(node)
    })
}

/// Rebuilds the nodes reachable from `roots` in arena (children-first)
/// order, each with its children replaced by their rebuilt ids, through
/// `f(graph, old id, node with new children, old → new so far)`.
pub(super) fn rebuild(
    g: &Graph,
    roots: &[Id],
    mut f: impl FnMut(&Graph, Id, Node, &HashMap<Id, Id>) -> Id,
) -> Vec<Id> {
    let live = live_nodes(g, roots);
    let mut map: HashMap<Id, Id> = HashMap::with_capacity(live.len());
    for &id in &live {
        let node = g.node(id);
        let new = match node {
            Node::Const(_) | Node::Sym(_) => id,
            node => {
                let mapped = map_children(&node, &map);
                f(g, id, mapped, &map)
            }
        };
        if new != id
            && let Some(label) = g.label(id)
        {
            g.set_label(new, &label); // the model's name follows the value
        }
        map.insert(id, new);
    }
    roots.iter().map(|r| map[r]).collect()
}

/// Ids reachable from `roots`, in arena order.
pub(super) fn live_nodes(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let live = g.reachable(roots);
    (0..live.len())
        .filter(|&i| live[i])
        .map(|i| Id(i as u32))
        .collect()
}

fn map_children(node: &Node, map: &HashMap<Id, Id>) -> Node {
    let m = |id: &Id| map[id];
    match node {
        Node::Const(_) | Node::Sym(_) => node.clone(),
        Node::Add(xs) => Node::Add(xs.iter().map(m).collect()),
        Node::Mul(xs) => Node::Mul(xs.iter().map(m).collect()),
        Node::Pow(a, b) => Node::Pow(m(a), m(b)),
        Node::Unary(op, a) => Node::Unary(*op, m(a)),
        Node::Binary(op, a, b) => Node::Binary(*op, m(a), m(b)),
    }
}

/// A term of a sum: coefficient times factors (none of them constant).
pub(super) type Term = (f64, Vec<Id>);

/// The factors of a (possibly lowered) product, nested products flattened
/// and a base met more than once with positive integer exponents merged
/// into one power (`l₁ · (l₁ · x) → l₁² · x`, the `l₁²` the model already
/// computes).
pub(super) fn factors_of(g: &Graph, id: Id) -> Term {
    let (c, fs) = flat_factors(g, id);
    (c, merge_powers(g, fs))
}

/// `(base, positive integer exponent)` of a factor.
pub(super) fn base_exponent(g: &Graph, f: Id) -> Option<(Id, i32)> {
    match g.node(f) {
        Node::Pow(b, e) => match crate::simplify::const_of(g, e) {
            Some(n) if n.fract() == 0.0 && (1.0..=64.0).contains(&n) => Some((b, n as i32)),
            _ => None,
        },
        _ => Some((f, 1)),
    }
}

fn merge_powers(g: &Graph, fs: Vec<Id>) -> Vec<Id> {
    let keyed: Vec<Option<(Id, i32)>> = fs.iter().map(|&f| base_exponent(g, f)).collect();
    let repeated = |b: Id| keyed.iter().flatten().filter(|(x, _)| *x == b).count() > 1;
    if !keyed.iter().flatten().any(|&(b, _)| repeated(b)) {
        return fs;
    }
    let mut out: Vec<Id> = Vec::with_capacity(fs.len());
    let mut done: Vec<Id> = Vec::new();
    for (&f, k) in fs.iter().zip(&keyed) {
        match k {
            Some((b, _)) if repeated(*b) => {
                if done.contains(b) {
                    continue;
                }
                done.push(*b);
                let n: i32 = keyed
                    .iter()
                    .flatten()
                    .filter(|(x, _)| x == b)
                    .map(|(_, n)| n)
                    .sum();
                out.push(g.intern(Node::Pow(*b, konst(g, f64::from(n)))));
            }
            _ => out.push(f),
        }
    }
    out
}

/// A product as its coefficient and its sorted leaf factors, nested
/// products flattened: equal for a canonical product and a lowered one that
/// groups the same factors differently (`None` for a non-product).
pub(crate) fn product_key(g: &Graph, id: Id) -> Option<(f64, Vec<Id>)> {
    if !matches!(g.node(id), Node::Mul(_)) {
        return None;
    }
    let (c, mut fs) = flat_factors(g, id);
    fs.sort_unstable();
    Some((c, fs))
}

/// The coefficient and factors of a product, nested products flattened.
fn flat_factors(g: &Graph, id: Id) -> Term {
    let (c, fs) = term_parts(g, id);
    let mut coef = c;
    let mut out = Vec::with_capacity(fs.len());
    for f in fs {
        if matches!(g.node(f), Node::Mul(_)) {
            let (c2, inner) = flat_factors(g, f);
            coef *= c2;
            out.extend(inner);
        } else {
            out.push(f);
        }
    }
    (coef, out)
}

/// A sum node of `addends` (one addend stands for itself).
pub(super) fn sum_node(g: &Graph, addends: Vec<Id>) -> Id {
    match addends.len() {
        1 => addends[0],
        _ => g.intern(Node::Add(addends.into_boxed_slice())),
    }
}

/// `c · f₁ · f₂ · …` as a node: constant first, nested products next (so
/// that they print without brackets), the rest in their given order.
pub(super) fn term_node(g: &Graph, (c, fs): Term) -> Id {
    if fs.is_empty() {
        return konst(g, c);
    }
    if c == 1.0 && fs.len() == 1 {
        return fs[0];
    }
    let (mut nested, rest): (Vec<Id>, Vec<Id>) = fs
        .into_iter()
        .partition(|&f| matches!(g.node(f), Node::Mul(_)));
    nested.extend(rest);
    if c != 1.0 {
        nested.insert(0, konst(g, c));
    }
    g.intern(Node::Mul(nested.into_boxed_slice()))
}
