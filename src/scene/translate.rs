//! Translation of serde/TOML deserialization errors into [`SceneError`]s
//! that name the field by its dotted path and speak the scene file's
//! language: "a non-negative integer", "a table", "an array", never the
//! Rust types the tables are read into (`u64`, `usize`, `map`, `as i128`).

use crate::error::SceneError;

/// Translates `e`; `found_at(path)` describes the value written at the
/// dotted `path` (its TOML type and text, e.g. ``a table `{ a = 1 }` ``),
/// `None` when it cannot be found.
///
/// The path comes from the error's key trail, which `toml` prints as a
/// trailing ``in `a.b` `` line when the error carries no input text (ours
/// never does: the deserializer is built from a tree).
pub fn translate(e: toml::de::Error, found_at: impl Fn(&str) -> Option<String>) -> SceneError {
    let message = e.message().to_string();
    let shown = e.to_string();
    let trail = shown
        .lines()
        .rev()
        .find_map(|l| l.strip_prefix("in `").and_then(|l| l.strip_suffix('`')))
        .unwrap_or("")
        .to_string();
    let join = |name: &str| {
        if trail.is_empty() {
            name.to_string()
        } else {
            format!("{trail}.{name}")
        }
    };
    let ticked = |s: &str| -> Option<(String, String)> {
        let rest = s.strip_prefix('`')?;
        let end = rest.find('`')?;
        Some((rest[..end].to_string(), rest[end + 1..].to_string()))
    };
    if let Some((name, _)) = message.strip_prefix("missing field ").and_then(ticked) {
        return SceneError::Missing { field: join(&name) };
    }
    if let Some((name, rest)) = message.strip_prefix("unknown field ").and_then(ticked) {
        let expected = rest.trim_start_matches(", ").trim();
        let expected = if expected.starts_with("there are no fields") {
            "this table takes no fields".to_string()
        } else {
            expected.to_string()
        };
        return SceneError::Unknown {
            field: join(&name),
            expected,
        };
    }
    if let Some((name, rest)) = message.strip_prefix("unknown variant ").and_then(ticked) {
        return SceneError::Invalid {
            field: trail,
            value: format!("{name:?}"),
            reason: rest.trim_start_matches(", ").trim().to_string(),
        };
    }
    if let Some(rest) = message.strip_prefix("invalid value: ")
        && let Some((value, expected)) = rest.rsplit_once(", expected ")
    {
        return SceneError::Invalid {
            field: trail,
            value: plain_value(value),
            reason: format!("must be {}", plain_type(expected)),
        };
    }
    if let Some(rest) = message.strip_prefix("invalid type: ")
        && let Some((found, expected)) = rest.rsplit_once(", expected ")
    {
        return SceneError::WrongType {
            found: found_at(&trail).unwrap_or_else(|| plain_found(found)),
            field: trail,
            expected: plain_type(expected),
        };
    }
    SceneError::Invalid {
        field: trail,
        value: String::from("(see reason)"),
        reason: plain_text(&message),
    }
}

/// A type as serde names it (`u64`, `f64`, `map`, `struct Peg`), in the
/// words of a TOML file.
pub fn plain_type(t: &str) -> String {
    match t.trim() {
        "u8" | "u16" | "u32" | "u64" | "u128" | "usize" => "a non-negative integer".into(),
        "i8" | "i16" | "i32" | "i64" | "i128" | "isize" => "an integer".into(),
        "f32" | "f64" => "a number".into(),
        "bool" | "a boolean" => "true or false".into(),
        "string" | "a string" | "str" | "char" => "a string".into(),
        "map" | "a map" => "a table".into(),
        "sequence" | "a sequence" => "an array".into(),
        t if t.starts_with("struct ") || t.starts_with("a map") => "a table".into(),
        t if t.starts_with("a sequence") || t.starts_with("tuple") => "an array".into(),
        t => plain_text(t),
    }
}

/// A value as serde's `invalid value` describes it (``integer `-3` ``,
/// ``floating point `1.5` ``, ``integer `…` as i128``), as written.
pub fn plain_value(v: &str) -> String {
    let v = v.trim();
    let inner = v
        .split_once('`')
        .and_then(|(_, rest)| rest.rsplit_once('`'))
        .map(|(inner, _)| inner);
    match inner {
        Some(inner) => inner.to_string(),
        None => plain_text(v),
    }
}

/// What serde's `invalid type` found, in TOML's words, when the value
/// itself cannot be looked up.
pub fn plain_found(f: &str) -> String {
    let f = f.trim();
    let (kind, rest) = f.split_once(' ').unwrap_or((f, ""));
    let written = plain_value(rest);
    let with = |what: &str| {
        if written.is_empty() {
            what.to_string()
        } else {
            format!("{what} {written}")
        }
    };
    match kind {
        "map" => "a table".into(),
        "sequence" => "an array".into(),
        "floating" => with("a float"),
        "integer" => with("an integer"),
        "boolean" => with("a boolean"),
        "string" => with("a string"),
        _ => plain_text(f),
    }
}

/// `text` with serde's Rust type words replaced by TOML's.
pub fn plain_text(text: &str) -> String {
    let mut out = text.replace(" as i128", "").replace(" as u128", "");
    for (rust, toml) in [
        ("usize", "non-negative integer"),
        ("u64", "non-negative integer"),
        ("u32", "non-negative integer"),
        ("i64", "integer"),
        ("f64", "number"),
        ("found map", "found a table"),
        ("found sequence", "found an array"),
    ] {
        out = out.replace(rust, toml);
    }
    out
}
