//! Build script of `pegdyn-benches`: writes the list of every generated
//! function (`$OUT_DIR/generated_list.rs`, the `for_each_generated!` macro
//! that `benches/list.rs` includes) with the same public generator and the
//! same built-in models as pegdyn's own `build.rs`, so the benches and the
//! instruction counts name exactly the functions pegdyn generates.

use std::path::PathBuf;
use std::process::exit;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=../equations/src");
    println!("cargo:rerun-if-changed=../equations/Cargo.toml");
    println!("cargo:rerun-if-env-changed=PEGDYN_NAIVE_FORMS");
    let Some(out_dir) = std::env::var_os("OUT_DIR").map(PathBuf::from) else {
        eprintln!("error: OUT_DIR is not set (build.rs must run under cargo)");
        exit(1);
    };
    // pegdyn's own build options: the same functions exist here as there.
    let mut generator = pegdyn_equations::Generator::new(pegdyn_equations::models::build_options());
    let written = pegdyn_equations::models::declare_all(&mut generator)
        .and_then(|()| generator.render())
        .and_then(|out| {
            let list = out_dir.join(pegdyn_equations::codegen::registry::LIST_FILE);
            let text = out.list.unwrap_or_default();
            pegdyn_equations::codegen::write_if_changed(&list, text.as_bytes())
        });
    if let Err(e) = written {
        eprintln!("error: code generation failed: {e}");
        exit(1);
    }
}
