//! Define → verify → emit.
//!
//! [`render`] is the one front door: it verifies every model ([`verify`]),
//! lowers and plans each function (the lowering [`lower`], the evaluation
//! order [`crate::schedule`]), emits it with `quote` ([`emit`],
//! [`function`]), with each module's typed inputs and output structs and,
//! for a model that has one, its ODE adapter, formats each module with
//! `syn` + `prettyplease`, and returns the file, the operation counts
//! ([`Report`]) and whatever the [`Options`](crate::Options) ask for
//! besides (the [`registry`] of every function, its function-list macro,
//! pegdyn's test harness). [`Rendered::write`] writes them into the output
//! directory, each only when its bytes change, so that an unchanged model
//! does not trigger recompilation.
//!
//! The output is deterministic: modules in registration order, functions in
//! model order, nodes in arena order; no hash-map iteration, no paths, no
//! timestamps.

mod adapter;
#[doc(hidden)]
pub mod coverage;
pub mod emit;
pub mod function;
#[doc(hidden)]
pub mod harness;
pub mod lower;
mod module;
pub mod names;
pub mod ops;
pub mod registry;
mod render;
mod tokens;
mod types;
mod value_names;
pub mod verify;
mod verify_types;

pub use module::ModuleSource;
pub use ops::{OpCounts, Report, ReportRow};
pub use render::{Entry, Rendered, Written, header, render, write_if_changed};
