//! Small token helpers of the emitter: literals, identifiers, method names
//! and readable names for `let`s.

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

use super::emit::{Frag, Prec};
use super::schedule::const_exponent;
use crate::graph::{Graph, Id, Node, Sym, Unary};

/// The Rust keywords, strict and reserved (edition 2024), none of which
/// may name a model symbol or a generated `let`: the one list read by the
/// name check ([`super::verify::is_snake_ident`]) and the schedule's namer.
pub(crate) const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut",
    "pub", "ref", "return", "self", "static", "struct", "super", "trait", "true", "type", "unsafe",
    "use", "where", "while", "abstract", "become", "box", "do", "final", "macro", "override",
    "priv", "try", "typeof", "unsized", "virtual", "yield",
];

/// An `f64` literal of a finite, non-negative value.
pub(crate) fn lit(v: f64) -> Literal {
    Literal::f64_unsuffixed(v)
}

/// A `usize` literal without suffix.
pub(crate) fn ulit(n: usize) -> Literal {
    Literal::usize_unsuffixed(n)
}

/// An identifier.
pub(crate) fn ident(s: &str) -> Ident {
    Ident::new(s, Span::call_site())
}

/// The `pegdyn::scalar::Real` method implementing a transcendental function.
pub(crate) fn method(op: Unary) -> &'static str {
    match op {
        Unary::Sin => "sin",
        Unary::Cos => "cos",
        Unary::Tan => "tan",
        Unary::Asin => "asin",
        Unary::Acos => "acos",
        Unary::Atan => "atan",
        Unary::Exp => "exp",
        Unary::Expm1 => "exp_m1",
        Unary::Ln => "ln",
        Unary::Ln1p => "ln_1p",
        Unary::Tanh => "tanh",
        Unary::Abs => "abs",
        Unary::Sign => "sign",
        Unary::Max0 => "max0",
        Unary::Step => "step",
    }
}

/// A readable base name for a `let`: `sin_theta` for a function of a
/// symbol, `sqrt_x` for its root; `None` for a numbered temporary.
pub(crate) fn let_base(g: &Graph, node: &Node, sym_name: &dyn Fn(Sym) -> String) -> Option<String> {
    let sym = |a: Id| match g.node(a) {
        Node::Sym(s) => Some(sym_name(s)),
        _ => None,
    };
    match node {
        Node::Unary(op, a) => sym(*a).map(|s| format!("{}_{s}", method(*op))),
        Node::Pow(b, e) if const_exponent(g, *e) == Some(0.5) => {
            sym(*b).map(|s| format!("sqrt_{s}"))
        }
        _ => None,
    }
}

/// A constant of the scalar type `T`: `T::from_f64(c)`, negative ones as
/// `-T::from_f64(c)`.
pub(crate) fn constant(v: f64) -> Frag {
    let l = lit(v.abs());
    if v < 0.0 {
        Frag::new(quote!(-T::from_f64(#l)), Prec::Prefix)
    } else {
        Frag::new(quote!(T::from_f64(#l)), Prec::Atom)
    }
}

/// The constant 1 of the scalar type (numerator of a reciprocal).
pub(crate) fn one() -> TokenStream {
    quote!(T::from_f64(1.0))
}

/// A literal that may be negative, as tokens.
pub(crate) fn lit_signed(v: f64) -> TokenStream {
    constant(v).ts
}
