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
//! Any error (a model that fails verification, an unwritable file) is
//! printed and the build fails with exit status 1.

use std::path::PathBuf;
use std::process::exit;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=equations/src");
    println!("cargo:rerun-if-changed=equations/Cargo.toml");
    let Some(out_dir) = std::env::var_os("OUT_DIR").map(PathBuf::from) else {
        eprintln!("error: OUT_DIR is not set (build.rs must run under cargo)");
        exit(1);
    };
    if let Err(e) = pegdyn_equations::generate(&out_dir) {
        eprintln!("error: code generation failed: {e}");
        exit(1);
    }
}
