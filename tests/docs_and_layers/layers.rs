//! The crate's layers: physics below, scenes and output above.
//!
//! The physics modules (the peg models, jamming, Hertz contact, the textbook
//! and reference systems, the integrator, the ODE interface, the scalar
//! types) must not use the scene layer (`scene`), the output writers
//! (`output`) or the command line (`cli`, `accuracy`): a scene kind is built
//! on top of the physics, never the other way round. This test reads the
//! sources and fails on any path into those layers.

use std::path::{Path, PathBuf};

/// Modules (folders or files under `src/`) of the physics layer.
const PHYSICS: &[&str] = &[
    "rigid_peg",
    "compliant_peg",
    "compliant_peg_3d",
    "jamming",
    "hertz",
    "textbook",
    "reference_problems.rs",
    "integrate",
    "sensitivity",
    "system.rs",
    "scalar",
];

/// Top-level modules the physics layer must not reach.
const UPPER: &[&str] = &["scene", "output", "cli", "accuracy"];

/// Every `.rs` file under `path`, in sorted order.
pub fn rust_files(path: &Path, out: &mut Vec<PathBuf>) {
    if path.is_dir() {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(path)
            .unwrap_or_else(|e| panic!("read {}: {e}", path.display()))
            .map(|e| e.expect("directory entry").path())
            .collect();
        entries.sort();
        for entry in entries {
            rust_files(&entry, out);
        }
    } else if path.extension().is_some_and(|e| e == "rs") {
        out.push(path.to_path_buf());
    }
}

/// The code of a line without its `//` comment (doc comments may name the
/// scenes that use a module).
fn code(line: &str) -> &str {
    line.find("//").map_or(line, |i| &line[..i])
}

/// Every `crate::<upper>`, `pegdyn::<upper>` or `super::…::<upper>` path
/// into an upper layer on a code line, as "file:line: text".
fn violations(file: &Path, text: &str) -> Vec<String> {
    let mut found = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let code = code(line);
        for upper in UPPER {
            let direct = ["crate::", "pegdyn::"]
                .iter()
                .any(|root| contains_path(code, root, upper));
            // A `super::` chain that climbs to the crate root and goes down
            // into an upper layer (e.g. `super::super::scene`).
            let climbing = code.contains("super::") && contains_path(code, "super::", upper);
            if direct || climbing {
                found.push(format!("{}:{}: {}", file.display(), n + 1, line.trim()));
            }
        }
    }
    found
}

/// Whether `code` contains `<root><module>` followed by a non-identifier
/// character (so `crate::scene` matches, `crate::scenery` does not).
fn contains_path(code: &str, root: &str, module: &str) -> bool {
    let needle = format!("{root}{module}");
    code.match_indices(&needle).any(|(i, _)| {
        let after = code[i + needle.len()..].chars().next();
        !after.is_some_and(|c| c.is_alphanumeric() || c == '_')
    })
}

#[test]
fn physics_never_imports_scene_or_output() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    for module in PHYSICS {
        let path = src.join(module);
        assert!(
            path.exists(),
            "physics module {} is missing",
            path.display()
        );
        rust_files(&path, &mut files);
    }
    assert!(files.len() > 20, "found only {} physics files", files.len());
    let found: Vec<String> = files
        .iter()
        .flat_map(|f| {
            let text =
                std::fs::read_to_string(f).unwrap_or_else(|e| panic!("read {}: {e}", f.display()));
            violations(f, &text)
        })
        .collect();
    assert!(
        found.is_empty(),
        "physics modules use the scene/output layer:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_check_sees_an_import() {
    let file = Path::new("src/example.rs");
    assert_eq!(
        violations(
            file,
            "use crate::scene::Kind;\nuse crate::integrate::Solver;"
        )
        .len(),
        1
    );
    assert_eq!(
        violations(file, "use crate::output::plot::Panel; // draws").len(),
        1
    );
    assert_eq!(
        violations(file, "use super::super::scene::validate::Checker;").len(),
        1
    );
    // Comments and look-alike names are not imports.
    assert!(violations(file, "//! used by `crate::scene::jamming`").is_empty());
    assert!(violations(file, "use crate::scenery::X; let output = 1;").is_empty());
}

/// The ways a file could be written or removed without a run's sink.
const FILE_WRITES: &[&str] = &[
    "std::fs",
    "fs::write",
    "File::create",
    "OpenOptions",
    "fs::rename",
    "fs::remove",
    "create_dir",
];

/// Lines of `text` (code, not comments) that touch the file system, other
/// than reading the scene file itself (`std::fs::read_to_string`).
fn file_writes(file: &Path, text: &str) -> Vec<String> {
    text.lines()
        .enumerate()
        .filter(|(_, line)| {
            let code = code(line);
            FILE_WRITES.iter().any(|w| code.contains(w))
                && !code.contains("std::fs::read_to_string(path)")
        })
        .map(|(n, line)| format!("{}:{}: {}", file.display(), n + 1, line.trim()))
        .collect()
}

#[test]
fn scenes_write_only_through_their_run_context() {
    // Every output of a scene goes through the sink of its run context
    // (`ctx.table`, `ctx.figure`, `ctx.file`), so that a run in memory
    // writes nothing and a run into a directory records every file.
    let mut files = Vec::new();
    rust_files(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src/scene"),
        &mut files,
    );
    assert!(files.len() > 30, "found only {} scene files", files.len());
    let found: Vec<String> = files
        .iter()
        .flat_map(|f| {
            let text =
                std::fs::read_to_string(f).unwrap_or_else(|e| panic!("read {}: {e}", f.display()));
            file_writes(f, &text)
        })
        .collect();
    assert!(
        found.is_empty(),
        "scene code touches files outside its run context:\n{}",
        found.join("\n")
    );
    let file = Path::new("src/scene/example.rs");
    assert_eq!(file_writes(file, "std::fs::write(&p, b)?;").len(), 1);
    assert_eq!(
        file_writes(file, "let f = File::create(&p)?; // x").len(),
        1
    );
    assert!(file_writes(file, "// std::fs::write is not used").is_empty());
}
