//! The file-level import graph of a Rust source tree, and its cycles.
//!
//! A file A depends on a file B when a path written in A's code resolves
//! into B. Paths are read from `use` declarations (groups `{a, b::c}`
//! expanded, `self` in a group meaning the group's prefix) and from paths
//! written inline in code. Comments, string and character literals, and
//! items under `#[cfg(test)]` are not code. A path resolves from
//! - `crate::` or the crate's own name (`extern crate self as pegdyn`) at the
//!   crate root,
//! - `self::` and `super::` at the module it is written in, counting inline
//!   `mod name { … }` blocks,
//!
//! to the deepest existing file among its prefixes (`a::b::C` → `a/b.rs`,
//! `a/b/mod.rs`, `a.rs`, `a/mod.rs`, the crate root). A module's paths into
//! its own submodules are not dependencies: a parent contains its children
//! (declaring, re-exporting and dispatching to them is the module tree), so
//! `mod child;`, `pub use child::X` and `self::child::f()` stay inside it;
//! relative paths (`child::f()`) can only name children and are not read.
//! A child's path up to its parent (`super::Error`) and every path sideways
//! or across the tree count. In `src/`, `main.rs` is the root of a second
//! crate (the binary), whose `cli/` files reach the library by `pegdyn::`.
//!
//! A cycle is a strongly connected component of more than one file.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module path: the segments from the crate root.
type ModPath = Vec<String>;

/// The files of one source tree by module path, and their dependencies.
pub struct Graph {
    /// Module path → file path relative to the tree's root.
    files: BTreeMap<ModPath, String>,
    /// File → the files it depends on.
    edges: BTreeMap<String, BTreeSet<String>>,
}

/// The module path of a file relative to the tree's root (`a/b.rs`,
/// `a/b/mod.rs` → `a::b`; `lib.rs` → the root; `main.rs` → the binary's root,
/// kept apart as `<bin>`).
fn module_path(rel: &str) -> ModPath {
    let stem = rel.trim_end_matches(".rs");
    let mut parts: ModPath = stem.split('/').map(str::to_owned).collect();
    match parts.last().map(String::as_str) {
        Some("mod" | "lib") => {
            parts.pop();
        }
        Some("main") if parts.len() == 1 => parts = vec!["<bin>".to_owned()],
        _ => {}
    }
    parts
}

/// `text` with comments, string, byte-string and character literals
/// replaced by spaces (line breaks kept), so that only code is left.
pub fn code_only(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let blank = |ch: char| if ch == '\n' { '\n' } else { ' ' };
    let mut i = 0;
    while i < c.len() {
        let at = |k: usize| c.get(i + k).copied().unwrap_or('\0');
        if at(0) == '/' && at(1) == '/' {
            while i < c.len() && c[i] != '\n' {
                out.push(' ');
                i += 1;
            }
        } else if at(0) == '/' && at(1) == '*' {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    out.push(blank(c[i]));
                    i += 1;
                }
            }
        } else if let Some(hashes) = raw_string_start(&c, i) {
            // r"…", r#"…"#, br"…": ends at a quote followed by the hashes.
            let open = i + hashes.1;
            out.extend(std::iter::repeat_n(' ', hashes.1 + 1));
            i = open + 1;
            while i < c.len() {
                if c[i] == '"' && (1..=hashes.0).all(|k| c.get(i + k) == Some(&'#')) {
                    out.extend(std::iter::repeat_n(' ', hashes.0 + 1));
                    i += hashes.0 + 1;
                    break;
                }
                out.push(blank(c[i]));
                i += 1;
            }
        } else if at(0) == '"' || (at(0) == 'b' && at(1) == '"' && !ident_before(&c, i)) {
            let start = if at(0) == 'b' { 2 } else { 1 };
            out.extend(std::iter::repeat_n(' ', start));
            i += start;
            while i < c.len() && c[i] != '"' {
                let skip = if c[i] == '\\' { 2 } else { 1 };
                for k in 0..skip {
                    if let Some(&ch) = c.get(i + k) {
                        out.push(blank(ch));
                    }
                }
                i += skip;
            }
            out.push(' ');
            i += 1;
        } else if at(0) == '\'' && (at(2) == '\'' || (at(1) == '\\' && at(3) == '\'')) {
            // A character literal ('a', '\n'); a lifetime ('a) has no closing quote.
            let len = if at(1) == '\\' { 4 } else { 3 };
            out.extend(std::iter::repeat_n(' ', len));
            i += len;
        } else if at(0) == '\'' && at(1) == '\\' {
            // '\u{…}', '\x7f': to the closing quote.
            let mut j = i + 2;
            while j < c.len() && c[j] != '\'' {
                j += 1;
            }
            out.extend(std::iter::repeat_n(' ', j + 1 - i));
            i = j + 1;
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

fn ident_before(c: &[char], i: usize) -> bool {
    i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_')
}

/// `(hashes, offset of the opening quote)` when a raw string starts at `i`.
fn raw_string_start(c: &[char], i: usize) -> Option<(usize, usize)> {
    if ident_before(c, i) {
        return None;
    }
    let mut k = i;
    if c.get(k) == Some(&'b') {
        k += 1;
    }
    if c.get(k) != Some(&'r') {
        return None;
    }
    k += 1;
    let mut hashes = 0;
    while c.get(k) == Some(&'#') {
        hashes += 1;
        k += 1;
    }
    (c.get(k) == Some(&'"')).then_some((hashes, k - i))
}

/// The end (exclusive) of the brace block opening at `open`.
fn block_end(code: &str, open: usize) -> usize {
    let mut depth = 0;
    for (k, ch) in code[open..].char_indices() {
        match ch {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return open + k + 1;
                }
            }
            _ => {}
        }
    }
    code.len()
}

/// `code` with every item under `#[cfg(test)]` blanked (a block item to its
/// closing brace, any other to its semicolon).
pub fn without_test_items(code: &str) -> String {
    let mut code = code.to_owned();
    while let Some(start) = code.find("#[cfg(test)]") {
        let rest = &code[start..];
        let brace = rest.find('{');
        let semi = rest.find(';');
        let end = match (brace, semi) {
            (Some(b), Some(s)) if s < b => start + s + 1,
            (Some(b), _) => block_end(&code, start + b),
            (None, Some(s)) => start + s + 1,
            (None, None) => code.len(),
        };
        let blank: String = code[start..end]
            .chars()
            .map(|ch| if ch == '\n' { '\n' } else { ' ' })
            .collect();
        code.replace_range(start..end, &blank);
    }
    code
}

/// The flat paths of one use tree (`a::{b, c::{d, self}}` → `a::b`,
/// `a::c::d`, `a::c`), without `as` renames.
pub fn expand(tree: &str) -> Vec<String> {
    let tree: String = tree.split_whitespace().collect::<Vec<_>>().join(" ");
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or(tree);
        return vec![path.replace(' ', "")];
    };
    let prefix = tree[..open].replace(' ', "");
    let body = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let (mut parts, mut depth, mut current) = (Vec::new(), 0, String::new());
    for ch in body.chars() {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(std::mem::take(&mut current));
                continue;
            }
            _ => {}
        }
        current.push(ch);
    }
    parts.push(current);
    parts
        .iter()
        .map(|p| p.trim())
        .filter(|p| !p.is_empty())
        .flat_map(|p| {
            if p == "self" || p.starts_with("self as ") {
                vec![prefix.trim_end_matches("::").to_owned()]
            } else {
                expand(&format!("{prefix}{p}"))
            }
        })
        .collect()
}

/// Whether `code[i..]` starts the keyword `word` (not inside an identifier).
fn keyword_at(code: &str, i: usize, word: &str) -> bool {
    code[i..].starts_with(word)
        && !code[..i]
            .chars()
            .next_back()
            .is_some_and(|c| c.is_alphanumeric() || c == '_')
        && code[i + word.len()..]
            .chars()
            .next()
            .is_some_and(char::is_whitespace)
}

/// One path written in a file: its segments and the module it is written
/// in (an inline `mod` block's path).
struct Written {
    segments: Vec<String>,
    base: ModPath,
}

/// Every path written in `code` (already without comments, literals and
/// test items), inline `mod name { … }` blocks read at `base::name`.
fn written_paths(code: &str, base: &ModPath, out: &mut Vec<Written>) {
    let mut code = code.to_owned();
    // Inline modules first, each at its own path, then blanked.
    let mut i = 0;
    while let Some(k) = code[i..].find("mod ") {
        let at = i + k;
        i = at + 4;
        if !keyword_at(&code, at, "mod") {
            continue;
        }
        let rest = &code[at + 4..];
        let name: String = rest
            .trim_start()
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let after = rest.trim_start()[name.len()..].trim_start();
        if name.is_empty() || !after.starts_with('{') {
            continue;
        }
        let open = code.len() - after.len();
        let end = block_end(&code, open);
        let mut inner = base.clone();
        inner.push(name);
        written_paths(&code[open + 1..end - 1], &inner, out);
        let blank: String = code[open..end]
            .chars()
            .map(|ch| if ch == '\n' { '\n' } else { ' ' })
            .collect();
        code.replace_range(open..end, &blank);
    }
    // `use` declarations, then blanked.
    let mut i = 0;
    while let Some(k) = code[i..].find("use ") {
        let at = i + k;
        i = at + 4;
        if !keyword_at(&code, at, "use") {
            continue;
        }
        let Some(semi) = code[at..].find(';') else {
            break;
        };
        for path in expand(&code[at + 4..at + semi]) {
            out.push(Written {
                segments: path.split("::").map(str::to_owned).collect(),
                base: base.clone(),
            });
        }
        let blank: String = code[at..at + semi]
            .chars()
            .map(|ch| if ch == '\n' { '\n' } else { ' ' })
            .collect();
        code.replace_range(at..at + semi, &blank);
    }
    // Inline paths: identifiers joined by `::`.
    let c: Vec<char> = code.chars().collect();
    let mut k = 0;
    while k < c.len() {
        let starts = (c[k].is_alphabetic() || c[k] == '_') && (k == 0 || !is_ident(c[k - 1]));
        if !starts || (k > 0 && c[k - 1] == ':') {
            k += 1;
            continue;
        }
        let mut segments = Vec::new();
        let mut j = k;
        loop {
            let s = j;
            while j < c.len() && is_ident(c[j]) {
                j += 1;
            }
            segments.push(c[s..j].iter().collect::<String>());
            if c.get(j) == Some(&':')
                && c.get(j + 1) == Some(&':')
                && c.get(j + 2)
                    .is_some_and(|&ch| ch.is_alphabetic() || ch == '_')
            {
                j += 2;
            } else {
                break;
            }
        }
        if segments.len() > 1 {
            out.push(Written {
                segments,
                base: base.clone(),
            });
        }
        k = j.max(k + 1);
    }
}

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

impl Graph {
    /// Reads every `.rs` file under `root`; `crate_name` is the name the
    /// crate may use for itself (`extern crate self as …`).
    pub fn read(root: &Path, crate_name: &str) -> Graph {
        let mut rels = Vec::new();
        collect(root, root, &mut rels);
        let files: BTreeMap<ModPath, String> = rels
            .iter()
            .map(|rel| (module_path(rel), rel.clone()))
            .collect();
        let texts: Vec<(String, String)> = rels
            .iter()
            .map(|rel| {
                let text = std::fs::read_to_string(root.join(rel))
                    .unwrap_or_else(|e| panic!("read {rel}: {e}"));
                (rel.clone(), text)
            })
            .collect();
        Graph::from_texts(&texts, crate_name, files)
    }

    /// The graph of `(relative path, text)` pairs.
    pub fn from_sources(sources: &[(&str, &str)], crate_name: &str) -> Graph {
        let texts: Vec<(String, String)> = sources
            .iter()
            .map(|(r, t)| ((*r).to_owned(), (*t).to_owned()))
            .collect();
        let files = texts
            .iter()
            .map(|(rel, _)| (module_path(rel), rel.clone()))
            .collect();
        Graph::from_texts(&texts, crate_name, files)
    }

    fn from_texts(
        texts: &[(String, String)],
        crate_name: &str,
        files: BTreeMap<ModPath, String>,
    ) -> Graph {
        let mut graph = Graph {
            files,
            edges: BTreeMap::new(),
        };
        for (rel, text) in texts {
            let module = module_path(rel);
            let in_bin = module.first().is_some_and(|m| m == "<bin>") || rel.starts_with("cli/");
            let code = without_test_items(&code_only(text));
            let mut paths = Vec::new();
            written_paths(&code, &module, &mut paths);
            for w in paths {
                if let Some(target) = graph.resolve(&w, crate_name, in_bin) {
                    // The file itself, or one of its own submodules.
                    if target.starts_with(module.as_slice()) {
                        continue;
                    }
                    let to = graph.files[&target].clone();
                    graph.edges.entry(rel.clone()).or_default().insert(to);
                }
            }
        }
        graph
    }

    /// The module of the file a written path resolves into, if any.
    fn resolve(&self, w: &Written, crate_name: &str, in_bin: bool) -> Option<ModPath> {
        let segs = &w.segments;
        let first = segs[0].as_str();
        let mut path: ModPath = match first {
            "crate" => {
                if in_bin && segs.get(1).is_some_and(|s| s != "cli") {
                    return None;
                }
                Vec::new()
            }
            s if s == crate_name => Vec::new(),
            "self" => w.base.clone(),
            "super" => {
                let mut p = w.base.clone();
                p.pop();
                p
            }
            _ => return None,
        };
        let mut rest = segs[1..].iter().peekable();
        while rest.peek().is_some_and(|s| *s == "super") {
            path.pop();
            rest.next();
        }
        path.extend(rest.cloned());
        (0..=path.len())
            .rev()
            .map(|n| path[..n].to_vec())
            .find(|p| self.files.contains_key(p) && !(p.is_empty() && in_bin))
    }

    /// The files a file depends on.
    pub fn dependencies(&self, file: &str) -> Vec<&str> {
        self.edges
            .get(file)
            .map(|s| s.iter().map(String::as_str).collect())
            .unwrap_or_default()
    }

    /// Every cycle: the strongly connected components of more than one
    /// file (Tarjan), each sorted, in sorted order.
    pub fn cycles(&self) -> Vec<Vec<String>> {
        struct Tarjan<'g> {
            graph: &'g Graph,
            index: BTreeMap<&'g str, usize>,
            low: BTreeMap<&'g str, usize>,
            stack: Vec<&'g str>,
            on_stack: BTreeSet<&'g str>,
            found: Vec<Vec<String>>,
        }
        impl<'g> Tarjan<'g> {
            fn visit(&mut self, v: &'g str) {
                let n = self.index.len();
                self.index.insert(v, n);
                self.low.insert(v, n);
                self.stack.push(v);
                self.on_stack.insert(v);
                for w in self.graph.edges.get(v).into_iter().flatten() {
                    let w = w.as_str();
                    if !self.index.contains_key(w) {
                        self.visit(w);
                        let lw = self.low[w];
                        let lv = self.low.get_mut(v).expect("visited");
                        *lv = (*lv).min(lw);
                    } else if self.on_stack.contains(w) {
                        let iw = self.index[w];
                        let lv = self.low.get_mut(v).expect("visited");
                        *lv = (*lv).min(iw);
                    }
                }
                if self.low[v] == self.index[v] {
                    let mut component = Vec::new();
                    while let Some(w) = self.stack.pop() {
                        self.on_stack.remove(w);
                        component.push(w.to_owned());
                        if w == v {
                            break;
                        }
                    }
                    if component.len() > 1 {
                        component.sort();
                        self.found.push(component);
                    }
                }
            }
        }
        let mut t = Tarjan {
            graph: self,
            index: BTreeMap::new(),
            low: BTreeMap::new(),
            stack: Vec::new(),
            on_stack: BTreeSet::new(),
            found: Vec::new(),
        };
        for file in self.files.values() {
            if !t.index.contains_key(file.as_str()) {
                t.visit(file);
            }
        }
        t.found.sort();
        t.found
    }
}

/// Every `.rs` file under `dir`, relative to `root`, with `/` separators.
fn collect(root: &Path, dir: &Path, out: &mut Vec<String>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("read {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            collect(root, &path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let rel = path.strip_prefix(root).expect("under root");
            out.push(rel.to_string_lossy().replace('\\', "/"));
        }
    }
}
