//! Build script of `pegdyn`: generates the model code.
//!
//! Inputs:  the models and generator in `equations/src` (crate
//!          `pegdyn-equations`, a build-dependency) and `equations/Cargo.toml`.
//! Outputs: `$OUT_DIR/generated.rs` (included by `src/generated.rs`),
//!          `$OUT_DIR/codegen_report.txt` (operation counts per function) and
//!          `$OUT_DIR/generated_calls.rs` (call table for
//!          `tests/generated_vs_interpreter.rs`) and `$OUT_DIR/generated_list.rs`
//!          (the function list of `benches/list.rs`), each rewritten only
//!          when its content changes.
//!
//! It uses the public builder API (`pegdyn_equations::Generator`), the same
//! one a downstream crate's build script uses (docs/own-model.md).
//!
//! Environment: `PEGDYN_NAIVE_FORMS=1` generates without the stable
//! numerical rewrites of the simplifier (`Options::from_env`) (for `pegdyn accuracy`'s "before"
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
    // The public generator API, as a downstream build script uses it.
    let options = pegdyn_equations::Options::from_env();
    let mut generator = pegdyn_equations::Generator::new(options);
    let declared = pegdyn_equations::models::declare_all(&mut generator);
    let written = declared.and_then(|()| generator.render()).and_then(|out| {
        out.write(&out_dir)?;
        // pegdyn's own test call table (tests/generated_vs_interpreter.rs).
        let calls = out_dir.join(pegdyn_equations::codegen::harness::CALLS_FILE);
        pegdyn_equations::codegen::write_if_changed(&calls, out.calls.as_bytes())?;
        let list = out_dir.join(pegdyn_equations::codegen::registry::LIST_FILE);
        pegdyn_equations::codegen::write_if_changed(&list, out.list.as_bytes())
    });
    if let Err(e) = written {
        eprintln!("error: code generation failed: {e}");
        exit(1);
    }
}
