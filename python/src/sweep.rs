//! Many runs of one scene with some fields replaced: one row per point,
//! run in parallel with rayon. The Python `pegdyn.sweep` calls this for
//! the whole sweep (local) or once per batch on each Dask worker.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use pegdyn::integrate::Interrupt;
use pegdyn::output::memory::{Column, Keep, Table};
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
    /// The derivatives its `[sensitivities]` table asked for (empty
    /// without one).
    derivatives: Vec<Derivative>,
}

/// One row of a run's `<scene>.sensitivities` table: the derivative of
/// `metric` with respect to the scene field `parameter`, its elasticity,
/// and the flag that replaces them where the metric is not differentiable
/// (NaN then, as for a metric without a value).
struct Derivative {
    metric: String,
    parameter: String,
    derivative: f64,
    elasticity: f64,
    flag: String,
}

/// The cells of column `name` of `t` as text (numbers as the file prints
/// them, an empty cell empty).
fn text_column(t: &Table, name: &str) -> Vec<String> {
    match t.column(name) {
        Some(Column::Numbers(v)) => v.iter().map(f64::to_string).collect(),
        Some(Column::Text(v)) => v.clone(),
        None => Vec::new(),
    }
}

/// The cells of column `name` of `t` as numbers, NaN for an empty cell.
fn number_column(t: &Table, name: &str) -> Vec<f64> {
    match t.column(name) {
        Some(Column::Numbers(v)) => v.clone(),
        Some(Column::Text(v)) => v.iter().map(|c| c.parse().unwrap_or(f64::NAN)).collect(),
        None => Vec::new(),
    }
}

/// The derivatives in a run's sensitivities table (`metric, parameter,
/// value, derivative, elasticity, flag`, docs/sensitivities.md).
fn derivatives(t: &Table) -> Vec<Derivative> {
    let metric = text_column(t, "metric");
    let parameter = text_column(t, "parameter");
    let derivative = number_column(t, "derivative");
    let elasticity = number_column(t, "elasticity");
    let flag = text_column(t, "flag");
    (0..metric.len())
        .map(|i| Derivative {
            metric: metric[i].clone(),
            parameter: parameter.get(i).cloned().unwrap_or_default(),
            derivative: derivative.get(i).copied().unwrap_or(f64::NAN),
            elasticity: elasticity.get(i).copied().unwrap_or(f64::NAN),
            flag: flag.get(i).cloned().unwrap_or_default(),
        })
        .collect()
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
                derivatives: Vec::new(),
            };
        }
    }
    let text = match toml::to_string(&doc) {
        Ok(t) => t,
        Err(e) => {
            return Row {
                index,
                result: Err(("invalid".into(), e.to_string())),
                derivatives: Vec::new(),
            };
        }
    };
    // Only the summary is kept: the run writes no file and keeps no table.
    if stop.is_requested() {
        return Row {
            index,
            result: Err(("failed".into(), "interrupted".into())),
            derivatives: Vec::new(),
        };
    }
    // Only the summary is kept, and the derivatives where the scene asks
    // for them: the run writes no file, and its other tables are dropped.
    let wants_derivatives = doc.contains_key("sensitivities");
    let keep = if wants_derivatives {
        Keep::Tables
    } else {
        Keep::Nothing
    };
    let mut derivatives_found = Vec::new();
    let result = match run_text(&text, name, Output::Memory(keep), limits, stop) {
        Outcome::Done(s, tables, _) => {
            if let Some(t) = tables.iter().find(|t| t.stem().ends_with(".sensitivities")) {
                derivatives_found = derivatives(t);
            }
            Ok(s)
        }
        Outcome::Invalid(e) => Err(("invalid".into(), e.to_string())),
        Outcome::Failed(m) => Err(("failed".into(), m)),
    };
    Row {
        index,
        result,
        derivatives: derivatives_found,
    }
}

/// Bytes a sweep keeps per row: a dict of the inputs, the fixed fields and
/// the run's metrics (a few dozen entries of about 100 bytes each).
const ROW_BYTES: f64 = 4096.0;

/// Bytes of one row's entry (a key and a float in the row's dict).
const ENTRY_BYTES: f64 = 100.0;

/// Entries a row gains per metric and field named in `[sensitivities]`
/// (the derivative, the elasticity, and a flag where there is one), for at
/// most this many metrics per field.
const SENSITIVITY_ENTRIES: f64 = 3.0 * 8.0;

/// The bytes a row of `doc` keeps beyond [`ROW_BYTES`]: its derivatives,
/// when the scene names fields in a `[sensitivities]` table.
fn derivative_bytes(doc: &toml::Table) -> f64 {
    let fields = doc
        .get("sensitivities")
        .and_then(|t| t.get("parameters"))
        .and_then(toml::Value::as_array)
        .map_or(0, Vec::len);
    #[allow(clippy::cast_precision_loss)] // a count of scene fields
    let fields = fields as f64;
    fields * SENSITIVITY_ENTRIES * ENTRY_BYTES
}

/// The work of a sweep of `points` runs of `loaded`: `points` times the
/// runs of one point (its grid's, or one), bounded by `max_runs`, each
/// keeping a row of `row_bytes` beyond [`ROW_BYTES`].
fn sweep_work(loaded: &scene::LoadedScene, points: usize, row_bytes: f64) -> Vec<WorkItem> {
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
            ROW_BYTES + row_bytes,
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
    let row_bytes = toml::from_str::<toml::Table>(text).map_or(0.0, |d| derivative_bytes(&d));
    bounds
        .check(&sweep_work(&loaded, points, row_bytes))
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
/// `"name [unit]"` (or `name` when dimensionless; a note, a result in
/// words, as its text; `"name (summary)"` where the name is one of those
/// fields, e.g. the 3-D kinds' `outcome` code). A scene with a
/// `[sensitivities]` table adds, per metric and field of its CSV,
/// `"d(metric)/d(field)"` and `"elasticity(metric, field)"` (NaN where
/// flagged) and, where flagged, `"flag(metric, field)"` with the reason.
/// Input values are added by the caller.
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

/// The fields every row has, besides the inputs and the metrics.
const FIXED: [&str; 7] = [
    "index",
    "outcome",
    "error",
    "stop",
    "t_end",
    "steps",
    "rhs_calls",
];

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
                let mut key = if m.unit.is_empty() {
                    m.name.clone()
                } else {
                    format!("{} [{}]", m.name, m.unit)
                };
                // A metric named like a row field (the 3-D kinds'
                // `outcome`, a code) must not overwrite it.
                if FIXED.contains(&key.as_str()) {
                    key.push_str(" (summary)");
                }
                // A note (a result in words, e.g. a ranking) is its text,
                // not a NaN.
                match &m.text {
                    Some(text) if m.value.is_nan() => d.set_item(key, text)?,
                    _ => d.set_item(key, m.value)?,
                }
            }
            for x in &r.derivatives {
                let of = format!("{}, {}", x.metric, x.parameter);
                d.set_item(format!("d({})/d({})", x.metric, x.parameter), x.derivative)?;
                d.set_item(format!("elasticity({of})"), x.elasticity)?;
                if !x.flag.is_empty() {
                    d.set_item(format!("flag({of})"), &x.flag)?;
                }
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
