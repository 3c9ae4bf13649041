//! Scene texts for tests: a shipped scene as written, and one line of it
//! changed.

use std::path::Path;

/// The text of the shipped scene `scenes/<name>.toml`.
pub fn shipped(name: &str) -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.toml")),
    )
    .unwrap_or_else(|e| panic!("the shipped scene {name} reads: {e}"))
}

/// `text` with the line starting `key =` replaced by `key = value` (the
/// line must exist).
pub fn with(text: &str, key: &str, value: &str) -> String {
    let line = text
        .lines()
        .find(|l| l.starts_with(&format!("{key} =")))
        .unwrap_or_else(|| panic!("no {key}"));
    text.replacen(line, &format!("{key} = {value}"), 1)
}
