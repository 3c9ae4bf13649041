//! Code generated at build time from the symbolic models in
//! `pegdyn-equations` (see `build.rs`): one module per model, each with
//! straight-line functions `f<T: Real>` of `&SVector<T, N>` inputs (generic
//! over the scalar, [`crate::scalar::Real`]: `f64`, or the double-double
//! [`crate::scalar::Dd`] as a reference) and `<INPUT>_NAMES` constants that
//! give the symbol name of every input component; then `registry`, which
//! lists every function with callers at both scalars.
//!
//! A readable copy of every module is checked in under `docs/generated/`
//! and kept current by `tests/generator/snapshot.rs`.

#[allow(
    clippy::all,
    clippy::pedantic,
    unused_parens,
    unused_variables,
    non_snake_case,
    missing_docs
)]
mod inner {
    include!(concat!(env!("OUT_DIR"), "/generated.rs"));
}
pub use inner::*;

/// The generated source, as `pegdyn codegen` prints it.
pub const SOURCE: &str = include_str!(concat!(env!("OUT_DIR"), "/generated.rs"));

/// Operation counts of every generated function (plain-text table).
pub const REPORT: &str = include_str!(concat!(env!("OUT_DIR"), "/codegen_report.txt"));

/// One generated function as the registry lists it
/// (`pegdyn::generated::registry::FUNCTIONS`): where it is, what it takes
/// and returns, and a caller on slices at `f64`.
#[derive(Clone, Copy, Debug)]
pub struct Function {
    /// The module (model) name.
    pub module: &'static str,
    /// The function name.
    pub name: &'static str,
    /// Inputs in order: argument name and the symbol name of each component.
    pub inputs: &'static [(&'static str, &'static [&'static str])],
    /// Outputs in order: name and number of entries (matrices row-major).
    pub outputs: &'static [(&'static str, usize)],
    /// Calls the function at `f64`: one slice per input, of its length;
    /// returns every output entry flattened in order.
    pub eval_f64: fn(&[&[f64]]) -> Vec<f64>,
}

/// A generated function with a second caller at double-double, as
/// `pegdyn::generated::registry::DD_FUNCTIONS` lists it (the reference of
/// [`crate::accuracy`]). A separate table so that a crate that needs only
/// the `f64` callers compiles no double-double code.
#[derive(Clone, Copy, Debug)]
pub struct DdFunction {
    /// The function and its `f64` caller.
    pub function: Function,
    /// The same caller at double-double.
    pub eval_dd: fn(&[&[crate::scalar::Dd]]) -> Vec<crate::scalar::Dd>,
}

impl Function {
    /// `module::name`.
    pub fn path(&self) -> String {
        format!("{}::{}", self.module, self.name)
    }

    /// The name of flattened output entry `k`: `name` for a scalar,
    /// `name[i]` otherwise.
    pub fn output_name(&self, mut k: usize) -> String {
        for &(name, len) in self.outputs {
            if k < len {
                return if len == 1 {
                    name.to_owned()
                } else {
                    format!("{name}[{k}]")
                };
            }
            k -= len;
        }
        format!("#{k}")
    }
}
