//! The exceptions: `SceneError` (a scene that does not validate, with the
//! first problem's `field`, `value` and `reason` and every problem in
//! `errors`) and `RunError` (a valid scene whose run failed).

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use pegdyn::error::{SceneError as CoreError, SceneErrors};

create_exception!(
    pegdyn,
    SceneError,
    PyValueError,
    "A scene that does not parse or validate.\n\n\
     The message is the one `pegdyn check` prints. Attributes of the first \
     problem: `field` (dotted path such as `pendulum.length`, or None), \
     `value` (the offending value as written, or None), `reason`; `errors` \
     lists every problem as `(field, value, reason)` tuples."
);
create_exception!(
    pegdyn,
    RunError,
    PyRuntimeError,
    "A valid scene whose run failed (an output could not be written, the \
     integrator rejected its input, the model has no answer at a state)."
);

/// `(field, value, reason)` of one scene error.
fn parts(e: &CoreError) -> (Option<String>, Option<String>, String) {
    match e {
        CoreError::Invalid {
            field,
            value,
            reason,
        } => (Some(field.clone()), Some(value.clone()), reason.clone()),
        CoreError::WrongType {
            field,
            found,
            expected,
        } => (
            Some(field.clone()),
            Some(found.clone()),
            format!("wrong type, expected {expected}"),
        ),
        CoreError::UnknownKind { value, known } => (
            Some("kind".into()),
            Some(format!("{value:?}")),
            format!("unknown scene kind; known kinds: {known}"),
        ),
        CoreError::Missing { field } => (Some(field.clone()), None, "missing field".into()),
        CoreError::Unknown { field, expected } => (
            Some(field.clone()),
            None,
            format!("unknown field; {expected}"),
        ),
        other => (other.field().map(str::to_owned), None, other.to_string()),
    }
}

/// The Python `SceneError` for `errors`; the message is prefixed by
/// `prefix` on every line (the file name, as `pegdyn check` does), when given.
pub fn scene_error(py: Python<'_>, errors: &SceneErrors, prefix: Option<&str>) -> PyErr {
    let text = errors.to_string();
    let message = match prefix {
        Some(p) => text
            .lines()
            .map(|l| format!("{p}: error: {l}"))
            .collect::<Vec<_>>()
            .join("\n"),
        None => text,
    };
    let err = SceneError::new_err(message);
    let all: Vec<_> = errors.errors.iter().map(|l| parts(&l.error)).collect();
    let value = err.value(py);
    let (field, val, reason) = all.first().cloned().unwrap_or((None, None, String::new()));
    // Attribute setting on a fresh exception object cannot fail in practice;
    // if it did, the message still carries everything.
    let _ = value.setattr("field", field);
    let _ = value.setattr("value", val);
    let _ = value.setattr("reason", reason);
    let list: Vec<Bound<'_, PyTuple>> = all
        .into_iter()
        .filter_map(|t| {
            PyTuple::new(
                py,
                [
                    t.0.into_pyobject(py).ok()?.into_any(),
                    t.1.into_pyobject(py).ok()?.into_any(),
                    t.2.into_pyobject(py).ok()?.into_any(),
                ],
            )
            .ok()
        })
        .collect();
    let _ = value.setattr("errors", list);
    err
}
