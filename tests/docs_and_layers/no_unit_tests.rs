//! The libraries carry no `#[cfg(test)]` code: they have no unit-test
//! harness (`[lib] test = false` in Cargo.toml and equations/Cargo.toml, so
//! that Cargo compiles each library once), and a test module written inside
//! `src/` would never run. Tests of one module go to
//! `tests/<area>/modules/` (pegdyn) or `equations/tests/pipeline/`.

use crate::layers::rust_files;
use std::path::Path;

/// Every line of `text` that turns code on only for a test build, as
/// "file:line: text".
fn test_only_lines(file: &Path, text: &str) -> Vec<String> {
    text.lines()
        .enumerate()
        .filter(|(_, line)| {
            let code = line.split("//").next().unwrap_or("");
            code.contains("cfg(test)") || code.contains("cfg(any(test") || code.contains("#[test]")
        })
        .map(|(n, line)| format!("{}:{}: {}", file.display(), n + 1, line.trim()))
        .collect()
}

#[test]
fn the_libraries_have_no_test_only_code() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["src", "equations/src"] {
        rust_files(&root.join(dir), &mut files);
    }
    assert!(files.len() > 100, "{} files", files.len());
    let found: Vec<String> = files
        .iter()
        .flat_map(|f| {
            let text =
                std::fs::read_to_string(f).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
            test_only_lines(f, &text)
        })
        .collect();
    assert!(
        found.is_empty(),
        "test-only code in a library (it never runs):\n{}",
        found.join("\n")
    );
}

#[test]
fn a_test_module_is_found() {
    let text = "fn f() {}\n#[cfg(test)]\nmod tests {\n    #[test]\n    fn t() {}\n}\n// #[cfg(test)] in a comment\n";
    let found = test_only_lines(Path::new("x.rs"), text);
    assert_eq!(found, ["x.rs:2: #[cfg(test)]", "x.rs:4: #[test]"]);
}
