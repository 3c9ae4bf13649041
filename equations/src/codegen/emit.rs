//! Emission of one function: `let` bindings in schedule order, then the
//! outputs, as a `proc_macro2::TokenStream`.
//!
//! Canonical forms are turned back into what a person would write: a sum
//! term with a negative coefficient becomes `a - b`, a factor `b^-n` becomes
//! a division, `x^0.5` becomes `x.sqrt()`, `x^(1/3)` becomes `x.cbrt()`, `x²` becomes
//! `x * x`. Code is
//! generic over the scalar `T: Real` of the runtime crate: constants are
//! `T::from_f64(c)`, functions are `Real` methods. Every function and power
//! is written and charged as its row of [`crate::graph::func`] says, the
//! table the interpreter evaluates with (`max0`, `step` and `sign`
//! propagate NaN). Operations are counted as they are emitted, so the
//! counts are those of the code.

use std::collections::HashMap;

use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;

use super::lower::product_key;
use super::names::{Names, snake_case};
use super::ops::OpCounts;
use super::tokens::{Frag, Prec, constant, ident, let_base, lit_signed, one};
use super::value_names::{ValueNames, scale_prefix};
use crate::graph::func::is_repeated_mul;
use crate::graph::{Graph, Id, Node, PowForm, Sym, Unary};
use crate::schedule::{Schedule, factor_sum, negated, pow_form};

/// Emits the expressions of one function.
pub struct Emitter<'a> {
    g: &'a Graph,
    sched: &'a Schedule,
    /// Rust name of each named node (symbols and `let`s), by node index.
    names: Vec<Option<Ident>>,
    /// Operations emitted so far.
    pub ops: OpCounts,
    /// Sine ↔ cosine bound together ([`sin_cos_partners`]).
    partner: HashMap<Id, Id>,
}

/// Sine and cosine of one argument that are both bound: emitted as one
/// `sin_cos` call. Each maps to its partner.
fn sin_cos_partners(g: &Graph, sched: &Schedule) -> HashMap<Id, Id> {
    let mut partner = HashMap::new();
    for &id in &sched.lets {
        let Node::Unary(Unary::Sin, u) = g.node(id) else {
            continue;
        };
        if let Some(c) = g.find(&Node::Unary(Unary::Cos, u))
            && c.index() < sched.live.len()
            && sched.live[c.index()]
            && sched.is_named(c)
        {
            partner.insert(id, c);
            partner.insert(c, id);
        }
    }
    partner
}

/// Two terms `−a + b` written `b − a`: the positive one leads (exact, a
/// two-term sum is commutative in floating point).
fn positive_first(terms: &mut [(bool, Frag)]) {
    if terms.len() == 2 && terms[0].0 && !terms[1].0 {
        terms.swap(0, 1);
    }
}

/// Named products by their sorted leaf factors ([`product_key`]): the
/// coefficient of the named product and its name.
type ProductNames = HashMap<Vec<Id>, (f64, String)>;

/// The model's named products, so that a lowered product with the same
/// leaves (grouped otherwise by the lowering, or scaled) finds its name.
fn labelled_products(g: &Graph) -> ProductNames {
    let mut out = HashMap::new();
    for (id, label) in g.labels() {
        if let Some((c, fs)) = product_key(g, id) {
            out.entry(fs).or_insert((c, label));
        }
    }
    out
}

/// The model's name for the value `id` (snake_case): its own label, or
/// that of a named product with the same leaves, prefixed by the scale
/// between them (`neg_<name>` for its negation, `half_<name>`, …).
fn model_name(g: &Graph, id: Id, products: &ProductNames) -> Option<String> {
    if let Some(l) = g.label(id) {
        return Some(snake_case(&l));
    }
    let (c, fs) = product_key(g, id)?;
    let (c0, l) = products.get(&fs)?;
    Some(format!("{}{}", scale_prefix(c / c0)?, snake_case(l)))
}

impl<'a> Emitter<'a> {
    /// An emitter for `sched`; `sym_name` gives the local name of each symbol.
    ///
    /// A `let` is called by the model's name for its value
    /// ([`Graph::label`], made a fresh snake_case identifier), else
    /// `sin_x`, `cos_x`, `sqrt_x` for a function of a symbol or of a value
    /// with a model name `x`, else `t0`, `t1`, ... in evaluation order; a
    /// sine and cosine bound together are named sine first.
    pub fn new(
        g: &'a Graph,
        sched: &'a Schedule,
        names: &mut Names,
        sym_name: &dyn Fn(Sym) -> String,
    ) -> Emitter<'a> {
        let partner = sin_cos_partners(g, sched);
        let by_product = labelled_products(g);
        let by_value = ValueNames::new(g, &sched.lets);
        let mut out: Vec<Option<Ident>> = vec![None; sched.live.len()];
        // Readable names (symbols, model names and functions of them).
        let mut readable: HashMap<Id, String> = HashMap::new();
        for i in 0..out.len() {
            let id = Id(i as u32);
            if !sched.named[i] || out[i].is_some() {
                continue;
            }
            let mut group = vec![id];
            if let Some(&other) = partner.get(&id) {
                group = match g.node(id) {
                    Node::Unary(Unary::Sin, _) => vec![id, other],
                    _ => vec![other, id],
                };
            }
            for id in group {
                let node = g.node(id);
                let name = match &node {
                    Node::Sym(s) => {
                        let n = sym_name(*s);
                        readable.insert(id, n.clone());
                        n
                    }
                    node => {
                        let base = model_name(g, id, &by_product)
                            .or_else(|| by_value.get(id).map(str::to_owned))
                            .or_else(|| {
                                let arg = |a: Id| readable.get(&a).cloned();
                                let_base(g, node, &arg)
                            });
                        match base {
                            Some(base) => {
                                let n = names.fresh(&base);
                                readable.insert(id, n.clone());
                                n
                            }
                            None => names.numbered("t"),
                        }
                    }
                };
                out[id.index()] = Some(ident(&name));
            }
        }
        Emitter {
            g,
            sched,
            names: out,
            ops: OpCounts::default(),
            partner,
        }
    }

    /// The local name of a named node.
    pub fn name(&self, id: Id) -> &Ident {
        self.names[id.index()].as_ref().expect("node is not named")
    }

    /// `let name = value;` for every scheduled `let`, in order. A `sin u`
    /// and a `cos u` that are both bound become one
    /// `let (sin_u, cos_u) = u.sin_cos();` at the place of the first (both
    /// depend only on `u`, bound earlier), counted as one transcendental
    /// call.
    pub fn lets(&mut self) -> Vec<TokenStream> {
        let sched = self.sched;
        let g = self.g;
        let mut out = Vec::with_capacity(sched.lets.len());
        for &id in &sched.lets {
            let Some(&other) = self.partner.get(&id) else {
                let value = self.node(id).ts;
                let name = self.name(id);
                out.push(quote!(let #name = #value;));
                continue;
            };
            if other < id {
                continue; // emitted with its partner
            }
            let (sin, cos) = match g.node(id) {
                Node::Unary(Unary::Sin, _) => (id, other),
                _ => (other, id),
            };
            let Node::Unary(_, u) = g.node(sin) else {
                unreachable!("paired node is a sine");
            };
            self.ops.transcendental += 1;
            let x = self.frag(u).at(Prec::Atom);
            let (s, c) = (self.name(sin), self.name(cos));
            out.push(quote!(let (#s, #c) = #x.sin_cos();));
        }
        out
    }

    /// The expression for `id`: its name if named, else the node inlined.
    pub fn expr(&mut self, id: Id) -> TokenStream {
        self.frag(id).ts
    }

    fn frag(&mut self, id: Id) -> Frag {
        if let Some(name) = &self.names[id.index()] {
            return Frag::new(quote!(#name), Prec::Atom);
        }
        self.node(id)
    }

    /// The node itself (never its name).
    fn node(&mut self, id: Id) -> Frag {
        let g = self.g;
        match g.node(id) {
            Node::Const(c) => constant(c.value()),
            Node::Sym(_) => {
                let name = self.name(id);
                Frag::new(quote!(#name), Prec::Atom)
            }
            // Lowered sums are already in evaluation order (`lower::horner`).
            Node::Add(xs) => self.sum(&xs),
            Node::Mul(xs) => match self.negated_sum(id) {
                Some(f) => f,
                None => self.product(&xs, None),
            },
            Node::Pow(b, e) => self.power(b, e),
            Node::Unary(op, a) => self.unary(op, a),
            Node::Binary(op, a, b) => {
                let spec = op.spec();
                self.ops.charge(spec.cost);
                let a = self.frag(a).at(Prec::Atom);
                let b = self.frag(b).ts;
                let m = ident(spec.method);
                Frag::new(quote!(#a.#m(#b)), Prec::Atom)
            }
        }
    }

    /// A sum, terms in the given order; negative-coefficient
    /// terms subtracted; common factors taken out as
    /// [`factor_sum`] says (as the interpreter does).
    fn sum(&mut self, xs: &[Id]) -> Frag {
        let sched = self.sched;
        let Some(f) = factor_sum(self.g, xs, |t| sched.is_named(t)) else {
            let mut terms: Vec<(bool, Frag)> = xs.iter().map(|&x| self.signed_term(x)).collect();
            positive_first(&mut terms);
            return self.signed_sum(terms);
        };
        let terms: Vec<(bool, Frag)> = f
            .rest
            .iter()
            .map(|(c, rest)| (*c < 0.0, self.product(rest, Some(c.abs()))))
            .collect();
        let inner = self.signed_sum(terms).at(Prec::Atom);
        let mut ts = TokenStream::new();
        for (k, &c) in f.common.iter().enumerate() {
            let c = self.frag(c).at(Prec::Prefix);
            ts = if k == 0 { c } else { quote!(#ts * #c) };
        }
        self.ops.mul += f.common.len();
        Frag::new(quote!(#ts * #inner), Prec::Product)
    }

    /// The negation `(−1)·S` of an inlined sum written with its terms'
    /// signs flipped (`b - a` for `−(a − b)`; two terms swap so that the
    /// positive one leads, which is exact), when `S` is not factored.
    fn negated_sum(&mut self, id: Id) -> Option<Frag> {
        let s = negated(self.g, id)?;
        if self.sched.is_named(s) {
            return None;
        }
        let Node::Add(xs) = self.g.node(s) else {
            return None;
        };
        let sched = self.sched;
        if factor_sum(self.g, &xs, |t| sched.is_named(t)).is_some() {
            return None;
        }
        let mut terms: Vec<(bool, Frag)> = xs
            .iter()
            .map(|&x| {
                let (neg, f) = self.signed_term(x);
                (!neg, f)
            })
            .collect();
        positive_first(&mut terms);
        Some(self.signed_sum(terms))
    }

    /// `t₁ ± t₂ ± …` from (is negative, magnitude) pairs.
    fn signed_sum(&mut self, terms: Vec<(bool, Frag)>) -> Frag {
        let mut ts = TokenStream::new();
        for (k, (negative, term)) in terms.into_iter().enumerate() {
            if k > 0 {
                self.ops.add += 1;
            }
            ts = match (k, negative) {
                (0, false) => term.at(Prec::Sum),
                (0, true) => {
                    let t = term.at(Prec::Prefix);
                    quote!(-#t)
                }
                (_, false) => {
                    let t = term.at(Prec::Sum);
                    quote!(#ts + #t)
                }
                (_, true) => {
                    let t = term.at(Prec::Product);
                    quote!(#ts - #t)
                }
            };
        }
        Frag::new(ts, Prec::Sum)
    }

    /// A sum term as (is negative, magnitude).
    fn signed_term(&mut self, x: Id) -> (bool, Frag) {
        if self.sched.is_named(x) {
            return (false, self.frag(x));
        }
        match self.g.node(x) {
            Node::Const(c) if c.value() < 0.0 => (true, constant(-c.value())),
            Node::Mul(fs) => match self.g.expr(fs[0]).as_const() {
                Some(c) if c < 0.0 => (true, self.product(&fs[1..], Some(-c))),
                _ => (false, self.product(&fs, None)),
            },
            _ => (false, self.node(x)),
        }
    }

    /// A product `c * n1 * n2 / (d1 * d2)`. `coeff` overrides a leading
    /// constant factor (already removed from `fs`).
    fn product(&mut self, fs: &[Id], coeff: Option<f64>) -> Frag {
        let mut c = coeff.unwrap_or(1.0);
        let mut num: Vec<Frag> = Vec::new();
        let mut den: Vec<Frag> = Vec::new();
        for (k, &f) in fs.iter().enumerate() {
            if k == 0
                && coeff.is_none()
                && let Some(v) = self.g.expr(f).as_const()
            {
                c = v;
                continue;
            }
            match self.denominator(f) {
                Some(d) => den.push(d),
                None => num.push(self.frag(f)),
            }
        }
        let negative = c < 0.0;
        if c.abs() != 1.0 || num.is_empty() {
            num.insert(0, constant(c.abs()));
        }
        self.ops.mul += num.len() - 1 + den.len().saturating_sub(1);
        let mut it = num.into_iter();
        let first = it.next().map(|f| {
            f.at(if negative {
                Prec::Prefix
            } else {
                Prec::Product
            })
        });
        let mut ts = if negative {
            quote!(-#first)
        } else {
            quote!(#first)
        };
        let mut prec = if negative { Prec::Prefix } else { Prec::Atom };
        for f in it {
            let f = f.at(Prec::Prefix);
            ts = quote!(#ts * #f);
            prec = Prec::Product;
        }
        if !den.is_empty() {
            self.ops.div += 1;
            let d = if den.len() == 1 {
                den.pop().map(|d| d.at(Prec::Atom))
            } else {
                let mut it = den.into_iter().map(|d| d.at(Prec::Prefix));
                let first = it.next();
                let mut d = quote!(#first);
                for f in it {
                    d = quote!(#d * #f);
                }
                Some(quote!((#d)))
            };
            ts = quote!(#ts / #d);
            prec = Prec::Product;
        }
        Frag::new(ts, prec)
    }

    /// `Some(b^n)` when factor `f` is an inlined `b^-n` for an integer `n`.
    fn denominator(&mut self, f: Id) -> Option<Frag> {
        if self.sched.is_named(f) {
            return None;
        }
        let Node::Pow(b, e) = self.g.node(f) else {
            return None;
        };
        match pow_form(self.g, e) {
            PowForm::Int(n) if n < 0 => Some(self.int_power(b, n.unsigned_abs())),
            _ => None,
        }
    }

    /// `b^n` for an integer `n >= 1`, charged as [`PowForm::Int`].
    fn int_power(&mut self, b: Id, n: u32) -> Frag {
        let base = self.frag(b);
        self.ops.charge(PowForm::Int(n as i32).cost());
        if n == 1 {
            return base;
        }
        let base = base.at(Prec::Atom);
        if is_repeated_mul(n) {
            let tail = (1..n).map(|_| quote!(* #base));
            return Frag::new(quote!(#base #(#tail)*), Prec::Product);
        }
        let n = Literal::u32_unsuffixed(n);
        Frag::new(quote!(#base.powi(#n)), Prec::Atom)
    }

    /// `b^e` standing alone (not a denominator of a product), in the form
    /// [`PowForm`] gives.
    fn power(&mut self, b: Id, e: Id) -> Frag {
        let form = pow_form(self.g, e);
        if let PowForm::Int(k) = form {
            if k >= 0 {
                return self.int_power(b, k as u32);
            }
            self.ops.div += 1;
            let d = self.int_power(b, k.unsigned_abs()).at(Prec::Atom);
            let one = one();
            return Frag::new(quote!(#one / #d), Prec::Product);
        }
        self.ops.charge(form.cost());
        let base = self.frag(b).at(Prec::Atom);
        let one = one();
        match form {
            PowForm::Sqrt => Frag::new(quote!(#base.sqrt()), Prec::Atom),
            PowForm::RecipSqrt => Frag::new(quote!(#one / #base.sqrt()), Prec::Product),
            PowForm::SqrtCubed => Frag::new(quote!(#base * #base.sqrt()), Prec::Product),
            PowForm::Cbrt => Frag::new(quote!(#base.cbrt()), Prec::Atom),
            PowForm::CbrtSquared => Frag::new(quote!(#base.cbrt().powi(2)), Prec::Atom),
            PowForm::Powf(Some(n)) => {
                let n = lit_signed(n);
                Frag::new(quote!(#base.powf(#n)), Prec::Atom)
            }
            PowForm::Powf(None) | PowForm::Int(_) => {
                let e = self.frag(e).ts;
                Frag::new(quote!(#base.powf(#e)), Prec::Atom)
            }
        }
    }

    /// A one-argument function as the `Real` method of its table row
    /// ([`Unary::spec`]), charged the row's cost.
    fn unary(&mut self, op: Unary, a: Id) -> Frag {
        let spec = op.spec();
        self.ops.charge(spec.cost);
        let x = self.frag(a).at(Prec::Atom);
        let m = ident(spec.method);
        Frag::new(quote!(#x.#m()), Prec::Atom)
    }
}
