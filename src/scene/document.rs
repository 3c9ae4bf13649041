//! A parsed scene file before it is handed to its kind: the TOML tree with
//! source spans, the `kind` tag, and translation of TOML/serde errors into
//! [`SceneError`]s that name the field by its dotted path.

use serde::Deserialize;
use serde::de::DeserializeOwned;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use crate::error::{Located, Location, SceneError, SceneErrors};

/// Top-level keys every scene may have, whatever its kind.
pub const COMMON_KEYS: [&str; 3] = ["kind", "description", "limits"];

/// A syntactically valid scene file.
pub struct Document<'a> {
    text: &'a str,
    root: Spanned<DeTable<'a>>,
    kind: String,
    description: Option<String>,
}

impl<'a> Document<'a> {
    /// Parses `text` as TOML and reads the common keys `kind` (required,
    /// string) and `description` (optional, string).
    pub fn parse(text: &'a str) -> Result<Self, SceneErrors> {
        let root = DeTable::parse(text).map_err(|e| {
            let at = e.span().map(|s| location(text, s.start));
            SceneErrors {
                errors: vec![Located {
                    error: SceneError::Syntax {
                        message: e.message().to_string(),
                    },
                    at,
                }],
            }
        })?;
        let wide = wide_integers(text, &root);
        if !wide.is_empty() {
            return Err(SceneErrors { errors: wide });
        }
        let mut doc = Document {
            text,
            root,
            kind: String::new(),
            description: None,
        };
        doc.kind = doc.string("kind")?.ok_or_else(|| {
            SceneErrors::from(SceneError::Missing {
                field: "kind".into(),
            })
        })?;
        doc.description = doc.string("description")?;
        Ok(doc)
    }

    fn string(&self, key: &str) -> Result<Option<String>, SceneErrors> {
        match self.root.get_ref().get(key) {
            None => Ok(None),
            Some(v) => match v.get_ref() {
                DeValue::String(s) => Ok(Some(s.to_string())),
                other => Err(self.locate(SceneError::WrongType {
                    field: key.into(),
                    found: type_name(other).into(),
                    expected: "a string".into(),
                })),
            },
        }
    }

    /// The scene kind, e.g. `"pendulum"`.
    pub fn kind(&self) -> &str {
        &self.kind
    }

    /// The optional free-text description.
    pub fn description(&self) -> Option<&str> {
        self.description.as_deref()
    }

    /// The optional `[limits]` table ([`crate::scene::limits::Limits`]),
    /// defaults where absent.
    ///
    /// # Errors
    /// A wrong type or an unknown key in `[limits]`, located.
    pub fn limits(&self) -> Result<crate::scene::limits::Limits, SceneErrors> {
        #[derive(serde::Deserialize)]
        struct Common {
            #[serde(default)]
            limits: crate::scene::limits::Limits,
        }
        let root = self.root.clone();
        Common::deserialize(toml::de::Deserializer::from(root))
            .map(|c| c.limits)
            .map_err(|e| {
                let at = e.span().map(|s| location(self.text, s.start));
                let error = translate(e);
                self.locate_all(SceneErrors {
                    errors: vec![Located { error, at }],
                })
            })
    }

    /// Deserializes the kind-specific part of the document (everything but
    /// [`COMMON_KEYS`]) into `T`. Use `#[serde(deny_unknown_fields)]` on `T`
    /// and its tables so that typos are reported.
    pub fn body<T: DeserializeOwned>(&self) -> Result<T, SceneErrors> {
        let mut root = self.root.clone();
        for key in COMMON_KEYS {
            root.get_mut().remove(key);
        }
        T::deserialize(toml::de::Deserializer::from(root)).map_err(|e| {
            let at = e.span().map(|s| location(self.text, s.start));
            let error = translate(e);
            self.locate_all(SceneErrors {
                errors: vec![Located { error, at }],
            })
        })
    }

    /// Attaches the file location of each error's field, where it can be found.
    pub fn locate_all(&self, mut errors: SceneErrors) -> SceneErrors {
        for e in &mut errors.errors {
            if e.at.is_none() {
                e.at = e
                    .error
                    .field()
                    .and_then(|f| self.span_of(f))
                    .map(|s| location(self.text, s));
            }
        }
        errors
    }

    fn locate(&self, error: SceneError) -> SceneErrors {
        self.locate_all(SceneErrors::from(error))
    }

    /// Byte offset of the value at dotted `path`, or of its deepest existing
    /// parent table's key when the field itself is absent.
    fn span_of(&self, path: &str) -> Option<usize> {
        let mut table = self.root.get_ref();
        let mut found = None;
        for key in path.split('.') {
            let Some((k, v)) = table.get_key_value(key) else {
                return found;
            };
            found = Some(k.span().start);
            match v.get_ref() {
                DeValue::Table(t) => table = t,
                _ => return Some(v.span().start),
            }
        }
        found
    }
}

/// Every integer of the tree outside TOML's 64-bit signed range (the
/// parser keeps integers as text, so `2^63` would otherwise reach the
/// fields that take `u64` and be refused by every other TOML reader),
/// named by its dotted path and located. The walk keeps its own stack: a
/// deeply nested file cannot exhaust the thread's.
fn wide_integers(text: &str, root: &Spanned<DeTable<'_>>) -> Vec<Located> {
    type Stack<'t, 'i> = Vec<(String, &'t Spanned<DeValue<'i>>)>;
    fn push_table<'t, 'i>(stack: &mut Stack<'t, 'i>, path: &str, t: &'t DeTable<'i>) {
        for (k, v) in t.iter() {
            let key = k.get_ref();
            let sub = if path.is_empty() {
                key.to_string()
            } else {
                format!("{path}.{key}")
            };
            stack.push((sub, v));
        }
    }
    let mut found = Vec::new();
    let mut stack = Stack::new();
    push_table(&mut stack, "", root.get_ref());
    while let Some((path, v)) = stack.pop() {
        match v.get_ref() {
            DeValue::Integer(i) if i64::from_str_radix(i.as_str(), i.radix()).is_err() => {
                found.push(Located {
                    error: SceneError::Invalid {
                        field: path,
                        value: text.get(v.span()).unwrap_or(i.as_str()).to_string(),
                        reason: format!(
                            "a TOML integer is a whole number from {} to {}",
                            i64::MIN,
                            i64::MAX
                        ),
                    },
                    at: Some(location(text, v.span().start)),
                });
            }
            DeValue::Table(t) => push_table(&mut stack, &path, t),
            DeValue::Array(a) => {
                for (k, item) in a.iter().enumerate() {
                    stack.push((format!("{path}[{k}]"), item));
                }
            }
            _ => {}
        }
    }
    found.sort_by_key(|l| l.at.map(|a| (a.line, a.column)));
    found
}

/// 1-based line and column of byte offset `at` in `text`.
pub fn location(text: &str, at: usize) -> Location {
    let at = at.min(text.len());
    let before = text.get(..at).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let column = before.get(line_start..).map_or(0, |s| s.chars().count()) + 1;
    Location { line, column }
}

fn type_name(v: &DeValue<'_>) -> &'static str {
    match v {
        DeValue::String(_) => "a string",
        DeValue::Integer(_) => "an integer",
        DeValue::Float(_) => "a float",
        DeValue::Boolean(_) => "a boolean",
        DeValue::Datetime(_) => "a datetime",
        DeValue::Array(_) => "an array",
        DeValue::Table(_) => "a table",
    }
}

/// Translates a serde/TOML deserialization error into a [`SceneError`] with
/// the dotted field path. The path comes from the error's key trail, which
/// `toml` prints as a trailing ``in `a.b` `` line when the error carries no
/// input text (ours never does: the deserializer is built from a tree).
fn translate(e: toml::de::Error) -> SceneError {
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
    if let Some(rest) = message.strip_prefix("invalid value: ") {
        if let Some((value, expected)) = rest.rsplit_once(", expected ") {
            return SceneError::Invalid {
                field: trail,
                value: value.to_string(),
                reason: format!("expected {expected}"),
            };
        }
    }
    if let Some(rest) = message.strip_prefix("invalid type: ") {
        if let Some((found, expected)) = rest.rsplit_once(", expected ") {
            let expected = match expected {
                "f64" => "a number",
                "usize" | "u64" | "u32" => "a non-negative integer",
                "a string" | "string" => "a string",
                e => e,
            };
            return SceneError::WrongType {
                field: trail,
                found: found.to_string(),
                expected: expected.to_string(),
            };
        }
    }
    SceneError::Invalid {
        field: trail,
        value: String::from("(see reason)"),
        reason: message,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Body {
        peg: Peg,
    }
    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Peg {
        mass: f64,
        n: usize,
    }

    fn err(text: &str) -> SceneErrors {
        Document::parse(text)
            .and_then(|d| d.body::<Body>())
            .unwrap_err()
    }

    #[test]
    fn structural_errors_name_the_dotted_field() {
        let e = err("kind = 'x'\n[peg]\nn = 1\n");
        assert!(matches!(&e.errors[0].error, SceneError::Missing { field } if field == "peg.mass"));
        let e = err("kind = 'x'\n[peg]\nmass = 1.0\nn = 1\nmas = 2\n");
        assert!(
            matches!(&e.errors[0].error, SceneError::Unknown { field, .. } if field == "peg.mas")
        );
        assert_eq!(e.errors[0].at, Some(Location { line: 5, column: 1 }));
        let e = err("kind = 'x'\n[peg]\nmass = true\nn = 1\n");
        assert!(
            matches!(&e.errors[0].error, SceneError::WrongType { field, found, .. } if field == "peg.mass" && found.contains("true")),
            "{e}"
        );
        let e = err("kind = 'x'\n[peg]\nmass = 1.0\nn = -3\n");
        assert!(
            e.to_string().contains("peg.n") && e.to_string().contains("-3"),
            "{e}"
        );
    }

    #[test]
    fn kind_is_required_and_a_string() {
        let e = Document::parse("[peg]\n").err().unwrap();
        assert!(matches!(&e.errors[0].error, SceneError::Missing { field } if field == "kind"));
        let e = Document::parse("kind = 3\n").err().unwrap();
        assert!(
            matches!(&e.errors[0].error, SceneError::WrongType { field, .. } if field == "kind")
        );
    }

    #[test]
    fn integers_past_64_bits_are_refused_where_they_stand() {
        let text = "kind = \"pendulum\"\n[limits]\nmax_steps = 10000000000000000000\n\
                    [grid]\nn = [1, 0x8000000000000000, -9223372036854775808]\n\
                    deep = { a = { b = -9223372036854775809 } }\n";
        let e = Document::parse(text).err().unwrap();
        let got: Vec<(String, String, usize)> = e
            .errors
            .iter()
            .map(|l| match &l.error {
                SceneError::Invalid { field, value, .. } => {
                    (field.clone(), value.clone(), l.at.unwrap().line)
                }
                other => panic!("{other}"),
            })
            .collect();
        assert_eq!(
            got,
            [
                ("limits.max_steps".into(), "10000000000000000000".into(), 3),
                ("grid.n[1]".into(), "0x8000000000000000".into(), 5),
                ("grid.deep.a.b".into(), "-9223372036854775809".into(), 6),
            ]
        );
        assert!(e.to_string().contains("9223372036854775807"), "{e}");
        // The edges of the range are TOML integers.
        let edge = "kind = \"k\"\na = 9223372036854775807\nb = -9223372036854775808\n";
        assert!(Document::parse(edge).is_ok());
    }

    #[test]
    fn locations_are_one_based() {
        assert_eq!(location("ab\ncd", 4), Location { line: 2, column: 2 });
        assert_eq!(location("", 0), Location { line: 1, column: 1 });
    }
}
