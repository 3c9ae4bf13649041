//! Docs that drift from the tree: every repository path that README.md or a
//! page under docs/ names in backticks (`src/...`, `docs/...`, `scenes/...`,
//! `tests/...`, `benches/...`, `examples/...`, `equations/...`, `python/...`)
//! must exist.
//!
//! A path may end in `/` (a folder) or carry a `::item` or `#anchor` suffix
//! (only the file part is checked). Glob-like names (`*`, `{`, `<`) and
//! output folders (`out/`) are not paths and are skipped.

use std::fs;
use std::path::{Path, PathBuf};

const ROOTS: [&str; 8] = [
    "src/",
    "docs/",
    "scenes/",
    "tests/",
    "benches/",
    "examples/",
    "equations/",
    "python/",
];

pub(crate) fn manifest_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The repository paths named in one backticked span or command line.
fn paths_in(span: &str) -> Vec<String> {
    span.split_whitespace()
        .filter(|w| ROOTS.iter().any(|r| w.starts_with(r)))
        .filter(|w| !w.contains(['*', '{', '<', '$']))
        .map(|w| {
            let w = w.split("::").next().unwrap_or(w);
            let w = w.split('#').next().unwrap_or(w);
            w.trim_end_matches([',', '.', ';', ':', ')']).to_owned()
        })
        .collect()
}

/// Every path of `text` named in an inline backticked span, or on a command
/// line (`cargo …`, `pegdyn …`, `bash …`) inside a fenced block. Other
/// lines of fenced blocks (sample output, code) are not read.
fn named_paths(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        let t = line.trim_start();
        if t.starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            if ["cargo ", "pegdyn ", "bash ", "PEGDYN_BLESS"]
                .iter()
                .any(|c| t.starts_with(c))
            {
                found.extend(paths_in(t.split('#').next().unwrap_or(t)));
            }
        } else {
            for span in line.split('`').skip(1).step_by(2) {
                found.extend(paths_in(span));
            }
        }
    }
    found
}

/// README.md, benches/README.md and every page of docs/.
pub(crate) fn doc_files() -> Vec<PathBuf> {
    let root = manifest_dir();
    let mut files = vec![root.join("README.md"), root.join("benches/README.md")];
    if let Ok(entries) = fs::read_dir(root.join("docs")) {
        for e in entries.flatten() {
            let p = e.path();
            if p.extension().is_some_and(|x| x == "md") {
                files.push(p);
            }
        }
    }
    files.sort();
    files
}

#[test]
fn every_path_named_in_the_docs_exists() {
    let root = manifest_dir();
    let mut missing = Vec::new();
    let mut checked = 0;
    for file in doc_files() {
        let Ok(text) = fs::read_to_string(&file) else {
            continue;
        };
        for p in named_paths(&text) {
            checked += 1;
            if !Path::new(&root).join(&p).exists() {
                let rel = file.strip_prefix(&root).unwrap_or(&file);
                missing.push(format!("{}: `{p}`", rel.display()));
            }
        }
    }
    assert!(
        checked > 20,
        "only {checked} paths found: is the scan broken?"
    );
    assert!(
        missing.is_empty(),
        "paths named in the docs that do not exist:\n{}",
        missing.join("\n")
    );
}

#[test]
fn scanner_finds_paths_in_spans_and_commands() {
    let text = "see `docs/a.md`, run `cargo run -- run scenes/b.toml --out out` and\n\
                `src/c.rs::f`; not `out/x.csv` nor `docs/generated/*.rs`\n\
                ```sh\ncargo run -- check scenes/d.toml   # comment src/x.rs\n\
                scenes/bad.toml: error: sample output\n```\n";
    assert_eq!(
        named_paths(text),
        ["docs/a.md", "scenes/b.toml", "src/c.rs", "scenes/d.toml"]
    );
}
