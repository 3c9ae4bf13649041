//! Code generated at build time from the symbolic models in
//! `pegdyn-equations` (see `build.rs`): one module per model, each with
//! straight-line functions of `&SVector<f64, N>` inputs and `<INPUT>_NAMES`
//! constants that give the symbol name of every input component.
//!
//! A readable copy of every module is checked in under `docs/generated/`
//! and kept current by `tests/generated_snapshot.rs`.

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
