//! Many runs of one scene with some fields replaced: one row per point,
//! run in parallel with rayon. The Python `pegdyn.sweep` calls this for
//! the whole sweep (local) or once per batch on each Dask worker.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use pegdyn::integrate::Interrupt;
use pegdyn::output::memory::Keep;
use pegdyn::scene::limits::{LimitOverrides, WorkItem};
use pegdyn::scene::{self, RunSummary};

use crate::errors::scene_error;
use crate::scene::{Outcome, Output, interruptible, overrides, run_text};
use crate::value;

/// One finished point.
struct Row {
    index: usize,
    /// `Err(message)`: the point's scene did not validate or its run failed.
    result: Result<RunSummary, (String, String)>,
}

/// Sets dotted `key` (`table.field`, tables created as needed) in `doc`.
fn set(doc: &mut toml::Table, key: &str, v: toml::Value) -> Result<(), String> {
    let mut parts: Vec<&str> = key.split('.').collect();
    let last = parts.pop().filter(|s| !s.is_empty()).ok_or("empty key")?;
    let mut t = doc;
    for p in parts {
        let entry = t
            .entry(p.to_string())
            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
        t = entry
            .as_table_mut()
            .ok_or_else(|| format!("`{key}`: `{p}` is not a table"))?;
    }
    t.insert(last.to_string(), v);
    Ok(())
}

/// The fixed context of every point of a sweep.
struct Sweep<'a> {
    base: &'a toml::Table,
    name: &'a str,
    keys: &'a [String],
    limits: &'a LimitOverrides,
    stop: &'a Interrupt,
}

fn run_point(sw: &Sweep<'_>, point: &[toml::Value], index: usize) -> Row {
    let Sweep {
        base,
        name,
        keys,
        limits,
        stop,
    } = *sw;
    let mut doc = base.clone();
    for (k, v) in keys.iter().zip(point) {
        if let Err(e) = set(&mut doc, k, v.clone()) {
            return Row {
                index,
                result: Err(("invalid".into(), e)),
            };
        }
    }
    let text = match toml::to_string(&doc) {
        Ok(t) => t,
        Err(e) => {
            return Row {
                index,
                result: Err(("invalid".into(), e.to_string())),
            };
        }
    };
    // Only the summary is kept: the run writes no file and keeps no table.
    if stop.is_requested() {
        return Row {
            index,
            result: Err(("failed".into(), "interrupted".into())),
        };
    }
    let result = match run_text(&text, name, Output::Memory(Keep::Nothing), limits, stop) {
        Outcome::Done(s, ..) => Ok(s),
        Outcome::Invalid(e) => Err(("invalid".into(), e.to_string())),
        Outcome::Failed(m) => Err(("failed".into(), m)),
    };
    Row { index, result }
}

/// Bytes a sweep keeps per row: a dict of the inputs, the fixed fields and
/// the run's metrics (a few dozen entries of about 100 bytes each).
const ROW_BYTES: f64 = 4096.0;

/// The work of a sweep of `points` runs of `loaded`: `points` times the
/// runs of one point (its grid's, or one), bounded by `max_runs`, each
/// keeping a row.
fn sweep_work(loaded: &scene::LoadedScene, points: usize) -> Vec<WorkItem> {
    let runs_each: f64 = loaded
        .work
        .iter()
        .filter(|w| w.limit == "max_runs")
        .map(|w| w.count)
        .sum();
    vec![
        WorkItem::new(
            "sweep",
            "max_runs",
            points as f64 * runs_each.max(1.0),
            ROW_BYTES,
        )
        .with_value(points as f64),
    ]
}

/// check_sweep(text, name, points, limits=None)
///
/// Refuses, before any run starts, a sweep of `points` runs of scene
/// `text` whose work (`points` times the runs of one point, each keeping
/// a row) exceeds the scene's `[limits]` with `limits` applied: raises
/// SceneError naming `sweep` and the limit (`max_runs`, `max_memory_mb`).
#[pyfunction]
#[pyo3(signature = (text, name, points, limits=None))]
pub fn check_sweep(
    py: Python<'_>,
    text: &str,
    name: &str,
    points: usize,
    limits: Option<Vec<String>>,
) -> PyResult<()> {
    let limits = overrides(limits)?;
    let loaded =
        scene::parse_named_with(text, name, &limits).map_err(|e| scene_error(py, &e, None))?;
    let bounds = limits.apply(
        scene::Document::parse(text)
            .and_then(|d| d.limits())
            .map_err(|e| scene_error(py, &e, None))?,
    );
    bounds
        .check(&sweep_work(&loaded, points))
        .map_err(|e| scene_error(py, &e, None))
}

/// run_points(text, name, keys, points, first_index=0, threads=None, limits=None) -> list[dict]
///
/// Runs scene `text` once per point, field `keys[j]` set to `point[j]`,
/// in parallel (rayon; `threads` caps the pool, default all cores), each
/// point's scene validated under `limits` (as `check`), with the GIL
/// released and Ctrl-C honoured (no further run starts, runs in progress
/// stop at their next step). Row `k` (in point order) has
/// `index` = `first_index + k`, the `outcome` (`"ok"`, `"stopped"` for an
/// unplanned integration stop, `"invalid"`, `"failed"`), `error` (message
/// or None), `stop`, `t_end`, `steps`, `rhs_calls` (None without time
/// integration) and every metric of the run summary, named
/// `"name [unit]"` (or `name` when dimensionless). Input values are added
/// by the caller.
#[pyfunction]
#[pyo3(signature = (text, name, keys, points, first_index=0, threads=None, limits=None))]
#[allow(clippy::too_many_arguments)]
pub fn run_points<'py>(
    py: Python<'py>,
    text: &str,
    name: String,
    keys: Vec<String>,
    points: Vec<Vec<Bound<'py, PyAny>>>,
    first_index: usize,
    threads: Option<usize>,
    limits: Option<Vec<String>>,
) -> PyResult<Vec<Bound<'py, PyDict>>> {
    let limits = overrides(limits)?;
    let base: toml::Table = toml::from_str(text)
        .map_err(|e| PyValueError::new_err(format!("scene text is not TOML: {e}")))?;
    let mut pts = Vec::with_capacity(points.len());
    for p in &points {
        if p.len() != keys.len() {
            return Err(PyValueError::new_err(format!(
                "a point has {} values for {} keys",
                p.len(),
                keys.len()
            )));
        }
        let vals: PyResult<Vec<toml::Value>> = p
            .iter()
            .zip(&keys)
            .map(|(v, k)| value::to_toml(v, k))
            .collect();
        pts.push(vals?);
    }
    let stop = Interrupt::new();
    let run_stop = stop.clone();
    let rows = interruptible(py, &stop, move || {
        let sw = Sweep {
            base: &base,
            name: &name,
            keys: &keys,
            limits: &limits,
            stop: &run_stop,
        };
        let work = || {
            pts.par_iter()
                .enumerate()
                .map(|(k, p)| run_point(&sw, p, first_index + k))
                .collect::<Vec<Row>>()
        };
        match threads {
            Some(t) => rayon::ThreadPoolBuilder::new()
                .num_threads(t.max(1))
                .build()
                .map(|pool| pool.install(work))
                .map_err(|e| e.to_string()),
            None => Ok(work()),
        }
    })?
    .map_err(|e| PyValueError::new_err(format!("cannot start the thread pool: {e}")))?;
    rows.iter().map(|r| row_dict(py, r)).collect()
}

fn row_dict<'py>(py: Python<'py>, r: &Row) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("index", r.index)?;
    match &r.result {
        Ok(s) => {
            let outcome = if s.success() { "ok" } else { "stopped" };
            d.set_item("outcome", outcome)?;
            d.set_item("error", py.None())?;
            match &s.integration {
                Some(i) => {
                    d.set_item("stop", &i.stop)?;
                    d.set_item("t_end", i.t_end)?;
                    d.set_item("steps", i.steps)?;
                    d.set_item("rhs_calls", i.rhs_calls)?;
                }
                None => {
                    for k in ["stop", "t_end", "steps", "rhs_calls"] {
                        d.set_item(k, py.None())?;
                    }
                }
            }
            for m in &s.metrics {
                let key = if m.unit.is_empty() {
                    m.name.clone()
                } else {
                    format!("{} [{}]", m.name, m.unit)
                };
                d.set_item(key, m.value)?;
            }
        }
        Err((outcome, msg)) => {
            d.set_item("outcome", outcome)?;
            d.set_item("error", msg)?;
            for k in ["stop", "t_end", "steps", "rhs_calls"] {
                d.set_item(k, py.None())?;
            }
        }
    }
    Ok(d)
}

/// set_fields(text, keys, values) -> str
///
/// Scene `text` with dotted field `keys[j]` set to `values[j]` (tables
/// created as needed), as TOML text. Not validated here.
#[pyfunction]
pub fn set_fields(
    text: &str,
    keys: Vec<String>,
    values: Vec<Bound<'_, PyAny>>,
) -> PyResult<String> {
    let mut doc: toml::Table = toml::from_str(text)
        .map_err(|e| PyValueError::new_err(format!("scene text is not TOML: {e}")))?;
    if keys.len() != values.len() {
        return Err(PyValueError::new_err("one value per key"));
    }
    for (k, v) in keys.iter().zip(&values) {
        set(&mut doc, k, value::to_toml(v, k)?).map_err(PyValueError::new_err)?;
    }
    toml::to_string(&doc).map_err(|e| PyValueError::new_err(format!("cannot write TOML: {e}")))
}
