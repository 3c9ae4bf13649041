//! The fields of a scene text by their dotted paths, with where their
//! values are written: for tests that change one value at a time and check
//! what the refusal says and where it puts it.

#![allow(dead_code)]

use std::ops::Range;

use toml::de::{DeTable, DeValue};

/// A value written in a scene: its dotted path (`grid.lateral_errors[1]`
/// for an array entry), its byte span and its 1-based line.
#[derive(Debug, Clone)]
pub struct Field {
    /// Dotted path, e.g. `peg.rim_fillet`.
    pub path: String,
    /// Byte span of the value.
    pub span: Range<usize>,
    /// 1-based line of the value.
    pub line: usize,
    /// Whether the value is an integer (else a float).
    pub integer: bool,
}

/// Every numeric value of `text` (floats and integers, in tables and
/// arrays), in file order.
pub fn numeric_fields(text: &str) -> Vec<Field> {
    fn walk(text: &str, prefix: &str, v: &DeValue<'_>, span: Range<usize>, out: &mut Vec<Field>) {
        let line = text[..span.start].matches('\n').count() + 1;
        match v {
            DeValue::Integer(_) | DeValue::Float(_) => out.push(Field {
                path: prefix.to_string(),
                span,
                line,
                integer: matches!(v, DeValue::Integer(_)),
            }),
            DeValue::Array(a) => {
                for (k, e) in a.iter().enumerate() {
                    walk(text, &format!("{prefix}[{k}]"), e.get_ref(), e.span(), out);
                }
            }
            DeValue::Table(t) => {
                for (k, e) in t.iter() {
                    let path = if prefix.is_empty() {
                        k.get_ref().to_string()
                    } else {
                        format!("{prefix}.{}", k.get_ref())
                    };
                    walk(text, &path, e.get_ref(), e.span(), out);
                }
            }
            _ => {}
        }
    }
    let Ok(root) = DeTable::parse(text) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (k, e) in root.get_ref().iter() {
        walk(text, k.get_ref(), e.get_ref(), e.span(), &mut out);
    }
    out.sort_by_key(|f| f.span.start);
    out
}

/// `text` with the value of `field` replaced by `by`.
pub fn replaced(text: &str, field: &Field, by: &str) -> String {
    format!(
        "{}{by}{}",
        &text[..field.span.start],
        &text[field.span.end..]
    )
}

/// Words of the Rust types scenes are read into, which no message to a
/// user may contain (`f64`, the number format, is a word of the domain).
pub const JARGON: [&str; 10] = [
    "u64",
    "usize",
    "u32",
    "i64",
    "i128",
    "found map",
    "sequence",
    "Some(",
    "= None",
    "floating point",
];
