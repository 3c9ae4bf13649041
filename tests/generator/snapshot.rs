//! The readable copies in `docs/generated/` are current.
//!
//! Regenerates every registered model in memory and compares each module
//! with `docs/generated/<module>.rs` and the report with
//! `docs/generated/codegen_report.txt`. A difference fails the test with
//! the list of stale files; run
//! `PEGDYN_BLESS=1 cargo test --test generator snapshot::` to rewrite them,
//! then review the diff like any other change. Also checks that the code
//! compiled into `pegdyn::generated` is the code the generator emits now.

use std::path::{Path, PathBuf};

use pegdyn_equations::{Generator, Options, Rendered, models};

fn docs_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs")
        .join("generated")
}

/// Every built-in model rendered as `build.rs` renders it (the registry
/// on, so that the whole file compares).
fn render_builtins() -> Rendered {
    let mut generator = Generator::new(Options {
        registry: true,
        parameter_jacobians: models::PARAMETER_JACOBIANS
            .iter()
            .map(|m| (*m).to_owned())
            .collect(),
        ..Options::default()
    });
    models::declare_all(&mut generator)
        .and_then(|()| generator.render())
        .unwrap_or_else(|e| panic!("generation failed: {e}"))
}

/// The expected files: name → content.
fn expected(generated: &Rendered) -> Vec<(String, String)> {
    let mut files: Vec<(String, String)> = generated
        .modules
        .iter()
        .map(|m| {
            let header = format!(
                "// @generated readable copy of `pegdyn::generated::{}` — do not edit.\n\
                 // Regenerate: PEGDYN_BLESS=1 cargo test --test generator snapshot::\n\n",
                m.name
            );
            (format!("{}.rs", m.name), header + &m.code)
        })
        .collect();
    files.push((
        "codegen_report.txt".to_owned(),
        generated.report.to_string(),
    ));
    files
}

#[test]
fn docs_generated_is_current() {
    let generated = render_builtins();
    let dir = docs_dir();
    let files = expected(&generated);
    let bless = std::env::var_os("PEGDYN_BLESS").is_some_and(|v| v == "1");
    let mut stale = Vec::new();
    for (name, content) in &files {
        let path = dir.join(name);
        if std::fs::read_to_string(&path).ok().as_deref() != Some(content.as_str()) {
            stale.push(name.clone());
            if bless {
                std::fs::create_dir_all(&dir).expect("create docs/generated");
                std::fs::write(&path, content).expect("write snapshot");
            }
        }
    }
    // Files of modules that no longer exist.
    for entry in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.ends_with(".rs") && !files.iter().any(|(n, _)| *n == name) {
            stale.push(format!("{name} (no such module)"));
            if bless {
                std::fs::remove_file(entry.path()).expect("remove stale snapshot");
            }
        }
    }
    if bless {
        if !stale.is_empty() {
            eprintln!(
                "PEGDYN_BLESS=1: rewrote docs/generated/: {}",
                stale.join(", ")
            );
        }
        return;
    }
    assert!(
        stale.is_empty(),
        "docs/generated/ is out of date: {}.\nIf the change is intended, run \
         `PEGDYN_BLESS=1 cargo test --test generator snapshot::` and review the diff.",
        stale.join(", ")
    );
}

#[test]
fn compiled_code_is_what_the_generator_emits() {
    let generated = render_builtins();
    assert_eq!(
        pegdyn::generated::SOURCE,
        generated.source,
        "OUT_DIR/generated.rs is stale: run cargo build"
    );
    assert_eq!(pegdyn::generated::REPORT, generated.report.to_string());
}
