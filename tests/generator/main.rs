//! The generated code: the checked-in copy, values against the interpreter and
//! the hand-derived forms, Lagrange's equations of the textbook systems, and
//! rounding error against double-double on hard cases.

// `hand_forms` includes `benches/cases.rs` (shared with the bench binary),
// which includes `tests/common/rng.rs` a second time, as its own module.
#![allow(clippy::duplicate_mod)]

#[path = "../common/mod.rs"]
mod common;

mod accuracy_report;
mod hand_forms;
mod hard_cases_compliant;
mod hard_cases_rewrites;
mod hard_cases_rigid;
mod lagrange_textbook;
mod modules;
mod parameter_jacobians;
mod scalar_dd;
mod snapshot;
mod vs_interpreter;
