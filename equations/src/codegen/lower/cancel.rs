//! Pass 1b: powers of parameters common to a product and its reciprocal
//! factor cancelled.

use super::{base_exponent, factors_of, term_node};
use crate::graph::{Graph, Id, Node};
use crate::simplify::konst;

/// `(parameter symbol, positive integer exponent)` of a factor that is a
/// parameter or a positive integer power of one.
fn parameter_power(g: &Graph, f: Id) -> Option<(Id, i32)> {
    base_exponent(g, f).filter(|&(b, _)| crate::simplify::is_param(g, b))
}

/// Pass 1b: in a product `n₁ n₂ … / (d₁ d₂ …)` (one reciprocal factor of
/// a product), powers of parameters common to numerator and denominator
/// are cancelled: Cramer's `l₁ l₂² S / (l₁² l₂² S₂)` becomes
/// `S / (l₁ S₂)`. Parameters only (masses, lengths are nonzero in any
/// meaningful model; a state could be zero, and `x/x` must stay NaN there).
pub(super) fn cancel_parameters(g: &Graph, id: Id) -> Id {
    let (c, fs) = factors_of(g, id);
    let reciprocal = |f: &Id| match g.node(*f) {
        Node::Pow(x, e) if crate::simplify::const_of(g, e) == Some(-1.0) => Some(x),
        _ => None,
    };
    let recips: Vec<(usize, Id)> = fs
        .iter()
        .enumerate()
        .filter_map(|(k, f)| reciprocal(f).map(|x| (k, x)))
        .collect();
    let [(r, den)] = recips[..] else {
        return id;
    };
    let (dc, mut dfs) = factors_of(g, den);
    let mut num: Vec<Id> = fs
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != r)
        .map(|(_, &f)| f)
        .collect();
    let mut changed = false;
    for x in num.iter_mut() {
        let Some((b, n)) = parameter_power(g, *x) else {
            continue;
        };
        let Some((j, m)) = dfs.iter().enumerate().find_map(|(j, &f)| {
            parameter_power(g, f).and_then(|(x, m)| (x == b).then_some((j, m)))
        }) else {
            continue;
        };
        let t = n.min(m);
        *x = power(g, b, n - t);
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
