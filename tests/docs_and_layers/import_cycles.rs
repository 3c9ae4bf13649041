//! No import cycle between the files of `src/` or of `equations/src`: a
//! file-level cycle means neither file can be read, tested or changed
//! without the other. The graph and its definition: `import_graph.rs`.
//! A cycle known today is listed in [`EXCEPTIONS`] with what it is; the
//! test also fails when an exception no longer matches a cycle, so the list
//! shrinks as the cycles are broken.

use std::path::Path;

use crate::import_graph::{Graph, code_only, expand, without_test_items};

/// One known cycle: the tree, its files, and what the cycle is.
struct Exception {
    tree: &'static str,
    files: &'static [&'static str],
    reason: &'static str,
}

const EXCEPTIONS: &[Exception] = &[];
/// The cycles of `tree` (relative to the workspace root) not covered by an
/// exception, and the exceptions of `tree` that match no cycle.
fn check(tree: &str, crate_name: &str) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(tree);
    let graph = Graph::read(&root, crate_name);
    let cycles = graph.cycles();
    let mut problems = Vec::new();
    for cycle in &cycles {
        let covered = EXCEPTIONS
            .iter()
            .any(|e| e.tree == tree && cycle.iter().all(|f| e.files.contains(&f.as_str())));
        if !covered {
            let edges: Vec<String> = cycle
                .iter()
                .map(|f| {
                    let inside: Vec<&str> = graph
                        .dependencies(f)
                        .into_iter()
                        .filter(|d| cycle.iter().any(|c| c == d))
                        .collect();
                    format!("    {tree}/{f} -> {}", inside.join(", "))
                })
                .collect();
            problems.push(format!(
                "import cycle between {} files of {tree}:\n{}",
                cycle.len(),
                edges.join("\n")
            ));
        }
    }
    for e in EXCEPTIONS.iter().filter(|e| e.tree == tree) {
        let matched = cycles
            .iter()
            .any(|c| c.iter().any(|f| e.files.contains(&f.as_str())));
        if !matched {
            problems.push(format!(
                "exception no longer needed (no cycle among {:?} of {tree}): remove it",
                e.files
            ));
        }
    }
    problems
}

#[test]
fn no_import_cycle_between_files() {
    let mut problems = check("src", "pegdyn");
    problems.extend(check("equations/src", "pegdyn_equations"));
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(EXCEPTIONS.iter().all(|e| !e.reason.is_empty()));
}

#[test]
fn the_graph_reads_code_only_and_finds_a_cycle() {
    // Groups expand, `self` in a group is its prefix, renames drop.
    assert_eq!(
        expand("crate::a::{b, c::{d as e, self}}"),
        ["crate::a::b", "crate::a::c::d", "crate::a::c"]
    );
    // Comments, strings and characters are not code; lifetimes are.
    let code =
        code_only("let s = \"crate::x\"; // crate::y\n/* crate::z */ let c = '\"'; f::<'a>()");
    assert!(!code.contains("crate::"), "{code}");
    assert!(code.contains("'a"), "{code}");
    assert!(
        !without_test_items(
            "#[cfg(test)]\nmod tests { use crate::x; }\n#[cfg(test)]\nuse crate::y;"
        )
        .contains("crate::")
    );
    let sources = [
        ("lib.rs", "pub mod a;\npub mod b;\npub mod c;"),
        // a → b inline; a's own submodule and test module do not count.
        (
            "a/mod.rs",
            "mod inner;\npub use inner::X;\nfn f() { crate::b::g(); self::inner::h(); }\n#[cfg(test)]\nmod tests { use crate::c::Z; }",
        ),
        ("a/inner.rs", "use super::super::c::Y;"),
        // b → a through an inline module's `super::super`.
        ("b.rs", "mod deep { fn k() { super::super::a::f(); } }"),
        // c → a only in a string: no edge.
        ("c.rs", "const S: &str = \"crate::a::f\";"),
    ];
    let graph = Graph::from_sources(&sources, "demo");
    assert_eq!(graph.dependencies("a/mod.rs"), ["b.rs"]);
    assert_eq!(graph.dependencies("a/inner.rs"), ["c.rs"]);
    assert_eq!(graph.dependencies("b.rs"), ["a/mod.rs"]);
    assert!(graph.dependencies("c.rs").is_empty());
    assert_eq!(graph.cycles(), [["a/mod.rs", "b.rs"]]);
}
