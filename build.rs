//! Build script of `pegdyn`: generates the model code.
//!
//! Inputs:  the models and generator in `equations/src` (crate
//!          `pegdyn-equations`, a build-dependency) and `equations/Cargo.toml`.
//! Outputs: `$OUT_DIR/generated.rs` (included by `src/generated.rs`, with the
//!          registry of every function), `$OUT_DIR/codegen_report.txt`
//!          (operation counts per function), `$OUT_DIR/generated_calls.rs`
//!          (the emitter-coverage test harness of
//!          `tests/generator/vs_interpreter.rs`) and
//!          `$OUT_DIR/generated_list.rs` (the function and output-struct
//!          lists of `benches/list.rs`), each rewritten only when its content
//!          changes.
//!
//! It declares the built-in models through the public builder
//! (`pegdyn_equations::models::declare_all` calls `Generator::model` for
//! each), the same API a downstream crate's build script uses
//! (docs/own-model.md), with the options of
//! `pegdyn_equations::models::build_options`: the extras only pegdyn needs
//! (the registry, the function list, the test harness and the parameter
//! Jacobians of the models whose sensitivities it integrates). The benches'
//! build script takes the same options.
//!
//! Environment: `PEGDYN_NAIVE_FORMS=1` generates without the stable
//! numerical rewrites of the simplifier (`Options::from_env`) (for `pegdyn accuracy`'s "before"
//! column only, see docs/ACCURACY.md; the snapshot test then fails).
//!
//! Any error (a model that fails verification, an unwritable file) is
//! printed and the build fails with exit status 1.

use std::path::PathBuf;
use std::process::exit;

use pegdyn_equations::{Generator, models};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=equations/src");
    println!("cargo:rerun-if-changed=equations/Cargo.toml");
    println!("cargo:rerun-if-env-changed=PEGDYN_NAIVE_FORMS");
    let Some(out_dir) = std::env::var_os("OUT_DIR").map(PathBuf::from) else {
        eprintln!("error: OUT_DIR is not set (build.rs must run under cargo)");
        exit(1);
    };
    let mut generator = Generator::new(models::build_options());
    let written = models::declare_all(&mut generator).and_then(|()| generator.write(&out_dir));
    if let Err(e) = written {
        eprintln!("error: code generation failed: {e}");
        exit(1);
    }
}
