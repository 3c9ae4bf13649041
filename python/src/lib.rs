//! The compiled core of the Python package `pegdyn` (module `pegdyn._pegdyn`).
//!
//! The Python layer (`python/pegdyn/__init__.py`) wraps these functions in
//! classes (`Scene`, `Result`, `SweepResult`, `Function`). Everything here
//! takes and returns plain values: scene text, dicts, lists and numpy arrays.
//!
//! - [`scene`]: validate and run a scene given as TOML text.
//! - [`functions`]: the generated functions evaluated on arrays of points.
//! - [`sweep`]: many runs of one scene with some fields replaced.

use pyo3::prelude::*;

mod errors;
mod functions;
mod scene;
mod sweep;
mod table;
mod value;

/// The module object `pegdyn._pegdyn`.
#[pymodule]
fn _pegdyn(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("SceneError", m.py().get_type::<errors::SceneError>())?;
    m.add("RunError", m.py().get_type::<errors::RunError>())?;
    m.add_function(wrap_pyfunction!(scene::check, m)?)?;
    m.add_function(wrap_pyfunction!(scene::run, m)?)?;
    m.add_function(wrap_pyfunction!(scene::to_toml, m)?)?;
    m.add_function(wrap_pyfunction!(scene::kinds, m)?)?;
    m.add_function(wrap_pyfunction!(table::read_csv, m)?)?;
    m.add_function(wrap_pyfunction!(functions::functions, m)?)?;
    m.add_function(wrap_pyfunction!(functions::evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(functions::rust_loop_ns, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::run_points, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::check_sweep, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::set_fields, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
