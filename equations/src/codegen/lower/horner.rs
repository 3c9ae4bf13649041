//! Pass 1: sums of products factored greedily (multivariate Horner),
//! parameter terms apart from and before state terms.

use super::{Term, factors_of, sum_node, term_node};
use crate::graph::{Graph, Id, Node};
use crate::simplify::konst;

/// Pass 1 for one sum whose terms are already lowered. The terms are taken
/// in [`crate::schedule::sum_order`] (products of parameters first) and the two
/// groups are factored apart, parameters' addends first: alike parameter
/// terms still meet before state-dependent ones are added (Sterbenz), as in
/// the interpreter. The emitter keeps this order.
pub(super) fn factor_sum(g: &Graph, xs: &[Id]) -> Id {
    let order = crate::schedule::sum_order(g, xs);
    let n_param = order
        .iter()
        .take_while(|&&t| crate::schedule::is_param_term(g, t))
        .count();
    let terms: Vec<Term> = order.iter().map(|&t| factors_of(g, t)).collect();
    let (params, state) = terms.split_at(n_param);
    let mut addends = horner(g, like_terms(params));
    addends.extend(horner(g, like_terms(state)));
    match addends.len() {
        0 => konst(g, 0.0),
        _ => sum_node(g, addends),
    }
}

/// Like terms collected: terms with the same factors (as a multiset) add
/// their coefficients, in the place of the first; a term whose coefficient
/// comes to zero is dropped (`x − x`, `a·x + (−a)·x`). Earlier passes can
/// make two canonical terms one value (a sum and its negation folded into
/// one `S⁺`), which the canonical simplifier never saw as alike.
fn like_terms(terms: &[Term]) -> Vec<Term> {
    let key = |fs: &[Id]| {
        let mut k = fs.to_vec();
        k.sort_unstable();
        k
    };
    let mut out: Vec<(Term, Vec<Id>)> = Vec::with_capacity(terms.len());
    for (c, fs) in terms {
        let k = key(fs);
        match out.iter_mut().find(|(_, k2)| *k2 == k) {
            Some(((c2, _), _)) => *c2 += c,
            None => out.push(((*c, fs.clone()), k)),
        }
    }
    out.into_iter()
        .map(|(t, _)| t)
        .filter(|(c, _)| *c != 0.0)
        .collect()
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
