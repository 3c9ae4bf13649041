//! The generated functions (`pegdyn::generated::registry::FUNCTIONS`)
//! evaluated on arrays of points: one row per point, a Rust loop over rows
//! with the GIL released.

use std::time::Instant;

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use pegdyn::generated::Function;
use pegdyn::generated::registry::FUNCTIONS;

fn find(module: &str, name: &str) -> PyResult<&'static Function> {
    FUNCTIONS
        .iter()
        .find(|f| f.module == module && f.name == name)
        .ok_or_else(|| PyKeyError::new_err(format!("no generated function {module}::{name}")))
}

/// functions() -> list[dict]: every generated function with `module`,
/// `name`, `inputs` (list of `(argument, [symbol, ...])`) and `outputs`
/// (list of `(name, entries)`, matrices row-major).
#[pyfunction]
pub fn functions(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    FUNCTIONS
        .iter()
        .map(|f| {
            let d = PyDict::new(py);
            d.set_item("module", f.module)?;
            d.set_item("name", f.name)?;
            let inputs: Vec<(&str, Vec<&str>)> =
                f.inputs.iter().map(|(a, s)| (*a, s.to_vec())).collect();
            d.set_item("inputs", inputs)?;
            d.set_item("outputs", f.outputs.to_vec())?;
            Ok(d)
        })
        .collect()
}

/// Evaluates `f` on `n` points; input `j` is `data[j]` with `rows[j]` rows
/// (`n` or 1, broadcast) of `f.inputs[j].1.len()` columns, row-major.
/// Returns `n` rows of every output entry flattened.
fn eval_rows(f: &Function, data: &[&[f64]], rows: &[usize], n: usize) -> Vec<f64> {
    let widths: Vec<usize> = f.inputs.iter().map(|(_, s)| s.len()).collect();
    let total: usize = f.outputs.iter().map(|(_, k)| k).sum();
    let mut out = Vec::with_capacity(n * total);
    let mut args: Vec<&[f64]> = Vec::with_capacity(data.len());
    for i in 0..n {
        args.clear();
        for ((d, &w), &r) in data.iter().zip(&widths).zip(rows) {
            let row = if r == 1 { 0 } else { i };
            args.push(&d[row * w..(row + 1) * w]);
        }
        out.extend_from_slice(&(f.eval_f64)(&args));
    }
    out
}

/// evaluate(module, name, inputs) -> ndarray of shape (N, total outputs)
///
/// `inputs`: one C-contiguous float64 array per argument, shape
/// `(N, len)` or `(1, len)` (broadcast to every point). Raises ValueError
/// for a wrong number of arguments, a wrong column count or mismatched
/// row counts; numpy raises TypeError for a wrong dtype.
#[pyfunction]
pub fn evaluate<'py>(
    py: Python<'py>,
    module: &str,
    name: &str,
    inputs: Vec<PyReadonlyArray2<'py, f64>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let f = find(module, name)?;
    if inputs.len() != f.inputs.len() {
        return Err(PyValueError::new_err(format!(
            "{}: takes {} inputs ({}), got {}",
            f.path(),
            f.inputs.len(),
            f.inputs
                .iter()
                .map(|(a, _)| *a)
                .collect::<Vec<_>>()
                .join(", "),
            inputs.len()
        )));
    }
    let mut n = 1;
    let mut rows = Vec::new();
    let mut data = Vec::new();
    for (a, (arg, syms)) in inputs.iter().zip(f.inputs) {
        let shape = a.shape();
        if shape[1] != syms.len() {
            return Err(PyValueError::new_err(format!(
                "{}: input `{arg}` must have {} columns ({}), got shape ({}, {})",
                f.path(),
                syms.len(),
                syms.join(", "),
                shape[0],
                shape[1]
            )));
        }
        if shape[0] != 1 {
            if n != 1 && shape[0] != n {
                return Err(PyValueError::new_err(format!(
                    "{}: input `{arg}` has {} rows, another input has {n} (rows must agree or be 1)",
                    f.path(),
                    shape[0]
                )));
            }
            n = shape[0];
        }
        rows.push(shape[0]);
        data.push(
            a.as_slice()
                .map_err(|e| PyValueError::new_err(format!("{}: input `{arg}`: {e}", f.path())))?,
        );
    }
    if rows.contains(&0) {
        n = 0;
    }
    let total: usize = f.outputs.iter().map(|(_, k)| k).sum();
    let out = py.detach(|| eval_rows(f, &data, &rows, n));
    let arr = Array2::from_shape_vec((n, total), out)
        .map_err(|e| PyValueError::new_err(format!("{}: {e}", f.path())))?;
    Ok(arr.into_pyarray(py))
}

/// rust_loop_ns(module, name, n, repeats=3) -> float
///
/// Benchmark helper: the best over `repeats` of the time per point, ns, of
/// the loop `evaluate` runs, on `n` points made in Rust (no Python in the
/// loop). Inputs are `0.1 + 0.01 k` for component `k`, with the point
/// index added to the first component.
#[pyfunction]
#[pyo3(signature = (module, name, n, repeats=3))]
pub fn rust_loop_ns(
    py: Python<'_>,
    module: &str,
    name: &str,
    n: usize,
    repeats: usize,
) -> PyResult<f64> {
    let f = find(module, name)?;
    let owned: Vec<Vec<f64>> = f
        .inputs
        .iter()
        .map(|(_, syms)| {
            let w = syms.len();
            (0..n * w)
                .map(|i| {
                    0.1 + 0.01 * (i % w) as f64
                        + if i % w == 0 {
                            1e-9 * (i / w) as f64
                        } else {
                            0.0
                        }
                })
                .collect()
        })
        .collect();
    let rows = vec![n; owned.len()];
    let best = py.detach(|| {
        let data: Vec<&[f64]> = owned.iter().map(Vec::as_slice).collect();
        let mut best = f64::INFINITY;
        for _ in 0..repeats.max(1) {
            let t = Instant::now();
            let out = eval_rows(f, &data, &rows, n);
            let dt = t.elapsed().as_secs_f64();
            std::hint::black_box(out);
            best = best.min(dt);
        }
        best
    });
    Ok(best * 1e9 / n.max(1) as f64)
}
