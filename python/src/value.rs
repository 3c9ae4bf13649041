//! Python values to TOML values: a scene given as a dict, and the values a
//! sweep writes into a scene's fields.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// Converts `obj` (bool, int, float, str, list/tuple, dict with string keys,
/// or a numpy scalar) to a TOML value; `path` names it in errors.
pub fn to_toml(obj: &Bound<'_, PyAny>, path: &str) -> PyResult<toml::Value> {
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
        let mut out = Vec::new();
        for (i, item) in obj.try_iter()?.enumerate() {
            out.push(to_toml(&item?, &format!("{path}[{i}]"))?);
        }
        return Ok(toml::Value::Array(out));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        return Ok(toml::Value::Table(table(d, path)?));
    }
    // numpy scalars and 0-d arrays: their `item()` is a Python scalar;
    // numpy arrays: `tolist()`.
    for method in ["tolist", "item"] {
        if obj.hasattr(method)? {
            let plain = obj.call_method0(method)?;
            if !plain.is(obj) {
                return to_toml(&plain, path);
            }
        }
    }
    Err(PyTypeError::new_err(format!(
        "`{path}`: cannot put a value of type {} in a scene (bool, int, float, str, list or dict)",
        obj.get_type().name()?
    )))
}

/// A dict with string keys as a TOML table; `path` is the dotted prefix.
pub fn table(d: &Bound<'_, PyDict>, path: &str) -> PyResult<toml::Table> {
    let mut t = toml::Table::new();
    for (k, v) in d.iter() {
        let key: String = k
            .extract()
            .map_err(|_| PyTypeError::new_err(format!("`{path}`: scene keys must be strings")))?;
        let sub = if path.is_empty() {
            key.clone()
        } else {
            format!("{path}.{key}")
        };
        t.insert(key, to_toml(&v, &sub)?);
    }
    Ok(t)
}
