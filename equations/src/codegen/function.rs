//! Emission of one verified [`FnSpec`] as a `pub fn`: doc comment with the
//! paper reference and operation counts, input bindings, `let`s, outputs.

use std::collections::{BTreeMap, BTreeSet};

use proc_macro2::TokenStream;
use quote::quote;

use super::emit::Emitter;
use super::names::{Names, snake_case};
use super::ops::ReportRow;
use super::tokens::{ident, ulit};
use crate::graph::{Graph, Id, Sym};
use crate::model::{FnSpec, Output};
use crate::schedule::Schedule;

/// The nalgebra type names a module's code mentions (for its `use`).
#[derive(Clone, Default)]
pub struct Uses(pub BTreeSet<&'static str>, pub BTreeSet<String>);

impl Uses {
    pub(crate) fn ty(&mut self, name: &'static str) {
        self.0.insert(name);
    }
    fn alias(&mut self, name: String) -> TokenStream {
        let id = ident(&name);
        self.1.insert(name);
        quote!(#id)
    }
    /// All names, sorted.
    pub fn names(&self) -> Vec<String> {
        let mut v: Vec<String> = self
            .0
            .iter()
            .map(|s| (*s).to_owned())
            .chain(self.1.iter().cloned())
            .collect();
        v.sort();
        v
    }
}

/// The Rust type of an output.
pub(crate) fn output_type(out: &Output, uses: &mut Uses) -> TokenStream {
    match out {
        Output::Scalar(_) => quote!(T),
        Output::Vector(v) => {
            uses.ty("SVector");
            let n = ulit(v.len());
            quote!(SVector<T, #n>)
        }
        Output::Matrix { .. } | Output::Symmetric { .. } => {
            uses.ty("SMatrix");
            let (r, c) = out.shape();
            let (r, c) = (ulit(r), ulit(c));
            quote!(SMatrix<T, #r, #c>)
        }
    }
}

/// The expression that builds an output from its entries (row-major):
/// nalgebra's `Vector3::new(..)` / `Matrix2x3::new(..)` up to 6×6,
/// `SMatrix::<T, R, C>::from_row_slice(&[..])` beyond; no allocation.
fn output_value(out: &Output, entries: Vec<TokenStream>, uses: &mut Uses) -> TokenStream {
    let (r, c) = out.shape();
    if let Output::Scalar(_) = out {
        return quote!(#(#entries)*);
    }
    if r <= 6 && c <= 6 {
        let alias = match out {
            Output::Vector(_) => format!("Vector{r}"),
            _ if r == c => format!("Matrix{r}"),
            _ => format!("Matrix{r}x{c}"),
        };
        let ty = uses.alias(alias);
        return quote!(#ty::new(#(#entries),*));
    }
    uses.ty("SMatrix");
    let (rl, cl) = (ulit(r), ulit(c));
    quote!(SMatrix::<T, #rl, #cl>::from_row_slice(&[#(#entries),*]))
}

pub(crate) fn doc_lines(text: &str) -> Vec<TokenStream> {
    text.lines()
        .map(|l| {
            let l = if l.is_empty() {
                String::new()
            } else {
                format!(" {l}")
            };
            quote!(#[doc = #l])
        })
        .collect()
}

/// What an output is, for docs: `scalar`, `vector of 3`, `2×3 matrix`,
/// `symmetric 2×2 matrix`.
pub(crate) fn output_kind(o: &Output) -> String {
    let (r, c) = o.shape();
    match o {
        Output::Scalar(_) => "scalar".to_owned(),
        Output::Vector(_) => format!("vector of {r}"),
        Output::Matrix { .. } => format!("{r}×{c} matrix"),
        Output::Symmetric { .. } => format!("symmetric {r}×{c} matrix"),
    }
}

/// Emits `spec` (already verified); returns the tokens and its report row.
/// A function with several outputs returns the struct `out` (one field per
/// output).
pub fn function(
    g: &Graph,
    module: &str,
    spec: &FnSpec,
    out: &str,
    uses: &mut Uses,
) -> (TokenStream, ReportRow) {
    let roots: Vec<Id> = spec
        .outputs
        .iter()
        .flat_map(|(_, o)| o.ids().iter().copied())
        .collect();
    let roots = super::lower::lower(g, &roots);
    let sched = Schedule::for_code(g, &roots);
    // Output names are locals only when there are several outputs.
    let out_locals = spec
        .outputs
        .iter()
        .filter(|_| spec.outputs.len() > 1)
        .map(|(n, _)| n.as_str());
    let mut names = Names::new(
        spec.inputs
            .iter()
            .map(|i| i.name.as_str())
            .chain(out_locals),
    );
    let mut sym_names: BTreeMap<Sym, String> = BTreeMap::new();
    let mut params = Vec::new();
    let mut binds = Vec::new();
    for input in &spec.inputs {
        let used: Vec<(usize, Sym)> = input
            .syms
            .iter()
            .copied()
            .enumerate()
            .filter(|(_, s)| sched.syms.contains(s))
            .collect();
        let n = ulit(input.syms.len());
        let arg = ident(&if used.is_empty() {
            format!("_{}", input.name)
        } else {
            input.name.clone()
        });
        uses.ty("SVector");
        params.push(quote!(#arg: &SVector<T, #n>));
        for (k, s) in used {
            let local = names.fresh(&snake_case(&g.sym_info(s).name));
            let (li, kl) = (ident(&local), ulit(k));
            binds.push(quote!(let #li = #arg[#kl];));
            sym_names.insert(s, local);
        }
    }
    let sym_name = |s: Sym| {
        sym_names
            .get(&s)
            .cloned()
            .unwrap_or_else(|| snake_case(&g.sym_info(s).name))
    };
    let mut em = Emitter::new(g, &sched, &mut names, &sym_name);
    let lets = em.lets();
    let mut types = Vec::new();
    let mut values = Vec::new();
    let mut lowered = roots.iter();
    for (_, out) in &spec.outputs {
        types.push(output_type(out, uses));
        let entries = lowered
            .by_ref()
            .take(out.ids().len())
            .map(|&id| em.expr(id))
            .collect();
        values.push(output_value(out, entries, uses));
    }
    let (ret, tail) = if spec.outputs.len() == 1 {
        (types.remove(0), values.remove(0))
    } else {
        let outs: Vec<_> = spec.outputs.iter().map(|(n, _)| ident(n)).collect();
        let ty = ident(out);
        (quote!(#ty<T>), quote!(#ty { #(#outs: #values),* }))
    };
    let ops = em.ops;
    let row = ReportRow {
        module: module.to_owned(),
        function: spec.name.clone(),
        ops,
        lets: sched.lets.len(),
    };
    let docs = doc_lines(&fn_doc(g, spec, out, &row));
    let name = ident(&spec.name);
    let inline = (row.lets <= INLINE_LETS).then(|| quote!(#[inline]));
    let ts = quote! {
        #(#docs)*
        #inline
        pub fn #name<T: Real>(#(#params),*) -> #ret {
            #(#binds)*
            #(#lets)*
            #tail
        }
    };
    (ts, row)
}

/// The largest function (in named intermediates) emitted `#[inline]`.
///
/// `#[inline]` lets a caller in another crate or codegen unit inline the
/// function, and makes every crate that calls a generic function compile
/// its own copy (an inline function is not shared from the crate that
/// defines it). For the right-hand sides and contact functions of the hot
/// loops (up to about 90 `let`s) that is worth it; a Jacobian or parameter
/// Jacobian of hundreds of `let`s gains nothing from being inlined into
/// its caller, and as an inline function it was compiled again into each
/// test binary, the command line and the Python module.
pub const INLINE_LETS: usize = 100;

/// The doc comment: the model's text, the inputs and outputs, the counts.
fn fn_doc(g: &Graph, spec: &FnSpec, out: &str, row: &ReportRow) -> String {
    let mut s = spec.doc.trim_end().to_owned();
    s.push_str("\n\n# Inputs\n");
    for i in &spec.inputs {
        let names: Vec<String> = i
            .syms
            .iter()
            .map(|&s| format!("`{}`", g.sym_info(s).name))
            .collect();
        s.push_str(&format!("- `{}` = ({})\n", i.name, names.join(", ")));
    }
    s.push_str("\n# Outputs\n");
    if spec.outputs.len() > 1 {
        s.push_str(&format!("The fields of [`{out}`]:\n"));
    }
    for (n, o) in &spec.outputs {
        s.push_str(&format!("- `{n}`: {}\n", output_kind(o)));
    }
    s.push_str(&format!("\n# Cost\n{}; {} `let`s.", row.ops, row.lets));
    s
}
