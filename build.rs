//! Build script of `pegdyn`: generates the model code.
//!
//! Inputs:  the models and generator in `equations/src` (crate
//!          `pegdyn-equations`, a build-dependency) and `equations/Cargo.toml`.
//! Outputs: `$OUT_DIR/generated.rs` (included by `src/generated.rs`),
//!          `$OUT_DIR/codegen_report.txt` (operation counts per function) and
//!          `$OUT_DIR/generated_calls.rs` (call table for
//!          `tests/generated_vs_interpreter.rs`), each rewritten only when its
//!          content changes.
//!
//! Environment: `PEGDYN_NAIVE_FORMS=1` generates without the stable
//! numerical rewrites of the simplifier (for `pegdyn accuracy`'s "before"
//! column only, see docs/ACCURACY.md; the snapshot test then fails).
//!
//! Any error (a model that fails verification, an unwritable file) is
//! printed and the build fails with exit status 1.

use std::path::PathBuf;
use std::process::exit;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=equations/src");
    println!("cargo:rerun-if-changed=equations/Cargo.toml");
    println!("cargo:rerun-if-env-changed=PEGDYN_NAIVE_FORMS");
    let Some(out_dir) = std::env::var_os("OUT_DIR").map(PathBuf::from) else {
        eprintln!("error: OUT_DIR is not set (build.rs must run under cargo)");
        exit(1);
    };
    let stable = std::env::var_os("PEGDYN_NAIVE_FORMS").is_none_or(|v| v != "1");
    let generated = pegdyn_equations::simplify::rules::with_stable_forms(stable, || {
        pegdyn_equations::generate(&out_dir)
    });
    if let Err(e) = generated {
        eprintln!("error: code generation failed: {e}");
        exit(1);
    }
}
