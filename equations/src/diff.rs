//! Symbolic differentiation.
//!
//! [`diff`] computes ∂e/∂x for every node kind, memoized over the DAG so that
//! shared subexpressions are differentiated once. Conventions at the kinks:
//! - d|x|/dx = sign(x), which is 0 at x = 0 (the subgradient's midpoint);
//! - d max(0, x)/dx = step(x), which is 0 at x = 0 (a contact that just
//!   touches has no stiffness yet);
//! - d sign(x)/dx = d step(x)/dx = 0 (everywhere except at 0, where the
//!   derivative does not exist; 0 is what the generated code uses).
//!
//! The chain rule is applied literally, so a derivative is NaN where it
//! multiplies an infinite factor by a zero one, even when the function is
//! locally constant there: `d sqrt(u) = du / (2 sqrt(u))` at `u = du = 0`
//! (e.g. `sqrt(max0(δ))` for an inactive contact: use exponents `>= 1` on a
//! `max0`, whose derivatives stay finite), `d b^y/dy = b^y ln(b)` at `b = 0`,
//! and `hypot(a, b)'` at `a = b = 0`. `equations/tests/pipeline/diff_vs_finite_difference.rs`
//! counts such points in random trees (about 0.1 %).
//!
//! [`time_derivative`] is the total derivative d/dt along given
//! coordinate/velocity pairs: d e/dt = ∂e/∂t + Σ ∂e/∂q_i · q̇_i.

use std::collections::HashMap;

use crate::expr::Expr;
use crate::graph::{Binary, Graph, Id, Node, Sym, SymKind, Unary};
use crate::simplify;

/// ∂e/∂x, for a symbol `x`.
pub fn diff(g: &Graph, e: Id, x: Sym) -> Id {
    let mut memo = HashMap::new();
    diff_memo(g, e, x, &mut memo)
}

fn diff_memo(g: &Graph, e: Id, x: Sym, memo: &mut HashMap<Id, Id>) -> Id {
    if let Some(&d) = memo.get(&e) {
        return d;
    }
    let zero = || g.constant(0.0).id();
    let one = || g.constant(1.0).id();
    let ex = |id: Id| g.expr(id);
    let d = match g.node(e) {
        Node::Const(_) => zero(),
        Node::Sym(s) => {
            if s == x {
                one()
            } else {
                zero()
            }
        }
        Node::Add(xs) => {
            let ds: Vec<Id> = xs.iter().map(|&t| diff_memo(g, t, x, memo)).collect();
            simplify::add(g, &ds)
        }
        Node::Mul(xs) => {
            // Product rule: Σ_k (∂f_k) Π_{j≠k} f_j.
            let mut terms = Vec::with_capacity(xs.len());
            for k in 0..xs.len() {
                let dk = diff_memo(g, xs[k], x, memo);
                if ex(dk).as_const() == Some(0.0) {
                    continue;
                }
                let mut fs: Vec<Id> = Vec::with_capacity(xs.len());
                fs.extend(
                    xs.iter()
                        .enumerate()
                        .filter(|&(j, _)| j != k)
                        .map(|(_, &f)| f),
                );
                fs.push(dk);
                terms.push(simplify::mul(g, &fs));
            }
            simplify::add(g, &terms)
        }
        Node::Pow(b, p) => {
            let db = diff_memo(g, b, x, memo);
            let dp = diff_memo(g, p, x, memo);
            let (b, p, db, dp) = (ex(b), ex(p), ex(db), ex(dp));
            let mut d = g.constant(0.0);
            if db.as_const() != Some(0.0) {
                // d(b^p) = p b^(p-1) db
                d = d + p * b.pow(p - 1.0) * db;
            }
            if dp.as_const() != Some(0.0) {
                // + b^p ln(b) dp
                d = d + b.pow(p) * b.ln() * dp;
            }
            d.id()
        }
        Node::Unary(op, a) => {
            let da = diff_memo(g, a, x, memo);
            if ex(da).as_const() == Some(0.0) {
                zero()
            } else {
                let u = ex(a);
                let outer = match op {
                    Unary::Sin => u.cos(),
                    Unary::Cos => -u.sin(),
                    Unary::Tan => 1.0 + u.tan().square(),
                    Unary::Asin => (1.0 - u.square()).powf(-0.5),
                    Unary::Acos => -(1.0 - u.square()).powf(-0.5),
                    Unary::Atan => 1.0 / (1.0 + u.square()),
                    Unary::Exp => u.exp(),
                    Unary::Expm1 => u.exp(),
                    Unary::Ln => 1.0 / u,
                    Unary::Ln1p => 1.0 / (1.0 + u),
                    Unary::Abs => u.signum(),
                    Unary::Sign | Unary::Step => g.constant(0.0),
                    Unary::Tanh => 1.0 - u.tanh().square(),
                    Unary::Max0 => u.step(),
                };
                (outer * ex(da)).id()
            }
        }
        Node::Binary(op, a, b) => {
            let da = ex(diff_memo(g, a, x, memo));
            let db = ex(diff_memo(g, b, x, memo));
            let (a, b) = (ex(a), ex(b));
            match op {
                // atan2(y, x)' = (x dy − y dx) / (x² + y²)
                Binary::Atan2 => ((b * da - a * db) / (a.square() + b.square())).id(),
                // hypot(a, b)' = (a da + b db) / hypot(a, b)
                Binary::Hypot => ((a * da + b * db) / a.hypot(b)).id(),
            }
        }
    };
    memo.insert(e, d);
    d
}

/// Total time derivative of `e` along `pairs` of (coordinate, velocity)
/// symbols: d e/dt = ∂e/∂t + Σ ∂e/∂q_i · q̇_i. If `e` does not contain time
/// the first term vanishes by itself.
pub fn time_derivative(g: &Graph, e: Id, pairs: &[(Sym, Sym)]) -> Id {
    let mut terms = Vec::with_capacity(pairs.len() + 1);
    if let Some(t) = g
        .lookup("t")
        .filter(|&t| g.sym_info(t).kind == SymKind::Time)
    {
        terms.push(diff(g, e, t));
    }
    for &(q, qd) in pairs {
        let dq = diff(g, e, q);
        let v = g.intern(Node::Sym(qd));
        terms.push(simplify::mul(g, &[dq, v]));
    }
    simplify::add(g, &terms)
}

impl<'g> Expr<'g> {
    /// ∂self/∂x, where `x` is a symbol (variable, parameter or time).
    ///
    /// # Panics
    /// If `x` is not a symbol.
    pub fn diff(self, x: Expr<'g>) -> Expr<'g> {
        let Node::Sym(s) = x.node() else {
            panic!("diff: `{x}` is not a symbol");
        };
        self.graph().expr(diff(self.graph(), self.id(), s))
    }

    /// Total time derivative along (coordinate, velocity) pairs of symbols.
    ///
    /// # Panics
    /// If a pair member is not a symbol.
    pub fn dt(self, pairs: &[(Expr<'g>, Expr<'g>)]) -> Expr<'g> {
        let sym = |e: Expr<'g>| match e.node() {
            Node::Sym(s) => s,
            _ => panic!("dt: `{e}` is not a symbol"),
        };
        let ps: Vec<(Sym, Sym)> = pairs.iter().map(|&(q, v)| (sym(q), sym(v))).collect();
        self.graph()
            .expr(time_derivative(self.graph(), self.id(), &ps))
    }
}
