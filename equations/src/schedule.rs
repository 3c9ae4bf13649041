//! The evaluation order, one definition for the interpreter
//! ([`crate::eval::Tape`]) and the emitter ([`crate::codegen`]): which nodes
//! a function computes and which are computed once and reused (a `let`), in
//! which order the terms of a sum are added and when a sum is evaluated
//! with its common factors taken out.
//!
//! The nodes reachable from the outputs, taken in arena order, are already a
//! topological order (children first, see [`crate::graph`]). A node gets a
//! `let` when it is used more than once, when it is expensive (a function
//! call, a square root, a branch), or when its emitted form mentions its
//! operand more than once (`x * x` for `x²`). Every
//! other node is inlined into its single user. Each node is computed once.

use std::collections::BTreeSet;

use crate::graph::{Graph, Id, Node, PowForm, Sym};

/// `Some(x)` when `id` is the pure negation `(−1)·x`.
pub fn negated(g: &Graph, id: Id) -> Option<Id> {
    g.with_node(id, |n| match n {
        Node::Mul(fs) if fs.len() == 2 => {
            (crate::simplify::const_of(g, fs[0]) == Some(-1.0)).then_some(fs[1])
        }
        _ => None,
    })
}

/// The constant exponent of a power node, if any.
pub(crate) fn const_exponent(g: &Graph, e: Id) -> Option<f64> {
    g.expr(e).as_const()
}

/// How the power node `b^e` is computed ([`PowForm`]).
pub fn pow_form(g: &Graph, e: Id) -> PowForm {
    PowForm::of(const_exponent(g, e))
}

/// Nodes that always get a `let`: calls, roots, branches (the table's
/// [`FuncSpec::is_call`](crate::graph::FuncSpec::is_call),
/// [`PowForm::is_call`]).
fn expensive(g: &Graph, node: &Node) -> bool {
    match node {
        Node::Unary(op, _) => op.spec().is_call(),
        Node::Binary(op, ..) => op.spec().is_call(),
        Node::Pow(_, e) => pow_form(g, *e).is_call(),
        _ => false,
    }
}

/// A reciprocal `b⁻¹` used by at most [`MAX_DIVIDING_USERS`] products:
/// emitted as a division in each (`n₁ / b`, `n₂ / b`) rather than bound as
/// `1 / b` and multiplied. Two divisions cost about as much throughput as
/// one division and two multiplications, and take one multiplication off
/// the critical path (the division waits for `b`, the numerators do not).
fn shared_reciprocal(g: &Graph, node: &Node, uses: u32) -> bool {
    matches!(node, Node::Pow(_, e) if const_exponent(g, *e) == Some(-1.0))
        && (2..=MAX_DIVIDING_USERS).contains(&uses)
}

/// Users up to which a shared reciprocal is a division in each.
const MAX_DIVIDING_USERS: u32 = 2;

/// Operands that must be a name because the emitted form repeats them.
fn repeated_operand(g: &Graph, node: &Node) -> Option<Id> {
    match node {
        Node::Pow(b, e) if pow_form(g, *e).repeats_base() => Some(*b),
        _ => None,
    }
}

/// The evaluation plan of one function.
#[derive(Debug)]
pub struct Schedule {
    /// `live[i]`: node `i` is reachable from an output.
    pub live: Vec<bool>,
    /// `named[i]`: node `i` is bound by a `let` (symbols are always named).
    pub named: Vec<bool>,
    /// The `let`-bound nodes in arena (= evaluation) order.
    pub lets: Vec<Id>,
    /// Symbols reachable from the outputs, in symbol order.
    pub syms: Vec<Sym>,
}

impl Schedule {
    /// Plans the evaluation of `roots` by the interpreter
    /// ([`crate::eval::Tape`]): a value is named when it is used more than
    /// once or is a call.
    pub fn new(g: &Graph, roots: &[Id]) -> Schedule {
        Schedule::plan(g, roots, false)
    }

    /// Plans the emitted code of (lowered) `roots`: as [`Schedule::new`],
    /// and besides, a pure negation `(−1)·x` is never bound (each user
    /// writes `-x`, a free sign flip, and `x` counts its users' uses), and a
    /// value the model named ([`Graph::label`]) gets its `let`.
    pub fn for_code(g: &Graph, roots: &[Id]) -> Schedule {
        Schedule::plan(g, roots, true)
    }

    fn plan(g: &Graph, roots: &[Id], code: bool) -> Schedule {
        let n = roots.iter().map(|r| r.index() + 1).max().unwrap_or(0);
        let mut live = vec![false; n];
        let mut uses = vec![0u32; n];
        let mut negation = vec![false; n];
        for r in roots {
            live[r.index()] = true;
            uses[r.index()] += 1;
        }
        for i in (0..n).rev() {
            if live[i] {
                let id = Id(i as u32);
                let neg = code && negated(g, id).is_some();
                negation[i] = neg;
                // An inlined negation passes its users on to its operand.
                let weight = if neg { uses[i] } else { 1 };
                g.with_node(id, |node| {
                    node.for_each_child(|c| {
                        live[c.index()] = true;
                        uses[c.index()] += weight;
                    })
                });
            }
        }
        let mut named = vec![false; n];
        let mut syms = BTreeSet::new();
        for i in (0..n).rev() {
            if !live[i] {
                continue;
            }
            g.with_node(Id(i as u32), |node| {
                match node {
                    Node::Sym(s) => {
                        syms.insert(*s);
                        named[i] = true;
                    }
                    Node::Const(_) => {}
                    _ if shared_reciprocal(g, node, uses[i]) => {
                        // Divide in each of its two users (as a person
                        // writes Cramer's rule): the base is named instead.
                        if let Node::Pow(b, _) = node {
                            let atomic = g.with_node(*b, |n| matches!(n, Node::Const(_)));
                            named[b.index()] |= !atomic;
                        }
                    }
                    _ if negation[i] => {}
                    _ => {
                        named[i] |= uses[i] > 1
                            || expensive(g, node)
                            || (code && g.label(Id(i as u32)).is_some());
                    }
                }
                if let Some(a) = repeated_operand(g, node) {
                    let atomic = g.with_node(a, |n| matches!(n, Node::Const(_)));
                    named[a.index()] |= !atomic;
                }
            });
        }
        let lets = (0..n)
            .filter(|&i| named[i] && g.with_node(Id(i as u32), |n| !matches!(n, Node::Sym(_))))
            .map(|i| Id(i as u32))
            .collect();
        Schedule {
            live,
            named,
            lets,
            syms: syms.into_iter().collect(),
        }
    }

    /// True when `id` is referred to by name (a symbol or a `let`).
    pub fn is_named(&self, id: Id) -> bool {
        self.named[id.index()]
    }
}

/// The order in which the terms of a sum are added (left to right) by the
/// interpreter, and the order the lowering (`codegen::lower`) keeps between
/// its two groups in the emitted code: terms that are products of
/// parameters (with a constant coefficient) first, then the others, each
/// group in canonical order. Alike parameters (`r` and `−D/2`) then meet
/// before a small state-dependent term is added, so their difference is
/// exact when they are close (Sterbenz) instead of rounded at their size.
pub fn sum_order(g: &Graph, xs: &[Id]) -> Vec<Id> {
    let (mut first, rest): (Vec<Id>, Vec<Id>) = xs.iter().partition(|&&t| is_param_term(g, t));
    first.extend(rest);
    first
}

/// True for a sum term that is a product of parameters (with a constant
/// coefficient): the first group of [`sum_order`].
pub fn is_param_term(g: &Graph, t: Id) -> bool {
    crate::simplify::all_params(g, &crate::simplify::term_parts(g, t).1)
}

/// A sum evaluated as `common₁ · common₂ · … · (Σ cₖ · restₖ)`: every term
/// is a product holding all the `common` factors (`m1 l1 s + m2 l1 s` is
/// `l1 · s · (m1 + m2)`), which saves a multiplication per common factor
/// and term. The interpreter applies it to the canonical DAG's sums, the
/// emitter to the lowered ones (where the lowering's Horner pass has
/// already taken out most common factors).
#[derive(Clone, Debug, PartialEq)]
pub struct FactoredSum {
    /// The shared non-constant factors, in canonical order.
    pub common: Vec<Id>,
    /// Each term's coefficient and remaining factors, in the order of the
    /// terms given.
    pub rest: Vec<(f64, Vec<Id>)>,
}

/// The factored form of the sum of `xs` (in the order given), when every term
/// is a product that is not bound to a name (`named`: a `let` of the
/// emitter's [`Schedule`], whose value
/// is reused rather than recomputed) and they share at least one
/// non-constant factor.
pub fn factor_sum(g: &Graph, xs: &[Id], named: impl Fn(Id) -> bool) -> Option<FactoredSum> {
    if xs.len() < 2
        || !xs
            .iter()
            .all(|&t| !named(t) && matches!(g.node(t), Node::Mul(_)))
    {
        return None;
    }
    let parts: Vec<(f64, Vec<Id>)> = xs
        .iter()
        .map(|&t| crate::simplify::term_parts(g, t))
        .collect();
    let mut common = parts[0].1.clone();
    for (_, fs) in &parts[1..] {
        common.retain(|f| fs.contains(f));
    }
    if common.is_empty() {
        return None;
    }
    let rest = parts
        .into_iter()
        .map(|(c, fs)| (c, fs.into_iter().filter(|f| !common.contains(f)).collect()))
        .collect();
    Some(FactoredSum { common, rest })
}
