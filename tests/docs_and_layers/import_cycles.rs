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

const EXCEPTIONS: &[Exception] = &[
    Exception {
        tree: "src",
        files: &[
            "compliant_peg_3d/curvature.rs",
            "compliant_peg_3d/face.rs",
            "compliant_peg_3d/jacobian.rs",
            "compliant_peg_3d/merge.rs",
            "compliant_peg_3d/prune.rs",
            "compliant_peg_3d/search.rs",
            "compliant_peg_3d/stiffness.rs",
            "compliant_peg_3d/system.rs",
        ],
        reason: "the compliant 3-D peg's contact law is written twice, at f64 in \
                 system.rs and at the dual number in jacobian.rs, and each calls the \
                 other's helpers; the contact search (search.rs) and the merge of its \
                 candidates (merge.rs) share the contact pair both ways; the axis and \
                 the frame helpers live in system.rs, which search, prune, face, \
                 curvature and stiffness import while system.rs calls all of them",
    },
    Exception {
        tree: "src",
        files: &["output/atomic.rs", "output/csv.rs", "output/memory.rs"],
        reason: "in-memory output is a magic directory: memory.rs keeps captured tables \
                 through the CSV writer, while the CSV and atomic writers ask memory.rs \
                 whether a path is in memory",
    },
    Exception {
        tree: "src",
        files: &["rigid_peg/generated_model.rs", "rigid_peg/prescribed.rs"],
        reason: "the rigid peg's prescribed-motion reactions type lives in prescribed.rs, \
                 which calls the generated model's adapter, and the adapter returns that \
                 type",
    },
    Exception {
        tree: "src",
        files: &["scene/fig9.rs", "scene/ranges/rigid.rs"],
        reason: "the Fig. 9 scene checks its fields with the rigid peg's ranges, and the \
                 ranges read the scene's peg table type",
    },
    Exception {
        tree: "equations/src",
        files: &[
            "codegen/emit.rs",
            "codegen/lower/mod.rs",
            "codegen/lower/sign.rs",
            "codegen/schedule.rs",
            "codegen/tokens.rs",
            "codegen/value_names.rs",
            "eval.rs",
            "simplify/mod.rs",
        ],
        reason: "the simplifier folds constants with the interpreter (eval.rs), the \
                 interpreter evaluates in the emitter's order (codegen/schedule.rs), the \
                 schedule and the sign folding of the lowering call each other, the \
                 lowering calls the simplifier; emit.rs and tokens.rs call each other",
    },
    Exception {
        tree: "equations/src",
        files: &["simplify/rules.rs", "simplify/stable.rs"],
        reason: "the table of rewrites (rules.rs) names the stable numerical rewrites \
                 (stable.rs), which measure their result with the table's sum measure",
    },
];

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
