//! Small token helpers of the emitter: emitted fragments with their binding
//! strength, literals, identifiers, method names and readable names for
//! `let`s.

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

use crate::graph::{Graph, Id, Node, PowForm};
use crate::schedule::pow_form;

/// Binding strength of an emitted fragment, loosest first.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
pub(crate) enum Prec {
    /// `a + b`, `a - b`
    Sum,
    /// `a * b`, `a / b`
    Product,
    /// `-a`
    Prefix,
    /// names, literals, calls, parenthesized expressions
    Atom,
}

/// An emitted expression and how tightly it binds.
pub(crate) struct Frag {
    pub(crate) ts: TokenStream,
    prec: Prec,
}

impl Frag {
    pub(crate) fn new(ts: TokenStream, prec: Prec) -> Frag {
        Frag { ts, prec }
    }

    /// The tokens, parenthesized if they bind looser than `min`.
    pub(crate) fn at(self, min: Prec) -> TokenStream {
        let ts = self.ts;
        if self.prec < min { quote!((#ts)) } else { ts }
    }
}

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

/// A readable base name for a `let`: `sin_theta` for a function of a
/// value with a readable name (`arg`: a symbol or a model-named value),
/// `sqrt_x` for its root; `None` for a numbered temporary.
pub(crate) fn let_base(
    g: &Graph,
    node: &Node,
    arg: &dyn Fn(Id) -> Option<String>,
) -> Option<String> {
    match node {
        Node::Unary(op, a) => arg(*a).map(|s| format!("{}_{s}", op.spec().method)),
        Node::Pow(b, e) if pow_form(g, *e) == PowForm::Sqrt => arg(*b).map(|s| format!("sqrt_{s}")),
        _ => None,
    }
}

/// A constant of the scalar type `T`: `T::from_f64(c)`, negative ones as
/// `-T::from_f64(c)`; an exact small rational whose decimal form is long
/// as `T::from_f64(1.0 / 12.0)` (the same `f64`: the division of two exact
/// integers rounds once, as the literal does).
pub(crate) fn constant(v: f64) -> Frag {
    let a = v.abs();
    let value = match rational(a) {
        Some((p, q)) => {
            let (p, q) = (lit(p as f64), lit(q as f64));
            quote!(#p / #q)
        }
        None => {
            let l = lit(a);
            quote!(#l)
        }
    };
    if v < 0.0 {
        Frag::new(quote!(-T::from_f64(#value)), Prec::Prefix)
    } else {
        Frag::new(quote!(T::from_f64(#value)), Prec::Atom)
    }
}

/// Denominators tried for a rational constant.
const MAX_DENOMINATOR: u32 = 1000;
/// Decimal forms up to this many characters print as they are (`0.5`,
/// `0.125`, `1.25`).
const SHORT_DECIMAL: usize = 8;

/// `Some((p, q))` when `a ≥ 0` is exactly the `f64` nearest `p / q` for a
/// small denominator `q > 1` (smallest first) and its decimal form is long.
fn rational(a: f64) -> Option<(u32, u32)> {
    if format!("{a}").len() <= SHORT_DECIMAL {
        return None;
    }
    (2..=MAX_DENOMINATOR).find_map(|q| {
        let p = (a * f64::from(q)).round();
        ((1.0..1e6).contains(&p) && p / f64::from(q) == a).then_some((p as u32, q))
    })
}

/// The constant 1 of the scalar type (numerator of a reciprocal).
pub(crate) fn one() -> TokenStream {
    quote!(T::from_f64(1.0))
}

/// A literal that may be negative, as tokens.
pub(crate) fn lit_signed(v: f64) -> TokenStream {
    constant(v).ts
}
