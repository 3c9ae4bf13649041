//! The generator's pipeline: the builder API, simplification laws and
//! values, derivatives, Lagrange's equations, the interpreter, lowering and
//! emission.

#[path = "../common/mod.rs"]
mod common;

mod builder;
mod codegen;
mod diff_vs_finite_difference;
mod display;
mod interpreter;
mod lagrange;
mod lower_preserves_value;
mod parameter_jacobians;
mod rigid_peg_variants;
mod simplify_laws;
mod simplify_preserves_value;
