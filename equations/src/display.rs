//! Infix printing that reads like the paper: `m*l^2*thetadot^2/2 - m*g*l*cos(theta)`.

use std::fmt::Write;

use crate::graph::{Binary, Graph, Id, Node, Unary};

/// Binding strength, loosest first.
#[derive(Clone, Copy, PartialEq, PartialOrd)]
enum Prec {
    Sum,
    Product,
    Power,
    Atom,
}

fn prec(n: &Node) -> Prec {
    match n {
        Node::Add(_) => Prec::Sum,
        Node::Mul(_) => Prec::Product,
        Node::Pow(..) => Prec::Power,
        Node::Const(c) if c.value() < 0.0 => Prec::Sum,
        _ => Prec::Atom,
    }
}

/// Name of a one-argument function as printed.
pub fn unary_name(op: Unary) -> &'static str {
    match op {
        Unary::Sin => "sin",
        Unary::Cos => "cos",
        Unary::Tan => "tan",
        Unary::Asin => "asin",
        Unary::Acos => "acos",
        Unary::Atan => "atan",
        Unary::Exp => "exp",
        Unary::Expm1 => "expm1",
        Unary::Ln => "ln",
        Unary::Ln1p => "ln1p",
        Unary::Abs => "abs",
        Unary::Sign => "sign",
        Unary::Tanh => "tanh",
        Unary::Max0 => "max0",
        Unary::Step => "step",
    }
}

/// Name of a two-argument function as printed.
pub fn binary_name(op: Binary) -> &'static str {
    match op {
        Binary::Atan2 => "atan2",
        Binary::Hypot => "hypot",
    }
}

/// The expression `id` in infix notation.
pub fn infix(g: &Graph, id: Id) -> String {
    let mut s = String::new();
    write_expr(g, id, Prec::Sum, &mut s);
    s
}

fn write_expr(g: &Graph, id: Id, ctx: Prec, s: &mut String) {
    let node = g.node(id);
    let paren = prec(&node) < ctx;
    if paren {
        s.push('(');
    }
    match &node {
        Node::Const(c) => {
            let _ = write!(s, "{}", c.value());
        }
        Node::Sym(sym) => s.push_str(&g.sym_info(*sym).name),
        Node::Add(xs) => {
            for (k, &x) in xs.iter().enumerate() {
                let (c, base) = crate::simplify::split_coeff(g, x);
                if c < 0.0 {
                    s.push_str(if k == 0 { "-" } else { " - " });
                    let pos = crate::simplify::scale(g, -c, base);
                    write_expr(g, pos, Prec::Product, s);
                } else {
                    if k > 0 {
                        s.push_str(" + ");
                    }
                    write_expr(g, x, Prec::Sum, s);
                }
            }
        }
        Node::Mul(xs) => {
            let mut num = Vec::new();
            let mut den = Vec::new();
            for &x in xs.iter() {
                match g.node(x) {
                    Node::Pow(b, e) if g.expr(e).as_const().is_some_and(|v| v < 0.0) => {
                        let v = g.expr(e).as_const().unwrap_or(-1.0);
                        den.push(if v == -1.0 { b } else { crate::simplify::pow(g, b, g.constant(-v).id()) });
                    }
                    _ => num.push(x),
                }
            }
            if num.is_empty() {
                s.push('1');
            }
            for (k, &x) in num.iter().enumerate() {
                if k > 0 {
                    s.push('*');
                }
                write_expr(g, x, Prec::Power, s);
            }
            for &x in &den {
                s.push('/');
                write_expr(g, x, Prec::Atom, s);
            }
        }
        Node::Pow(b, e) => {
            if g.expr(*e).as_const() == Some(0.5) {
                s.push_str("sqrt(");
                write_expr(g, *b, Prec::Sum, s);
                s.push(')');
            } else {
                write_expr(g, *b, Prec::Atom, s);
                s.push('^');
                write_expr(g, *e, Prec::Atom, s);
            }
        }
        Node::Unary(op, a) => {
            let _ = write!(s, "{}(", unary_name(*op));
            write_expr(g, *a, Prec::Sum, s);
            s.push(')');
        }
        Node::Binary(op, a, b) => {
            let _ = write!(s, "{}(", binary_name(*op));
            write_expr(g, *a, Prec::Sum, s);
            s.push_str(", ");
            write_expr(g, *b, Prec::Sum, s);
            s.push(')');
        }
    }
    if paren {
        s.push(')');
    }
}
