//! Python values to TOML values: a scene given as a dict, and the values a
//! sweep writes into a scene's fields.
//!
//! The walk is guarded: a dict or list that contains itself, or one nested
//! deeper than [`MAX_DEPTH`], raises ValueError naming the path and the
//! depth (Rust's stack is never the limit, so no input crashes the
//! interpreter).

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// How deep a value may nest (tables, lists, numpy's `tolist()`): a scene
/// nests tables three deep and lists two; 64 leaves room and keeps the
/// walk's stack small.
pub const MAX_DEPTH: usize = 64;

/// The containers on the path from the root to the value being converted
/// (by identity), to find a value that contains itself.
#[derive(Default)]
struct Walk {
    open: Vec<usize>,
}

/// Converts `obj` (bool, int, float, str, list/tuple, dict with string keys,
/// or a numpy scalar or array) to a TOML value; `path` names it in errors.
///
/// # Errors
/// TypeError for a value TOML cannot hold; ValueError for a value that
/// contains itself or nests deeper than [`MAX_DEPTH`].
pub fn to_toml(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<toml::Value> {
    Walk::default().value(obj, path)
}

/// A dict with string keys as a TOML table; `path` is the dotted prefix.
///
/// # Errors
/// As [`to_toml`].
pub fn table(d: &Bound<'_, PyDict>, path: &str) -> PyResult<toml::Table> {
    Walk::default().table(d, path)
}

impl Walk {
    /// Enters container `obj` at `path`, refusing a cycle or a depth past
    /// [`MAX_DEPTH`].
    fn enter(&mut self, obj: &Bound<'_, PyAny>, path: &str) -> PyResult<()> {
        let id = obj.as_ptr() as usize;
        let shown = if path.is_empty() { "the scene" } else { path };
        if self.open.contains(&id) {
            return Err(PyValueError::new_err(format!(
                "`{shown}` contains itself (a dict or list that holds itself, {} levels down): \
                 a scene is a tree of tables and values",
                self.open.len()
            )));
        }
        if self.open.len() >= MAX_DEPTH {
            return Err(PyValueError::new_err(format!(
                "`{}` is nested {} levels deep: a scene value nests at most {MAX_DEPTH} levels \
                 of dicts and lists",
                short(shown),
                self.open.len() + 1
            )));
        }
        self.open.push(id);
        Ok(())
    }

    fn value(&mut self, obj: &Bound<'_, PyAny>, path: &str) -> PyResult<toml::Value> {
        if obj.is_instance_of::<PyBool>() {
            return Ok(toml::Value::Boolean(obj.extract()?));
        }
        if obj.is_instance_of::<PyInt>() {
            let v: i64 = obj.extract().map_err(|_| {
                PyTypeError::new_err(format!("`{path}`: integer does not fit in 64 bits"))
            })?;
            return Ok(toml::Value::Integer(v));
        }
        if obj.is_instance_of::<PyFloat>() {
            return Ok(toml::Value::Float(obj.extract()?));
        }
        if obj.is_instance_of::<PyString>() {
            return Ok(toml::Value::String(obj.extract()?));
        }
        if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
            self.enter(obj, path)?;
            let mut out = Vec::new();
            for (i, item) in obj.try_iter()?.enumerate() {
                out.push(self.value(&item?, &format!("{path}[{i}]"))?);
            }
            self.open.pop();
            return Ok(toml::Value::Array(out));
        }
        if let Ok(d) = obj.cast::<PyDict>() {
            return Ok(toml::Value::Table(self.table(d, path)?));
        }
        // numpy scalars and 0-d arrays: their `item()` is a Python scalar;
        // numpy arrays: `tolist()`.
        for method in ["tolist", "item"] {
            if obj.hasattr(method)? {
                let plain = obj.call_method0(method)?;
                if !plain.is(obj) {
                    // A `tolist()` that hands back another object of its kind
                    // counts as a level, so that it cannot recurse without end.
                    self.enter(obj, path)?;
                    let v = self.value(&plain, path);
                    self.open.pop();
                    return v;
                }
            }
        }
        Err(PyTypeError::new_err(format!(
            "`{path}`: cannot put a value of type {} in a scene (bool, int, float, str, list or dict)",
            obj.get_type().name()?
        )))
    }

    fn table(&mut self, d: &Bound<'_, PyDict>, path: &str) -> PyResult<toml::Table> {
        self.enter(d.as_any(), path)?;
        let mut t = toml::Table::new();
        for (k, v) in d.iter() {
            let key: String = k.extract().map_err(|_| {
                PyTypeError::new_err(format!("`{path}`: scene keys must be strings"))
            })?;
            let sub = if path.is_empty() {
                key.clone()
            } else {
                format!("{path}.{key}")
            };
            t.insert(key, self.value(&v, &sub)?);
        }
        self.open.pop();
        Ok(t)
    }
}

/// `path` cut to its first 60 and last 20 characters when longer.
fn short(path: &str) -> String {
    let chars: Vec<char> = path.chars().collect();
    if chars.len() <= 90 {
        return path.to_string();
    }
    let head: String = chars[..60].iter().collect();
    let tail: String = chars[chars.len() - 20..].iter().collect();
    format!("{head}…{tail}")
}
