//! Rust names in the emitted code: the keywords no name may take,
//! snake_case identifiers for symbol names, and the per-function namer
//! that hands out unique `let` names.

use std::collections::BTreeSet;

/// The Rust keywords, strict and reserved (edition 2024), none of which
/// may name a model symbol or a generated `let`: the one list read by the
/// name check ([`is_snake_ident`]) and the namer ([`Names`]).
pub(crate) const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut",
    "pub", "ref", "return", "self", "static", "struct", "super", "trait", "true", "type", "unsafe",
    "use", "where", "while", "abstract", "become", "box", "do", "final", "macro", "override",
    "priv", "try", "typeof", "unsized", "virtual", "yield",
];

/// True for a snake_case Rust identifier that is not a keyword
/// (the strict and reserved keywords of edition 2024).
pub fn is_snake_ident(s: &str) -> bool {
    let mut cs = s.chars();
    let first_ok = cs
        .next()
        .is_some_and(|c| c.is_ascii_lowercase() || c == '_');
    first_ok
        && s != "_"
        && s.chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
        && !KEYWORDS.contains(&s)
}

/// Names the generated code itself uses (besides the Rust keywords,
/// [`KEYWORDS`]), so no `let` may take them.
const GENERATED_NAMES: &[&str] = &["f64", "nalgebra"];

/// ASCII names of Greek letters (lower and upper case map to the same).
fn greek(c: char) -> Option<&'static str> {
    const LOWER: [&str; 25] = [
        "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
        "lambda", "mu", "nu", "xi", "omicron", "pi", "rho", "sigma", "sigma", "tau", "upsilon",
        "phi", "chi", "psi", "omega",
    ];
    let k = match c {
        'α'..='ω' => c as u32 - 'α' as u32,
        'Α'..='Ω' => c as u32 - 'Α' as u32,
        _ => return None,
    };
    LOWER.get(k as usize).copied()
}

/// A snake_case ASCII identifier for a symbol name: Greek letters spelled
/// out (`γ` → `gamma`), a combining dot as `dot`, camelCase split, anything
/// else as `_`.
pub fn snake_case(name: &str) -> String {
    let mut out = String::new();
    let mut prev_lower = false;
    for c in name.chars() {
        if let Some(w) = greek(c) {
            if prev_lower {
                out.push('_');
            }
            out.push_str(w);
            prev_lower = true;
        } else if c == '\u{307}' {
            out.push_str("dot");
            prev_lower = true;
        } else if c.is_ascii_uppercase() {
            if prev_lower {
                out.push('_');
            }
            out.push(c.to_ascii_lowercase());
            prev_lower = false;
        } else if c.is_ascii_alphanumeric() {
            out.push(c);
            prev_lower = c.is_ascii_lowercase() || c.is_ascii_digit();
        } else {
            out.push('_');
            prev_lower = false;
        }
    }
    let out = out.trim_matches('_').to_owned();
    match out.chars().next() {
        None => "s".to_owned(),
        Some(c) if c.is_ascii_digit() => format!("s{out}"),
        _ => out,
    }
}

/// Hands out identifiers unique within one function.
#[derive(Default)]
pub struct Names {
    taken: BTreeSet<String>,
    counter: usize,
}

impl Names {
    /// A name set that already holds `reserved` (e.g. the input names).
    pub fn new<'a>(reserved: impl IntoIterator<Item = &'a str>) -> Names {
        let mut taken: BTreeSet<String> = KEYWORDS
            .iter()
            .chain(GENERATED_NAMES)
            .map(|s| (*s).to_owned())
            .collect();
        taken.extend(reserved.into_iter().map(str::to_owned));
        Names { taken, counter: 0 }
    }

    /// The next free `{prefix}{k}`, k = 0, 1, 2, ...
    pub fn numbered(&mut self, prefix: &str) -> String {
        loop {
            let name = format!("{prefix}{}", self.counter);
            self.counter += 1;
            if self.taken.insert(name.clone()) {
                return name;
            }
        }
    }

    /// `base`, or `base_2`, `base_3`, ... whichever is free first.
    pub fn fresh(&mut self, base: &str) -> String {
        let mut name = base.to_owned();
        let mut k = 2;
        while self.taken.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        self.taken.insert(name.clone());
        name
    }
}
