//! # pegdyn-equations
//!
//! The build-time half of pegdyn: expression DAGs for the models, symbolic
//! differentiation, Lagrange derivation, and emission of straight-line Rust.
//!
//! Define → verify → emit: models build expressions in a [`Graph`];
//! [`codegen`] checks and emits them; a build script writes the result into
//! `OUT_DIR`. [`Generator`] is the entry point for a build script: pegdyn's
//! own `build.rs` adds its models ([`models`]) with it, and a downstream
//! crate declares its own models by name with [`ModelBuilder`] (guide:
//! `docs/own-model.md` in the pegdyn repository).

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
