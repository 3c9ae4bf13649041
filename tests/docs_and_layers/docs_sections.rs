//! Docs that point at a section that moved: wherever README.md, a page of
//! docs/ or of docs/bench/ names a page with the titles of its sections
//! (`` `docs/BENCHMARKS.md`, "Stiff contact" ``, `docs/bench-methods.md`
//! ("Whole runs", "The floor")), each title must begin a heading of that
//! page, or a bold run-in heading (`**Event accuracy.**`), or appear in
//! one.

use crate::docs_paths::{doc_files, manifest_dir};
use std::fs;

/// The `(page, title)` pairs of `text` (whitespace folded to single
/// spaces): a `docs/….md` path, then, after an optional backtick, comma,
/// `section` or opening parenthesis, one or more quoted titles separated
/// by commas.
fn section_refs(text: &str) -> Vec<(String, String)> {
    let t: String = text.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut found = Vec::new();
    let mut rest = t.as_str();
    while let Some(i) = rest.find("docs/") {
        let before = rest[..i].chars().next_back();
        let tail = &rest[i..];
        rest = &tail[5..];
        if before.is_some_and(|c| c.is_alphanumeric() || c == '/') {
            continue;
        }
        let end = tail
            .find(|c: char| !(c.is_alphanumeric() || "_./-".contains(c)))
            .unwrap_or(tail.len());
        let page = tail[..end].trim_end_matches('.');
        if !page.ends_with(".md") {
            continue;
        }
        let mut s = &tail[page.len()..];
        s = s
            .trim_start_matches('`')
            .trim_start_matches(',')
            .trim_start();
        s = s.strip_prefix("section ").unwrap_or(s);
        s = s.strip_prefix('(').unwrap_or(s);
        while let Some(quoted) = s.strip_prefix('"') {
            let Some(close) = quoted.find('"') else { break };
            found.push((page.to_owned(), quoted[..close].to_owned()));
            s = quoted[close + 1..].trim_start_matches(',').trim_start();
        }
    }
    found
}

/// Whether `title` heads a section of `page` (its text).
fn has_section(page: &str, title: &str) -> bool {
    let folded: String = page.split_whitespace().collect::<Vec<_>>().join(" ");
    page.lines().filter(|l| l.starts_with('#')).any(|l| {
        l.split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
            .contains(title)
    }) || folded.contains(&format!("**{title}"))
}

#[test]
fn every_section_named_in_the_docs_exists() {
    let root = manifest_dir();
    let mut files = doc_files();
    if let Ok(entries) = fs::read_dir(root.join("docs/bench")) {
        files.extend(
            entries
                .flatten()
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "md")),
        );
    }
    let mut checked = 0;
    let mut missing = Vec::new();
    for file in &files {
        let Ok(text) = fs::read_to_string(file) else {
            continue;
        };
        for (page, title) in section_refs(&text) {
            let Ok(target) = fs::read_to_string(root.join(&page)) else {
                continue; // a missing page is the path test's to report
            };
            checked += 1;
            if !has_section(&target, &title) {
                let from = file.strip_prefix(&root).unwrap_or(file).display();
                missing.push(format!("{from}: {page}, \"{title}\""));
            }
        }
    }
    assert!(
        checked >= 30,
        "only {checked} section references found: the scanner is broken"
    );
    assert!(
        missing.is_empty(),
        "sections that do not exist:\n{}",
        missing.join("\n")
    );
}

#[test]
fn the_section_scanner_reads_the_forms_the_docs_use() {
    let text = "see (`docs/BENCHMARKS.md`, \"Stiff\ncontact\") and docs/bench-methods.md\n\
                (\"Whole runs\", \"The floor\"); docs/python.md, section \"Sweeps\"; \
                not mydocs/x.md \"No\" nor docs/a.svg \"No\"";
    assert_eq!(
        section_refs(text),
        [
            ("docs/BENCHMARKS.md", "Stiff contact"),
            ("docs/bench-methods.md", "Whole runs"),
            ("docs/bench-methods.md", "The floor"),
            ("docs/python.md", "Sweeps"),
        ]
        .map(|(a, b)| (a.to_owned(), b.to_owned()))
    );
    let page = "# Top\n\n## Stiff contact: RODAS4\n\n**Event accuracy.** text";
    assert!(has_section(page, "Stiff contact"));
    assert!(has_section(page, "Event accuracy"));
    assert!(!has_section(page, "Whole runs"));
}
