//! The typed boundary of a generated module, the way prost writes a struct
//! per message: the struct of each typed input (`Params`), with the names
//! of its fields and `From` conversions both ways with the `SVector` the
//! functions take, and the struct each function with several outputs
//! returns (`<Function>Out`, or one shared by several functions).

use proc_macro2::TokenStream;
use quote::quote;

use super::function::{Uses, doc_lines, output_kind, output_type};
use super::names::is_snake_ident;
use super::tokens::{ident, ulit};
use crate::graph::Graph;
use crate::model::{FnSpec, Input, OutType, Record};

/// A field doc from a declared meaning (`mass of the bob, kg`): a leading
/// space, the first letter capitalized, a full stop at the end.
fn sentence(text: &str) -> String {
    let mut cs = text.trim().chars();
    let mut out: String = match cs.next() {
        Some(c) => format!(" {}{}", c.to_uppercase(), cs.as_str()),
        None => String::new(),
    };
    if !out.ends_with('.') {
        out.push('.');
    }
    out
}

/// `pub struct <Record><T>` and its conversions, or `pub use` of the
/// struct of the module it is shared with.
pub(crate) fn record(g: &Graph, r: &Record, input: &Input, uses: &mut Uses) -> TokenStream {
    let ty = ident(&r.name);
    if let Some(other) = &r.shared_with {
        let doc = format!(
            " The struct of `{}`, shared with `{other}` (same components).",
            r.input
        );
        let om = ident(other);
        return quote! {
            #[doc = #doc]
            pub use super::#om::#ty;
        };
    }
    uses.ty("SVector");
    let names: Vec<String> = input.syms.iter().map(|&s| g.sym_info(s).name).collect();
    let fields: Vec<_> = names.iter().map(|n| ident(n)).collect();
    let docs: Vec<String> = r.fields.iter().map(|d| sentence(d)).collect();
    let idx: Vec<_> = (0..names.len()).map(ulit).collect();
    let n = ulit(names.len());
    let allow = names
        .iter()
        .any(|n| !is_snake_ident(n))
        .then(|| quote!(#[allow(non_snake_case)]));
    let struct_docs = doc_lines(&r.doc);
    let list = ident(&format!("{}_NAMES", r.input.to_uppercase()));
    let names_doc = format!(
        " The field names in vector order: the symbol names of `{}` ([`{list}`]).",
        r.input
    );
    let from_doc = format!(" The `{}` vector of these values, in field order.", r.input);
    let into_doc = format!(" The fields of a `{}` vector, in field order.", r.input);
    quote! {
        #(#struct_docs)*
        #[derive(Clone, Copy, Debug, PartialEq)]
        #allow
        pub struct #ty<T> {
            #(#[doc = #docs] pub #fields: T,)*
        }
        impl<T> #ty<T> {
            #[doc = #names_doc]
            pub const NAMES: [&'static str; #n] = #list;
        }
        impl<T: Real> From<#ty<T>> for SVector<T, #n> {
            #[doc = #from_doc]
            fn from(v: #ty<T>) -> SVector<T, #n> {
                SVector::from([#(v.#fields),*])
            }
        }
        impl<T: Real> From<&SVector<T, #n>> for #ty<T> {
            #[doc = #into_doc]
            fn from(v: &SVector<T, #n>) -> #ty<T> {
                #ty { #(#fields: v[#idx]),* }
            }
        }
        impl<T: Real> From<SVector<T, #n>> for #ty<T> {
            #[doc = #into_doc]
            fn from(v: SVector<T, #n>) -> #ty<T> {
                #ty::from(&v)
            }
        }
    }
}

/// `pub struct <Out><T: Real>` with one field per output of `f` (the first
/// function returning it), documented by `o` (or by the outputs' shapes
/// for a module built without docs).
pub(crate) fn out_struct(
    name: &str,
    o: Option<&OutType>,
    f: &FnSpec,
    uses: &mut Uses,
) -> TokenStream {
    let ty = ident(name);
    if let Some(other) = o.and_then(|o| o.shared_with.as_ref()) {
        let doc = format!(" The outputs' struct, shared with `{other}` (same fields).");
        let om = ident(other);
        return quote! {
            #[doc = #doc]
            pub use super::#om::#ty;
        };
    }
    let doc = o.map_or_else(
        || format!("The outputs of [`{}`].", f.name),
        |o| o.doc.clone(),
    );
    let struct_docs = doc_lines(&doc);
    let mut fields = Vec::new();
    for (k, (n, out)) in f.outputs.iter().enumerate() {
        let d = match o.and_then(|o| o.fields.get(k)) {
            Some(d) if !d.is_empty() => sentence(d),
            _ => format!(" `{n}`: {}.", output_kind(out)),
        };
        let (field, t) = (ident(n), output_type(out, uses));
        fields.push(quote!(#[doc = #d] pub #field: #t,));
    }
    quote! {
        #(#struct_docs)*
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct #ty<T: Real> {
            #(#fields)*
        }
    }
}
