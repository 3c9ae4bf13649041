//! The rewrite table: identities and numerically stable forms.
//!
//! Later work extends this table; each rule is one row with the law it
//! implements and, for stable forms, the cancellation it avoids.

use crate::graph::{Graph, Id, Unary};

/// Rewrites applied to a sum whose terms are already collected.
pub(crate) fn rewrite_sum(g: &Graph, terms: Vec<Id>) -> Id {
    super::finish_sum(g, terms)
}

/// Rewrites of a one-argument function of a non-constant argument.
pub(crate) fn rewrite_unary(_g: &Graph, _op: Unary, _x: Id) -> Option<Id> {
    None
}
