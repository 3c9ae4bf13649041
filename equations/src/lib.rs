//! # pegdyn-equations
//!
//! The build-time half of pegdyn: expression DAGs for the models, symbolic
//! differentiation, Lagrange derivation, and emission of straight-line Rust.
//!
//! Define → verify → emit: a model is declared by name with
//! [`ModelBuilder`] (its coordinates, parameters and inputs with their
//! meanings and units, its dynamics and functions) inside
//! [`Generator::model`]; [`render`] verifies every model and emits it — a
//! `Params` struct per model, a struct per multi-output function, the
//! functions and, for a model that asks for one, an ODE adapter — and a
//! build script writes the result into `OUT_DIR`. pegdyn's own `build.rs`
//! declares its models ([`models::declare_all`]) exactly as a downstream
//! crate declares its own (guide: `docs/own-model.md` in the pegdyn
//! repository).

#![warn(missing_docs)]

pub mod diff;
pub mod display;
pub mod eval;
pub mod expand;
pub mod expr;
pub mod graph;
pub mod schedule;
pub mod simplify;
pub mod subst;

pub use expr::Expr;
pub use graph::{Graph, Id, Node, Sym, SymKind};
pub mod codegen;
pub mod error;
pub mod lagrange;
pub mod model;
pub mod models;

pub mod builder;
pub mod options;

pub use builder::{Generator, ModelBuilder, Outputs, blocks};
pub use codegen::{Entry, Rendered, Report, render};
pub use error::GenError;
pub use options::Options;
