//! One module's code: the `pub mod <name> { .. }` of a verified module —
//! input name lists, typed inputs, output structs and functions, and the
//! ODE adapter when the model has one — as tokens, then formatted.

use std::collections::BTreeSet;

use proc_macro2::TokenStream;
use quote::quote;

use super::ops::Report;
use super::tokens::{ident, ulit};
use super::{adapter, function, types};
use crate::error::GenError;
use crate::graph::Graph;
use crate::model::Module;

/// The generated code of one module, formatted.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModuleSource {
    /// The module name (`pub mod <name>`).
    pub name: String,
    /// `pub mod <name> { .. }`, formatted by prettyplease.
    pub code: String,
}

/// Emits and formats one verified module, appending its report rows.
pub(crate) fn emit_module(
    g: &Graph,
    m: &Module,
    report: &mut Report,
) -> Result<ModuleSource, GenError> {
    let tokens = module_tokens(g, m, report);
    let file = syn::parse2::<syn::File>(tokens).map_err(|e| GenError::Parse {
        module: m.name.clone(),
        message: e.to_string(),
    })?;
    Ok(ModuleSource {
        name: m.name.clone(),
        code: prettyplease::unparse(&file),
    })
}

/// `pub mod name { use ..; consts; typed inputs; (out struct, fn)s;
/// adapter }`.
fn module_tokens(g: &Graph, m: &Module, report: &mut Report) -> TokenStream {
    let mut uses = function::Uses::default();
    let mut fns = Vec::new();
    let mut emitted_outs = BTreeSet::new();
    for f in &m.functions {
        let (out, declared) = m.out_type_of(f);
        if f.outputs.len() > 1 && emitted_outs.insert(out.clone()) {
            fns.push(types::out_struct(&out, declared, f, &mut uses));
        }
        let (ts, row) = function::function(g, &m.name, f, &out, &mut uses);
        fns.push(ts);
        report.rows.push(row);
    }
    let mut consts = Vec::new();
    let mut seen = BTreeSet::new();
    for input in m.functions.iter().flat_map(|f| &f.inputs) {
        if !seen.insert(input.name.as_str()) {
            continue;
        }
        let cname = ident(&format!("{}_NAMES", input.name.to_uppercase()));
        let n = ulit(input.syms.len());
        let names: Vec<String> = input.syms.iter().map(|&s| g.sym_info(s).name).collect();
        let doc = format!(
            " Symbol names of the components of `{}`, in order.",
            input.name
        );
        consts.push(quote! {
            #[doc = #doc]
            pub const #cname: [&str; #n] = [#(#names),*];
        });
    }
    let mut records = Vec::new();
    for r in &m.records {
        let input = m
            .functions
            .iter()
            .flat_map(|f| &f.inputs)
            .find(|i| i.name == r.input);
        if let Some(input) = input {
            records.push(types::record(g, r, input, &mut uses));
        }
    }
    let adapter = m
        .adapter
        .as_ref()
        .filter(|l| l.adapter)
        .map(adapter::tokens);
    let types: Vec<_> = uses.names().iter().map(|n| ident(n)).collect();
    let docs = function::doc_lines(m.doc.trim_end());
    let name = ident(&m.name);
    quote! {
        #(#docs)*
        pub mod #name {
            use nalgebra::{#(#types),*};
            use pegdyn::scalar::Real;
            #(#consts)*
            #(#records)*
            #(#fns)*
            #adapter
        }
    }
}
