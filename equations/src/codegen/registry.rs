//! The registry of generated functions: `pub mod registry` at the end of
//! `generated.rs`, a table `FUNCTIONS` with, for every function, its module
//! and name, its inputs (name and symbol names), its outputs (name and
//! number of entries) and two callers on slices, one at `f64` and one at
//! the double-double `Dd`. Tools that evaluate every function
//! (`pegdyn accuracy`) walk it; adding a model adds its rows.
//!
//! A caller takes one slice per input (component `k` of input `i` is
//! `a[i][k]`) and returns all outputs flattened, outputs in order, matrices
//! row-major (the order of [`crate::model::FnSpec::interpret`]).

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use super::tokens::ident;
use crate::graph::Graph;
use crate::model::{Module, Output};

/// `pub mod registry { .. }` for `modules` (each with its graph).
pub fn tokens(modules: &[(&Graph, &Module)]) -> TokenStream {
    let mut rows = Vec::new();
    let mut fns = Vec::new();
    for (_, m) in modules {
        for f in &m.functions {
            let (mi, fi) = (ident(&m.name), ident(&f.name));
            let caller = format_ident!("call_{}_{}", m.name, f.name);
            let args = (0..f.inputs.len()).map(|k| {
                let k = Literal::usize_unsuffixed(k);
                quote!(&SVector::from_column_slice(a[#k]))
            });
            let single = f.outputs.len() == 1;
            let pushes = f.outputs.iter().enumerate().map(|(k, (_, o))| {
                let k = Literal::usize_unsuffixed(k);
                let r = if single { quote!(r) } else { quote!(r.#k) };
                match o {
                    Output::Scalar(_) => quote!(out.push(#r);),
                    Output::Vector(_) => quote!(out.extend(#r.iter());),
                    Output::Matrix { .. } | Output::Symmetric { .. } => {
                        quote!(out.extend(#r.transpose().iter());)
                    }
                }
            });
            fns.push(quote! {
                fn #caller<T: Real>(a: &[&[T]]) -> Vec<T> {
                    let r = super::#mi::#fi(#(#args),*);
                    let mut out = Vec::new();
                    #(#pushes)*
                    out
                }
            });
            let inputs = f.inputs.iter().map(|i| {
                let names = ident(&format!("{}_NAMES", i.name.to_uppercase()));
                let n = &i.name;
                quote!((#n, &super::#mi::#names))
            });
            let outputs = f.outputs.iter().map(|(n, o)| {
                let len = Literal::usize_unsuffixed(o.ids().len());
                quote!((#n, #len))
            });
            let (ms, fs) = (&m.name, &f.name);
            rows.push(quote! {
                Function {
                    module: #ms,
                    name: #fs,
                    inputs: &[#(#inputs),*],
                    outputs: &[#(#outputs),*],
                    eval_f64: #caller::<f64>,
                    eval_dd: #caller::<Dd>,
                }
            });
        }
    }
    let n = Literal::usize_unsuffixed(rows.len());
    quote! {
        /// Every generated function with callers at `f64` and at the
        /// double-double `Dd` (used by `pegdyn accuracy`).
        pub mod registry {
            use nalgebra::SVector;
            use pegdyn::generated::Function;
            use pegdyn::scalar::{Dd, Real};
            /// Every generated function, modules in registration order.
            pub const FUNCTIONS: [Function; #n] = [#(#rows),*];
            #(#fns)*
        }
    }
}
