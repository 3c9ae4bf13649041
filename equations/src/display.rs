//! Infix printing that reads like the paper:
//! `m*l^2*thetadot^2/2 - m*g*l*cos(theta)`.
//!
//! The canonical forms are turned back into what a person writes: a term
//! with a negative coefficient prints as `- …`, `(-1)*x` as `-x`, factors
//! with negative exponents go to a denominator (`a/(b*c)`), a coefficient
//! `1/k` for an integer `k` prints as `/k`, and `x^0.5` as `sqrt(x)`.
//! Parentheses appear only where precedence needs them (`^` binds tighter
//! than `*` and `/`, which bind tighter than `+`, `-` and a leading minus).
//! Printing never adds nodes to the graph and depends only on the DAG, so
//! it is deterministic.
//!
//! ```
//! use pegdyn_equations::Graph;
//! let g = Graph::new();
//! let (theta, w) = (g.var("theta"), g.var("thetadot"));
//! let (m, l, gr) = (g.param("m"), g.param("l"), g.param("g"));
//! let lagrangian = 0.5 * m * (l * w).square() + m * gr * l * theta.cos();
//! assert_eq!(lagrangian.diff(theta).to_string(), "-m*l*g*sin(theta)");
//! assert_eq!((m - l).to_string(), "m - l");
//! assert_eq!(((m - l) / gr).to_string(), "(m - l)/g");
//! ```

use std::fmt::Write;

use crate::graph::{Binary, Graph, Id, Node, Unary};
use crate::simplify::term_parts;

/// Binding strength, loosest first.
#[derive(Clone, Copy, PartialEq, PartialOrd)]
enum Prec {
    /// `a + b`, `a - b`, and a leading minus.
    Sum,
    /// `a*b`, `a/b`.
    Product,
    /// `a^b`.
    Power,
    /// Symbols, numbers, function calls.
    Atom,
}

/// Name of a one-argument function as printed ([`Unary::spec`]).
pub fn unary_name(op: Unary) -> &'static str {
    op.spec().name
}

/// Name of a two-argument function as printed ([`Binary::spec`]).
pub fn binary_name(op: Binary) -> &'static str {
    op.spec().name
}

/// The expression `id` in infix notation.
pub fn infix(g: &Graph, id: Id) -> String {
    let mut s = String::new();
    write_expr(g, id, Prec::Sum, &mut s);
    s
}

/// A number as printed: shortest round-trip digits, exponent notation only
/// for very small or very large magnitudes.
pub fn number(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 || (1e-4..1e16).contains(&a) || !a.is_finite() {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// A product split for printing: `sign·coeff · num / den`, where each
/// denominator entry is a base with its (positive) exponent.
struct Fraction {
    coeff: f64,
    num: Vec<Id>,
    den: Vec<(Id, f64)>,
}

/// The fraction view of a product or of a power with a negative constant
/// exponent; `None` for any other node.
fn fraction(g: &Graph, id: Id) -> Option<Fraction> {
    let neg_exp = |f: Id| match g.node(f) {
        Node::Pow(b, e) => match g.node(e) {
            Node::Const(c) if c.value() < 0.0 => Some((b, -c.value())),
            _ => None,
        },
        _ => None,
    };
    match g.node(id) {
        Node::Mul(_) => {
            let (coeff, fs) = term_parts(g, id);
            let (mut num, mut den) = (Vec::new(), Vec::new());
            for f in fs {
                match neg_exp(f) {
                    Some(d) => den.push(d),
                    None => num.push(f),
                }
            }
            Some(Fraction { coeff, num, den })
        }
        Node::Pow(..) => neg_exp(id).map(|d| Fraction {
            coeff: 1.0,
            num: Vec::new(),
            den: vec![d],
        }),
        _ => None,
    }
}

fn prec(g: &Graph, id: Id) -> Prec {
    if let Some(f) = fraction(g, id) {
        return if f.coeff < 0.0 {
            Prec::Sum
        } else {
            Prec::Product
        };
    }
    match g.node(id) {
        Node::Add(_) => Prec::Sum,
        Node::Const(c) if c.value() < 0.0 => Prec::Sum,
        Node::Pow(_, e) if g.expr(e).as_const() != Some(0.5) => Prec::Power,
        _ => Prec::Atom,
    }
}

fn write_expr(g: &Graph, id: Id, ctx: Prec, s: &mut String) {
    let paren = prec(g, id) < ctx;
    if paren {
        s.push('(');
    }
    if let Some(f) = fraction(g, id) {
        write_fraction(g, &f, s);
    } else {
        match g.node(id) {
            Node::Const(c) => s.push_str(&number(c.value())),
            Node::Sym(sym) => s.push_str(&g.sym_info(sym).name),
            Node::Add(xs) => write_sum(g, &xs, s),
            Node::Mul(_) => unreachable!("products print as fractions"),
            Node::Pow(b, e) => match g.expr(e).as_const() {
                Some(v) => write_power(g, b, v, s),
                None => {
                    write_expr(g, b, Prec::Atom, s);
                    s.push('^');
                    write_expr(g, e, Prec::Atom, s);
                }
            },
            Node::Unary(op, a) => {
                let _ = write!(s, "{}(", unary_name(op));
                write_expr(g, a, Prec::Sum, s);
                s.push(')');
            }
            Node::Binary(op, a, b) => {
                let _ = write!(s, "{}(", binary_name(op));
                write_expr(g, a, Prec::Sum, s);
                s.push_str(", ");
                write_expr(g, b, Prec::Sum, s);
                s.push(')');
            }
        }
    }
    if paren {
        s.push(')');
    }
}

/// `b^e` for a constant exponent `e > 0`: `b`, `sqrt(b)` or `b^e`.
fn write_power(g: &Graph, b: Id, e: f64, s: &mut String) {
    if e == 1.0 {
        write_expr(g, b, Prec::Power, s);
    } else if e == 0.5 {
        s.push_str("sqrt(");
        write_expr(g, b, Prec::Sum, s);
        s.push(')');
    } else {
        write_expr(g, b, Prec::Atom, s);
        s.push('^');
        if e < 0.0 {
            let _ = write!(s, "({})", number(e));
        } else {
            s.push_str(&number(e));
        }
    }
}

fn write_sum(g: &Graph, xs: &[Id], s: &mut String) {
    for (k, &x) in xs.iter().enumerate() {
        let negative = match fraction(g, x) {
            Some(f) if f.coeff < 0.0 => {
                s.push_str(if k == 0 { "-" } else { " - " });
                write_fraction(
                    g,
                    &Fraction {
                        coeff: -f.coeff,
                        ..f
                    },
                    s,
                );
                true
            }
            _ => false,
        };
        if negative {
            continue;
        }
        match g.expr(x).as_const() {
            Some(v) if v < 0.0 => {
                s.push_str(if k == 0 { "-" } else { " - " });
                s.push_str(&number(-v));
            }
            _ => {
                if k > 0 {
                    s.push_str(" + ");
                }
                write_expr(g, x, Prec::Sum, s);
            }
        }
    }
}

/// The integer `k` when `c == 1/k` exactly, for printing `x/k`.
fn reciprocal_integer(c: f64) -> Option<f64> {
    let k = (1.0 / c).round();
    (k > 1.0 && k < 1e6 && 1.0 / k == c).then_some(k)
}

fn write_fraction(g: &Graph, f: &Fraction, s: &mut String) {
    let mut c = f.coeff;
    if c < 0.0 {
        s.push('-');
        c = -c;
    }
    let k = reciprocal_integer(c);
    let mut first = true;
    if k.is_none() && (c != 1.0 || f.num.is_empty()) {
        s.push_str(&number(c));
        first = false;
    } else if f.num.is_empty() {
        s.push('1');
        first = false;
    }
    for &x in &f.num {
        if !first {
            s.push('*');
        }
        first = false;
        write_expr(g, x, Prec::Power, s);
    }
    let n_den = f.den.len() + usize::from(k.is_some());
    if n_den == 0 {
        return;
    }
    s.push('/');
    if n_den > 1 {
        s.push('(');
    }
    let mut first = true;
    if let Some(k) = k {
        s.push_str(&number(k));
        first = false;
    }
    for &(b, e) in &f.den {
        if !first {
            s.push('*');
        }
        first = false;
        write_power(g, b, e, s);
    }
    if n_den > 1 {
        s.push(')');
    }
}
