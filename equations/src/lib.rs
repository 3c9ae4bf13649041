//! # pegdyn-equations
//!
//! The build-time half of pegdyn: expression DAGs for the models, symbolic
//! differentiation, Lagrange derivation, and emission of straight-line Rust.
//!
//! Define → verify → emit: models in [`models`] build expressions in a
//! [`Graph`]; [`codegen`] checks and emits them; `build.rs` of the `pegdyn`
//! crate writes the result into `OUT_DIR`.

pub mod diff;
pub mod display;
pub mod eval;
pub mod expand;
pub mod expr;
pub mod graph;
pub mod simplify;
pub mod subst;

pub use expr::Expr;
pub use graph::{Graph, Id, Node, Sym, SymKind};
pub mod codegen;
pub mod error;
pub mod lagrange;
pub mod model;
pub mod models;

pub use codegen::{Report, generate};
pub use error::GenError;
