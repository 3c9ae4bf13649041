//! Substitution of symbols by expressions.
//!
//! [`Expr::subs`] and [`Substitution`] rebuild an expression with some
//! symbols replaced, through the simplifying constructors, so that what the replacement makes trivial
//! folds away (`x·0 = 0`, `cos 0 = 1`, `a·N + (−a)·N = 0`). Memoized over the
//! DAG: shared subexpressions are rebuilt once.
//!
//! Models use it to specialize one derivation: a variant with a coordinate
//! held at a constant (ψ ≡ 0), a coefficient eliminated (f = 0), two unknowns
//! identified (N_B1 = N_B2), or the known part of an expression that is
//! linear in some unknowns (the unknowns set to 0).
//!
//! ```
//! use pegdyn_equations::Graph;
//! let g = Graph::new();
//! let (x, y) = (g.var("x"), g.var("y"));
//! let e = x.cos() * y + x.sin() * y.square();
//! assert_eq!(e.subs(&[(x, g.constant(0.0))]), y);
//! assert_eq!((x * y - y * x.cos()).subs(&[(x, y)]), y.square() - y * y.cos());
//! ```

use std::collections::HashMap;

use crate::expr::Expr;
use crate::graph::{Graph, Id, Node, Sym};
use crate::simplify;

/// `e` with every symbol of `map` replaced by its expression (all at once:
/// a replacement is not itself substituted into), rebuilt nodes in `memo`.
fn subst_memo(g: &Graph, e: Id, map: &HashMap<Sym, Id>, memo: &mut HashMap<Id, Id>) -> Id {
    if let Some(&r) = memo.get(&e) {
        return r;
    }
    let mut sub = |id: Id| subst_memo(g, id, map, memo);
    let r = match g.node(e) {
        Node::Const(_) => e,
        Node::Sym(s) => map.get(&s).copied().unwrap_or(e),
        Node::Add(xs) => {
            let ts: Vec<Id> = xs.iter().map(|&t| sub(t)).collect();
            if ts[..] == xs[..] {
                e
            } else {
                simplify::add(g, &ts)
            }
        }
        Node::Mul(xs) => {
            let fs: Vec<Id> = xs.iter().map(|&f| sub(f)).collect();
            if fs[..] == xs[..] {
                e
            } else {
                simplify::mul(g, &fs)
            }
        }
        Node::Pow(b, p) => {
            let (nb, np) = (sub(b), sub(p));
            if (nb, np) == (b, p) {
                e
            } else {
                simplify::pow(g, nb, np)
            }
        }
        Node::Unary(op, a) => {
            let na = sub(a);
            if na == a {
                e
            } else {
                simplify::unary(g, op, na)
            }
        }
        Node::Binary(op, a, b) => {
            let (na, nb) = (sub(a), sub(b));
            if (na, nb) == (a, b) {
                e
            } else {
                simplify::binary(g, op, na, nb)
            }
        }
    };
    memo.insert(e, r);
    r
}

/// A substitution that remembers what it has rebuilt, so that many outputs
/// of one derivation are specialized with their shared parts rebuilt once.
pub struct Substitution {
    map: HashMap<Sym, Id>,
    memo: HashMap<Id, Id>,
}

impl Substitution {
    /// The substitution of the (symbol, replacement) `pairs`.
    ///
    /// # Panics
    /// If a left-hand side is not a symbol.
    pub fn new(pairs: &[(Expr<'_>, Expr<'_>)]) -> Substitution {
        Substitution {
            map: map_of(pairs),
            memo: HashMap::new(),
        }
    }

    /// `e` with the symbols replaced.
    pub fn apply<'g>(&mut self, e: Expr<'g>) -> Expr<'g> {
        let g = e.graph();
        g.expr(subst_memo(g, e.id(), &self.map, &mut self.memo))
    }
}

/// A substitution map from (symbol, replacement) pairs of expressions.
///
/// # Panics
/// If a left-hand side is not a symbol (a bug in the calling model).
fn map_of(pairs: &[(Expr<'_>, Expr<'_>)]) -> HashMap<Sym, Id> {
    pairs
        .iter()
        .map(|&(s, v)| match s.node() {
            Node::Sym(sym) => (sym, v.id()),
            _ => panic!("subs: `{s}` is not a symbol"),
        })
        .collect()
}

impl<'g> Expr<'g> {
    /// `self` with the symbols of `pairs` replaced (simultaneously).
    ///
    /// # Panics
    /// If a left-hand side is not a symbol.
    pub fn subs(self, pairs: &[(Expr<'g>, Expr<'g>)]) -> Expr<'g> {
        Substitution::new(pairs).apply(self)
    }
}
