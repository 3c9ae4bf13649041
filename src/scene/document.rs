//! A parsed scene file before it is handed to its kind: the TOML tree with
//! source spans, the `kind` tag, and translation of TOML/serde errors into
//! [`SceneError`]s that name the field by its dotted path.

use serde::Deserialize;
use serde::de::DeserializeOwned;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use crate::error::{Located, Location, SceneError, SceneErrors};
use crate::scene::translate::translate;

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
            .map_err(|e| self.translated(e))
    }

    /// Deserializes the kind-specific part of the document (everything but
    /// [`COMMON_KEYS`]) into `T`. Use `#[serde(deny_unknown_fields)]` on `T`
    /// and its tables so that typos are reported.
    pub fn body<T: DeserializeOwned>(&self) -> Result<T, SceneErrors> {
        let mut root = self.root.clone();
        for key in COMMON_KEYS {
            root.get_mut().remove(key);
        }
        T::deserialize(toml::de::Deserializer::from(root)).map_err(|e| self.translated(e))
    }

    /// A deserialization error as located [`SceneErrors`], the value found
    /// described by its TOML type and text ([`translate`]).
    fn translated(&self, e: toml::de::Error) -> SceneErrors {
        let at = e.span().map(|s| location(self.text, s.start));
        let error = translate(e, |path| self.found_at(path));
        self.locate_all(SceneErrors {
            errors: vec![Located { error, at }],
        })
    }

    /// The value at dotted `path` as an error message shows it: its TOML
    /// type and the text written, e.g. ``a datetime `1979-05-27` ``.
    #[doc(hidden)]
    pub fn found_at(&self, path: &str) -> Option<String> {
        let v = self.value_at(path)?;
        let span = v.span();
        let written = self.text.get(span.start..span.end)?.trim();
        Some(format!("{} `{written}`", type_name(v.get_ref())))
    }

    /// The value at dotted `path`, where a key may end in `[k]` (the
    /// `k`-th element of an array, e.g. `grid.lateral_errors[2]`).
    fn value_at(&self, path: &str) -> Option<&Spanned<DeValue<'a>>> {
        let mut table = self.root.get_ref();
        let mut keys = path.split('.').peekable();
        while let Some(key) = keys.next() {
            let (name, index) = split_index(key);
            let mut v = table.get(name)?;
            if let Some(k) = index {
                match v.get_ref() {
                    DeValue::Array(a) => v = a.get(k)?,
                    _ => return None,
                }
            }
            if keys.peek().is_none() {
                return Some(v);
            }
            match v.get_ref() {
                DeValue::Table(t) => table = t,
                _ => return None,
            }
        }
        None
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

    /// Byte offset of the value at dotted `path` (a key may end in `[k]`,
    /// an array element), or of its deepest existing parent table's key
    /// when the field itself is absent.
    fn span_of(&self, path: &str) -> Option<usize> {
        let mut table = self.root.get_ref();
        let mut found = None;
        for key in path.split('.') {
            let (name, index) = split_index(key);
            let Some((k, v)) = table.get_key_value(name) else {
                return found;
            };
            found = Some(k.span().start);
            let v = match (index, v.get_ref()) {
                (Some(i), DeValue::Array(a)) => match a.get(i) {
                    Some(element) => element,
                    None => return Some(v.span().start),
                },
                _ => v,
            };
            match v.get_ref() {
                DeValue::Table(t) => table = t,
                _ => return Some(v.span().start),
            }
        }
        found
    }
}

/// A key of a dotted path and its array index: `lateral_errors[2]` is
/// `("lateral_errors", Some(2))`.
fn split_index(key: &str) -> (&str, Option<usize>) {
    key.strip_suffix(']')
        .and_then(|k| k.split_once('['))
        .and_then(|(name, i)| Some((name, Some(i.parse().ok()?))))
        .unwrap_or((key, None))
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
