//! Polynomial expansion: products and small integer powers of sums are
//! multiplied out, so that the simplifier's sum laws (like-term collection,
//! `sin² + cos² = 1`, the angle-sum rows of [`crate::simplify::rules`]) see
//! every monomial.
//!
//! Not a rewrite at construction (expanding every product would blow up the
//! large models); a model calls [`Expr::expand`] where it pays, typically on
//! a kinetic energy written from Cartesian velocities, whose squares of sums
//! hide `cos(θ₁ − θ₂)`. Function arguments are not entered.
//!
//! ```
//! use pegdyn_equations::Graph;
//! let g = Graph::new();
//! let (a, b, x, y) = (g.param("a"), g.param("b"), g.var("x"), g.var("y"));
//! let vx = a * x.cos() + b * y.cos();
//! let vy = a * x.sin() + b * y.sin();
//! let speed2 = (vx.square() + vy.square()).expand();
//! assert_eq!(speed2, a.square() + b.square() + 2.0 * a * b * (x - y).cos());
//! ```

use std::collections::HashMap;

use crate::expr::Expr;
use crate::graph::{Graph, Id, Node};
use crate::simplify::{self, konst};

/// Expansion stops (the product is kept as it is) beyond this many terms.
pub const MAX_TERMS: usize = 512;
/// Largest integer power of a sum that is multiplied out.
pub const MAX_POWER: f64 = 8.0;

impl<'g> Expr<'g> {
    /// `self` with products and integer powers (`2 ..= 8`) of sums
    /// multiplied out, recursively through sums, products and powers (not
    /// into function arguments); a product whose expansion would exceed
    /// [`MAX_TERMS`] terms is kept. Preserves the value wherever `self` is
    /// defined (the order of rounding changes).
    pub fn expand(self) -> Expr<'g> {
        let g = self.graph();
        g.expr(expand(g, self.id(), &mut HashMap::new()))
    }
}

/// The terms of `id` if it is a sum, else `[id]`.
fn terms_of(g: &Graph, id: Id) -> Vec<Id> {
    g.with_node(id, |n| match n {
        Node::Add(xs) => xs.to_vec(),
        _ => vec![id],
    })
}

/// The product of `factors` (already expanded), multiplied out term by term
/// unless that exceeds [`MAX_TERMS`].
fn distribute(g: &Graph, factors: &[Id]) -> Id {
    let lists: Vec<Vec<Id>> = factors.iter().map(|&f| terms_of(g, f)).collect();
    let n = lists
        .iter()
        .try_fold(1usize, |n, l| n.checked_mul(l.len()))
        .unwrap_or(usize::MAX);
    if n > MAX_TERMS {
        return simplify::mul(g, factors);
    }
    let mut acc = vec![konst(g, 1.0)];
    for l in &lists {
        let mut next = Vec::with_capacity(acc.len() * l.len());
        for &a in &acc {
            for &t in l {
                next.push(simplify::mul(g, &[a, t]));
            }
        }
        acc = next;
    }
    simplify::add(g, &acc)
}

fn expand(g: &Graph, id: Id, memo: &mut HashMap<Id, Id>) -> Id {
    if let Some(&r) = memo.get(&id) {
        return r;
    }
    let r = match g.node(id) {
        Node::Add(xs) => {
            let ts: Vec<Id> = xs.iter().map(|&x| expand(g, x, memo)).collect();
            simplify::add(g, &ts)
        }
        Node::Mul(fs) => {
            let fs: Vec<Id> = fs.iter().map(|&f| expand(g, f, memo)).collect();
            distribute(g, &fs)
        }
        Node::Pow(b, e) => {
            let eb = expand(g, b, memo);
            match simplify::const_of(g, e) {
                Some(n) if n.fract() == 0.0 && (2.0..=MAX_POWER).contains(&n) => {
                    distribute(g, &vec![eb; n as usize])
                }
                _ => simplify::pow(g, eb, e),
            }
        }
        _ => id,
    };
    memo.insert(id, r);
    r
}
