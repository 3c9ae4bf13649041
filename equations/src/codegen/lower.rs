//! Lowering before emission: the canonical DAG (flat, expanded sums and
//! products) rewritten into the shape a person would write by hand, so
//! that the emitted code does the same work as a hand-derived form.
//!
//! Two passes, both over the nodes reachable from a function's outputs:
//!
//! 1. **Sums are factored** greedily (multivariate Horner): in a sum of
//!    products, the factor shared by the most terms is taken out,
//!    `a·x + a·y + z → a·(x + y) + z`, and the rule is applied again inside
//!    and outside the bracket. The sub-sums it creates are hash-consed, so
//!    `(m₁ + m₂)` built in two places is one value, bound once.
//!    Then, in a product with one reciprocal factor, powers of parameters
//!    common to numerator and denominator cancel (Cramer's rule:
//!    `l₁ l₂² S / (l₁² l₂² S₂) → S / (l₁ S₂)`).
//! 2. **Sub-products are shared**: the pair of factors that occurs together
//!    in the most products (at least two) becomes a product of its own and
//!    replaces the pair everywhere; repeated until no pair recurs (greedy
//!    pair extraction). `m₂·l₁·l₂` in five terms is computed once.
//!
//! The new nodes are interned without simplification (the simplifier would
//! flatten them back), so they live beside the canonical ones in the same
//! arena and only the emitter sees them. The interpreter
//! ([`crate::eval::Tape`]) keeps evaluating the canonical DAG: it is the
//! independent oracle that `tests/generated_vs_interpreter.rs` checks the
//! lowered code against. Constants are never taken out (they fold into the
//! coefficient of a term), so the number of multiplications never grows.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};

use crate::graph::{Graph, Id, Node};
use crate::simplify::{konst, term_parts};

/// The lowered roots of `roots` (same values, same order).
pub fn lower(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let factored = rebuild(g, roots, |g, _, node, _| match node {
        Node::Add(xs) => factor_sum(g, &xs),
        node => g.intern(node),
    });
    let cancelled = rebuild(g, &factored, |g, _, node, _| match node {
        Node::Mul(_) => cancel_parameters(g, g.intern(node)),
        node => g.intern(node),
    });
    share_products(g, &cancelled)
}

/// `(parameter symbol, positive integer exponent)` of a factor that is a
/// parameter or a positive integer power of one.
fn parameter_power(g: &Graph, f: Id) -> Option<(Id, i32)> {
    let (b, n) = base_exponent(g, f)?;
    match g.node(b) {
        Node::Sym(s) if g.sym_info(s).kind == crate::graph::SymKind::Param => Some((b, n)),
        _ => None,
    }
}

/// Pass 1b: in a product `n₁ n₂ … / (d₁ d₂ …)` (one reciprocal factor of
/// a product), powers of parameters common to numerator and denominator
/// are cancelled: Cramer's `l₁ l₂² S / (l₁² l₂² S₂)` becomes
/// `S / (l₁ S₂)`. Parameters only (masses, lengths are nonzero in any
/// meaningful model; a state could be zero, and `x/x` must stay NaN there).
fn cancel_parameters(g: &Graph, id: Id) -> Id {
    let (c, fs) = factors_of(g, id);
    let reciprocal = |f: &Id| match g.node(*f) {
        Node::Pow(x, e) if crate::simplify::const_of(g, e) == Some(-1.0) => Some(x),
        _ => None,
    };
    let recips: Vec<usize> = (0..fs.len())
        .filter(|&k| reciprocal(&fs[k]).is_some())
        .collect();
    let [r] = recips[..] else {
        return id;
    };
    let Some(den) = reciprocal(&fs[r]) else {
        return id;
    };
    let (dc, dfs) = factors_of(g, den);
    let mut num: Vec<Id> = fs
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != r)
        .map(|(_, &f)| f)
        .collect();
    let mut dfs = dfs;
    let mut changed = false;
    for k in 0..num.len() {
        let Some((b, n)) = parameter_power(g, num[k]) else {
            continue;
        };
        let Some(j) = dfs
            .iter()
            .position(|&f| parameter_power(g, f).is_some_and(|(x, _)| x == b))
        else {
            continue;
        };
        let Some((_, m)) = parameter_power(g, dfs[j]) else {
            continue;
        };
        let t = n.min(m);
        num[k] = power(g, b, n - t);
        dfs[j] = power(g, b, m - t);
        changed = true;
    }
    if !changed {
        return id;
    }
    let one = |f: &Id| crate::simplify::const_of(g, *f) == Some(1.0);
    num.retain(|f| !one(f));
    dfs.retain(|f| !one(f));
    let den = term_node(g, (dc, dfs));
    num.push(g.intern(Node::Pow(den, konst(g, -1.0))));
    term_node(g, (c, num))
}

/// `b^n` as a node for `n >= 0` (`1`, `b`, or a power).
fn power(g: &Graph, b: Id, n: i32) -> Id {
    match n {
        0 => konst(g, 1.0),
        1 => b,
        _ => g.intern(Node::Pow(b, konst(g, f64::from(n)))),
    }
}

/// Rebuilds the nodes reachable from `roots` in arena (children-first)
/// order, each with its children replaced by their rebuilt ids, through
/// `f(graph, old id, node with new children, old → new so far)`.
fn rebuild(
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
        map.insert(id, new);
    }
    roots.iter().map(|r| map[r]).collect()
}

/// Ids reachable from `roots`, in arena order.
fn live_nodes(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let n = roots.iter().map(|r| r.index() + 1).max().unwrap_or(0);
    let mut live = vec![false; n];
    for r in roots {
        live[r.index()] = true;
    }
    for i in (0..n).rev() {
        if live[i] {
            g.with_node(Id(i as u32), |node| {
                node.for_each_child(|c| live[c.index()] = true)
            });
        }
    }
    (0..n).filter(|&i| live[i]).map(|i| Id(i as u32)).collect()
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
type Term = (f64, Vec<Id>);

/// The factors of a (possibly lowered) product, nested products flattened
/// and a base met more than once with positive integer exponents merged
/// into one power (`l₁ · (l₁ · x) → l₁² · x`, the `l₁²` the model already
/// computes).
fn factors_of(g: &Graph, id: Id) -> Term {
    let (c, fs) = flat_factors(g, id);
    (c, merge_powers(g, fs))
}

/// `(base, positive integer exponent)` of a factor.
fn base_exponent(g: &Graph, f: Id) -> Option<(Id, i32)> {
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

/// Pass 1 for one sum whose terms are already lowered. The terms are taken
/// in [`crate::eval::sum_order`] (products of parameters first) and the two
/// groups are factored apart, parameters' addends first: alike parameter
/// terms still meet before state-dependent ones are added (Sterbenz), as in
/// the interpreter. The emitter keeps this order.
fn factor_sum(g: &Graph, xs: &[Id]) -> Id {
    let order = crate::eval::sum_order(g, xs);
    let n_param = order
        .iter()
        .take_while(|&&t| crate::eval::is_param_term(g, t))
        .count();
    let terms: Vec<Term> = order.iter().map(|&t| factors_of(g, t)).collect();
    let (params, state) = terms.split_at(n_param);
    let mut addends = horner(g, params.to_vec());
    addends.extend(horner(g, state.to_vec()));
    sum_node(g, addends)
}

/// The addends of `Σ terms` after greedy factoring, each a node.
fn horner(g: &Graph, terms: Vec<Term>) -> Vec<Id> {
    if terms.is_empty() {
        return Vec::new();
    }
    let Some(f) = most_shared_factor(&terms) else {
        return shared_coefficient(g, terms);
    };
    let (with, without): (Vec<Term>, Vec<Term>) =
        terms.into_iter().partition(|(_, fs)| fs.contains(&f));
    let inner: Vec<Term> = with
        .into_iter()
        .map(|(c, mut fs)| {
            // One occurrence (a flattened product may repeat a factor).
            if let Some(i) = fs.iter().position(|&x| x == f) {
                fs.remove(i);
            }
            (c, fs)
        })
        .collect();
    let bracket = sum_node(g, horner(g, inner));
    let mut out = vec![term_node(g, (1.0, vec![f, bracket]))];
    if !without.is_empty() {
        out.extend(horner(g, without));
    }
    out
}

/// The addends of a sum whose terms share no factor: terms with the same
/// coefficient magnitude `c ≠ 1` (at least two) summed first and scaled
/// once, `½a + ½b → ½(a + b)`.
fn shared_coefficient(g: &Graph, terms: Vec<Term>) -> Vec<Id> {
    let shared = terms.iter().map(|t| t.0.abs()).find(|&c| {
        c != 1.0
            && terms
                .iter()
                .filter(|t| t.0.abs() == c && !t.1.is_empty())
                .count()
                >= 2
    });
    let Some(c) = shared else {
        return terms.into_iter().map(|t| term_node(g, t)).collect();
    };
    let (with, without): (Vec<Term>, Vec<Term>) = terms
        .into_iter()
        .partition(|t| t.0.abs() == c && !t.1.is_empty());
    let inner: Vec<Id> = with
        .into_iter()
        .map(|(k, fs)| term_node(g, (k.signum(), fs)))
        .collect();
    let scaled = g.intern(Node::Mul(
        vec![konst(g, c), sum_node(g, inner)].into_boxed_slice(),
    ));
    let mut out = vec![scaled];
    out.extend(without.into_iter().map(|t| term_node(g, t)));
    out
}

/// The non-constant factor in the most terms (at least two); ties go to
/// the factor that comes first in the terms (deterministic).
fn most_shared_factor(terms: &[Term]) -> Option<Id> {
    if terms.len() < 2 {
        return None;
    }
    let mut counts: Vec<(Id, usize)> = Vec::new();
    for (_, fs) in terms {
        for (i, &f) in fs.iter().enumerate() {
            if fs[..i].contains(&f) {
                continue; // each term counts once
            }
            match counts.iter_mut().find(|(x, _)| *x == f) {
                Some((_, n)) => *n += 1,
                None => counts.push((f, 1)),
            }
        }
    }
    let best = counts.iter().map(|&(_, n)| n).max()?;
    (best >= 2).then(|| counts.into_iter().find(|&(_, n)| n == best).map(|(f, _)| f))?
}

/// A sum node of `addends` (one addend stands for itself).
fn sum_node(g: &Graph, addends: Vec<Id>) -> Id {
    match addends.len() {
        1 => addends[0],
        _ => g.intern(Node::Add(addends.into_boxed_slice())),
    }
}

/// `c · f₁ · f₂ · …` as a node: constant first, nested products next (so
/// that they print without brackets), the rest in their given order.
fn term_node(g: &Graph, (c, fs): Term) -> Id {
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

/// A factor of pass 2: a node, or the product of two earlier factors.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
enum Factor {
    Node(Id),
    Pair(usize),
}

/// Pass 2: greedy pair extraction over every product reachable from
/// `roots`, then the rebuild with the shared products in place.
fn share_products(g: &Graph, roots: &[Id]) -> Vec<Id> {
    let live = live_nodes(g, roots);
    let mut products: Vec<(Id, f64, Vec<Factor>)> = Vec::new();
    for &id in &live {
        if matches!(g.node(id), Node::Mul(_)) {
            let (c, fs) = factors_of(g, id);
            products.push((id, c, fs.into_iter().map(Factor::Node).collect()));
        }
    }
    let pairs = extract_pairs(products.iter_mut().map(|(_, _, fs)| fs).collect());
    let by_id: HashMap<Id, usize> = products
        .iter()
        .enumerate()
        .map(|(k, (id, _, _))| (*id, k))
        .collect();
    let mut pair_nodes: HashMap<usize, Id> = HashMap::new();
    rebuild(g, roots, |g, old, node, map| {
        let Some(&k) = by_id.get(&old) else {
            return g.intern(node);
        };
        // Every leaf factor of product `k` comes before it in the arena,
        // so it is already in `map`.
        let (_, c, fs) = &products[k];
        let fs: Vec<Id> = fs
            .iter()
            .map(|&f| factor_node(g, f, &pairs, &mut pair_nodes, map))
            .collect();
        term_node(g, (*c, fs))
    })
}

/// The node of pass-2 factor `f`, leaves mapped through `map`; a pair's
/// product is built once and shared by every product that holds it.
fn factor_node(
    g: &Graph,
    f: Factor,
    pairs: &[(Factor, Factor)],
    built: &mut HashMap<usize, Id>,
    map: &HashMap<Id, Id>,
) -> Id {
    match f {
        Factor::Node(id) => map.get(&id).copied().unwrap_or(id),
        Factor::Pair(k) => {
            if let Some(&id) = built.get(&k) {
                return id;
            }
            let (a, b) = pairs[k];
            let a = factor_node(g, a, pairs, built, map);
            let b = factor_node(g, b, pairs, built, map);
            let id = term_node(g, (1.0, vec![a, b]));
            built.insert(k, id);
            id
        }
    }
}

/// Greedy pair extraction: while some pair of factors occurs together in
/// two or more of `products`, replace it by a new factor (returned as the
/// table of pairs, indexed by `Factor::Pair`). Most frequent pair first;
/// ties to the smallest pair (deterministic).
fn extract_pairs(mut products: Vec<&mut Vec<Factor>>) -> Vec<(Factor, Factor)> {
    let mut counts: HashMap<(Factor, Factor), usize> = HashMap::new();
    let mut holders: HashMap<(Factor, Factor), Vec<usize>> = HashMap::new();
    for (k, fs) in products.iter().enumerate() {
        for p in pairs_of(fs) {
            *counts.entry(p).or_default() += 1;
            holders.entry(p).or_default().push(k);
        }
    }
    let mut heap: BinaryHeap<(usize, Reverse<(Factor, Factor)>)> = counts
        .iter()
        .filter(|(_, n)| **n >= 2)
        .map(|(p, n)| (*n, Reverse(*p)))
        .collect();
    let mut table = Vec::new();
    while let Some((n, Reverse(p))) = heap.pop() {
        if counts.get(&p) != Some(&n) || n < 2 {
            continue; // stale entry
        }
        let new = Factor::Pair(table.len());
        table.push(p);
        let ks = holders.remove(&p).unwrap_or_default();
        for k in ks {
            let fs = &mut *products[k];
            if !(fs.contains(&p.0) && fs.contains(&p.1)) {
                continue;
            }
            for q in pairs_of(fs) {
                if let Some(c) = counts.get_mut(&q) {
                    *c -= 1;
                }
            }
            // One occurrence of each (a flattened product may repeat a factor).
            for x in [p.0, p.1] {
                if let Some(i) = fs.iter().position(|&f| f == x) {
                    fs.remove(i);
                }
            }
            fs.insert(0, new);
            for q in pairs_of(fs) {
                let c = counts.entry(q).or_default();
                *c += 1;
                holders.entry(q).or_default().push(k);
                if *c >= 2 {
                    heap.push((*c, Reverse(q)));
                }
            }
        }
        counts.remove(&p);
    }
    table
}

/// The unordered pairs of distinct factors of one product, each as
/// (smaller, larger), each pair once even where a factor repeats.
fn pairs_of(fs: &[Factor]) -> Vec<(Factor, Factor)> {
    let mut out = Vec::with_capacity(fs.len() * fs.len().saturating_sub(1) / 2);
    for (i, &a) in fs.iter().enumerate() {
        for &b in &fs[i + 1..] {
            if a != b {
                out.push(if a < b { (a, b) } else { (b, a) });
            }
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}
