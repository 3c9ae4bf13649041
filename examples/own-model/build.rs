//! Generates the model's code into `$OUT_DIR/own_model.rs` (and the
//! operation counts into `$OUT_DIR/own_model_report.txt`) with
//! `pegdyn-equations`, the way `prost-build` generates protobuf code.

mod model;

use pegdyn_equations::{Generator, Options};

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=model.rs");
    println!("cargo:rerun-if-env-changed=PEGDYN_NAIVE_FORMS");
    let Some(out_dir) = std::env::var_os("OUT_DIR") else {
        eprintln!("error: OUT_DIR is not set (build.rs must run under cargo)");
        std::process::exit(1);
    };
    // The registry (every function at f64 and double-double) is an extra:
    // the accuracy check in tests/checks.rs walks it.
    let options = Options {
        registry: true,
        source_file: "own_model.rs".to_owned(),
        report_file: "own_model_report.txt".to_owned(),
        ..Options::from_env()
    };
    let mut generator = Generator::new(options);
    let written = model::declare(&mut generator)
        .and_then(|()| model::declare_forced(&mut generator))
        .and_then(|()| generator.write(out_dir.as_ref()));
    if let Err(e) = written {
        eprintln!("error: code generation failed: {e}");
        std::process::exit(1);
    }
}
