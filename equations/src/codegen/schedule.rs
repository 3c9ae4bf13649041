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

use crate::graph::{Graph, Id, Node, Sym, Unary};

/// The constant exponent of a power node, if any.
pub(crate) fn const_exponent(g: &Graph, e: Id) -> Option<f64> {
    g.expr(e).as_const()
}

/// Integer powers emitted as repeated multiplication (`x * x`, `x * x * x`).
pub(crate) fn is_repeated_mul(n: f64) -> bool {
    n.abs() == 2.0 || n.abs() == 3.0
}

/// Integer exponents emitted with `powi` (or multiplication / division).
pub(crate) fn as_integer(n: f64) -> Option<i32> {
    (n.fract() == 0.0 && n.abs() <= 64.0).then_some(n as i32)
}

/// Nodes that always get a `let`: calls, roots, branches.
fn expensive(g: &Graph, node: &Node) -> bool {
    match node {
        Node::Unary(op, _) => *op != Unary::Abs,
        Node::Binary(..) => true,
        Node::Pow(_, e) => const_exponent(g, *e).and_then(as_integer).is_none(),
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
        Node::Pow(b, e) => match const_exponent(g, *e) {
            Some(n) if is_repeated_mul(n) || n == 1.5 => Some(*b),
            _ => None,
        },
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
    /// Plans the evaluation of `roots`.
    pub fn new(g: &Graph, roots: &[Id]) -> Schedule {
        let n = roots.iter().map(|r| r.index() + 1).max().unwrap_or(0);
        let mut live = vec![false; n];
        let mut uses = vec![0u32; n];
        for r in roots {
            live[r.index()] = true;
            uses[r.index()] += 1;
        }
        for i in (0..n).rev() {
            if live[i] {
                g.with_node(Id(i as u32), |node| {
                    node.for_each_child(|c| {
                        live[c.index()] = true;
                        uses[c.index()] += 1;
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
                    _ => named[i] |= uses[i] > 1 || expensive(g, node),
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
