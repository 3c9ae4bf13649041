//! Scheduling: which nodes a function computes, which get a `let`, and the
//! Rust names of symbols and intermediate values.
//!
//! The nodes reachable from the outputs, taken in arena order, are already a
//! topological order (children first, see [`crate::graph`]). A node gets a
//! `let` when it is used more than once, when it is expensive (a function
//! call, a square root, a branch), or when its emitted form mentions its
//! operand more than once (`x * x` for `x²`). Every
//! other node is inlined into its single user. Each node is computed once.

use std::collections::BTreeSet;

use crate::graph::{Graph, Id, Node, PowForm, Sym};

/// The constant exponent of a power node, if any.
pub(crate) fn const_exponent(g: &Graph, e: Id) -> Option<f64> {
    g.expr(e).as_const()
}

/// How the power node `b^e` is computed ([`PowForm`]).
pub(crate) fn pow_form(g: &Graph, e: Id) -> PowForm {
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
                let neg = code && super::lower::sign::negated(g, id).is_some();
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

/// Names the generated code itself uses (besides the Rust keywords,
/// [`super::tokens::KEYWORDS`]), so no `let` may take them.
const GENERATED_NAMES: &[&str] = &["f64", "nalgebra"];

/// ASCII names of Greek letters (lower and upper case map to the same).
fn greek(c: char) -> Option<&'static str> {
    const LOWER: [&str; 25] = [
        "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
        "lambda", "mu", "nu", "xi", "omicron", "pi", "rho", "sigma", "sigma", "tau", "upsilon",
        "phi", "chi", "psi", "omega",
    ];
    let k = match c {
        'α'..='ω' => c as u32 - 'α' as u32,
        'Α'..='Ω' => c as u32 - 'Α' as u32,
        _ => return None,
    };
    LOWER.get(k as usize).copied()
}

/// A snake_case ASCII identifier for a symbol name: Greek letters spelled
/// out (`γ` → `gamma`), a combining dot as `dot`, camelCase split, anything
/// else as `_`.
pub fn snake_case(name: &str) -> String {
    let mut out = String::new();
    let mut prev_lower = false;
    for c in name.chars() {
        if let Some(w) = greek(c) {
            if prev_lower {
                out.push('_');
            }
            out.push_str(w);
            prev_lower = true;
        } else if c == '\u{307}' {
            out.push_str("dot");
            prev_lower = true;
        } else if c.is_ascii_uppercase() {
            if prev_lower {
                out.push('_');
            }
            out.push(c.to_ascii_lowercase());
            prev_lower = false;
        } else if c.is_ascii_alphanumeric() {
            out.push(c);
            prev_lower = c.is_ascii_lowercase() || c.is_ascii_digit();
        } else {
            out.push('_');
            prev_lower = false;
        }
    }
    let out = out.trim_matches('_').to_owned();
    match out.chars().next() {
        None => "s".to_owned(),
        Some(c) if c.is_ascii_digit() => format!("s{out}"),
        _ => out,
    }
}

/// Hands out identifiers unique within one function.
#[derive(Default)]
pub struct Names {
    taken: BTreeSet<String>,
    counter: usize,
}

impl Names {
    /// A name set that already holds `reserved` (e.g. the input names).
    pub fn new<'a>(reserved: impl IntoIterator<Item = &'a str>) -> Names {
        let mut taken: BTreeSet<String> = super::tokens::KEYWORDS
            .iter()
            .chain(GENERATED_NAMES)
            .map(|s| (*s).to_owned())
            .collect();
        taken.extend(reserved.into_iter().map(str::to_owned));
        Names { taken, counter: 0 }
    }

    /// The next free `{prefix}{k}`, k = 0, 1, 2, ...
    pub fn numbered(&mut self, prefix: &str) -> String {
        loop {
            let name = format!("{prefix}{}", self.counter);
            self.counter += 1;
            if self.taken.insert(name.clone()) {
                return name;
            }
        }
    }

    /// `base`, or `base_2`, `base_3`, ... whichever is free first.
    pub fn fresh(&mut self, base: &str) -> String {
        let mut name = base.to_owned();
        let mut k = 2;
        while self.taken.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        self.taken.insert(name.clone());
        name
    }
}
