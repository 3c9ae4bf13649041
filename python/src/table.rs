//! The tables of a run as Python values: captured in memory
//! ([`tables_dict`]), or read back from the CSV files a run wrote. `pegdyn` prints every `f64` in the
//! shortest form that parses back to the same bits, so the arrays hold
//! exactly the numbers the run computed.

use numpy::IntoPyArray;
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use pegdyn::output::memory;

/// tables_dict: `{file stem: {column: float64 array | list[str]}}`, the
/// captured tables in order (the same values [`read_csv`] reads from the
/// files of the same run).
pub fn tables_dict<'py>(
    py: Python<'py>,
    tables: Vec<memory::Table>,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for t in tables {
        let stem = t.stem();
        let cols = PyDict::new(py);
        for (name, col) in t.header.iter().zip(t.columns) {
            match col {
                memory::Column::Numbers(v) => cols.set_item(name, v.into_pyarray(py))?,
                memory::Column::Text(v) => cols.set_item(name, v)?,
            }
        }
        out.set_item(stem, cols)?;
    }
    Ok(out)
}

/// One column: numbers, or text when any cell is not a number.
enum Column {
    Numbers(Vec<f64>),
    Text(Vec<String>),
}

/// Parses CSV text written by `pegdyn` (no quoting: cells never contain
/// commas) into named columns, in header order.
fn parse(text: &str) -> Result<Vec<(String, Vec<String>)>, String> {
    let mut lines = text.lines();
    let header = lines.next().ok_or("empty file")?;
    let mut cols: Vec<(String, Vec<String>)> = header
        .split(',')
        .map(|h| (h.to_string(), Vec::new()))
        .collect();
    for (i, line) in lines.enumerate() {
        if line.is_empty() {
            continue;
        }
        let cells: Vec<&str> = line.split(',').collect();
        if cells.len() != cols.len() {
            return Err(format!(
                "row {i} has {} cells, header has {}",
                cells.len(),
                cols.len()
            ));
        }
        for (c, cell) in cols.iter_mut().zip(cells) {
            c.1.push(cell.to_string());
        }
    }
    Ok(cols)
}

fn typed(cells: Vec<String>) -> Column {
    let nums: Result<Vec<f64>, _> = cells.iter().map(|c| c.parse::<f64>()).collect();
    match nums {
        Ok(v) => Column::Numbers(v),
        Err(_) => Column::Text(cells),
    }
}

/// read_csv(path) -> dict[str, numpy.ndarray | list[str]]
///
/// Reads a CSV file written by pegdyn: one float64 array per numeric
/// column (exact values: the file holds shortest round-trip decimals), a
/// list of str for a text column.
#[pyfunction]
pub fn read_csv<'py>(py: Python<'py>, path: &str) -> PyResult<Bound<'py, PyDict>> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| PyOSError::new_err(format!("cannot read {path}: {e}")))?;
    let cols = parse(&text).map_err(|e| PyValueError::new_err(format!("{path}: {e}")))?;
    let out = PyDict::new(py);
    for (name, cells) in cols {
        match typed(cells) {
            Column::Numbers(v) => out.set_item(name, v.into_pyarray(py))?,
            Column::Text(v) => out.set_item(name, v)?,
        }
    }
    Ok(out)
}
