//! Validating and running one scene given as TOML text.
//!
//! The scene is re-parsed from its text wherever it runs (a parsed scene is
//! not `Send`; parsing costs microseconds), so the Python `Scene` object is
//! just its text and name, and pickles to Dask workers as such.

use std::path::PathBuf;
use std::sync::mpsc;
use std::time::Duration;

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

use pegdyn::integrate::Interrupt;
use pegdyn::output::memory::{Keep, KeptFile, Table};
use pegdyn::output::record::{Origin, RunRecord};
use pegdyn::output::sink::Sink;
use pegdyn::scene::limits::LimitOverrides;
use pegdyn::scene::{self, Progress, RunContext, RunSummary};

use crate::errors::{RunError, scene_error};
use crate::{table, value};

/// The `KEY=VALUE` limit arguments (as `pegdyn run --limit`), parsed;
/// ValueError naming the argument when one is unusable.
pub fn overrides(limits: Option<Vec<String>>) -> PyResult<LimitOverrides> {
    LimitOverrides::parse(&limits.unwrap_or_default())
        .map_err(|e| PyValueError::new_err(format!("limits: {e}")))
}

/// check(text, name, prefix=None, limits=None) -> (kind, description, describe)
///
/// Parses and validates scene `text` under its `[limits]` with `limits`
/// (`KEY=VALUE` strings, as `pegdyn check --limit`) applied; raises
/// SceneError with the messages of `pegdyn check` (each line prefixed by
/// `prefix: error: ` when given).
#[pyfunction]
#[pyo3(signature = (text, name, prefix=None, limits=None))]
pub fn check(
    py: Python<'_>,
    text: &str,
    name: &str,
    prefix: Option<&str>,
    limits: Option<Vec<String>>,
) -> PyResult<(String, Option<String>, String)> {
    let limits = overrides(limits)?;
    match scene::parse_named_with(text, name, &limits) {
        Ok(s) => Ok((s.kind.to_string(), s.description, s.scene.describe())),
        Err(e) => Err(scene_error(py, &e, prefix)),
    }
}

/// to_toml(d) -> str: a dict (nested dicts are tables) as TOML text.
#[pyfunction]
pub fn to_toml(d: &Bound<'_, PyDict>) -> PyResult<String> {
    let t = value::table(d, "")?;
    toml::to_string(&t).map_err(|e| PyRuntimeError::new_err(format!("cannot write TOML: {e}")))
}

/// kinds() -> list[(name, about)]: the registered scene kinds.
#[pyfunction]
pub fn kinds() -> Vec<(&'static str, &'static str)> {
    scene::KINDS.iter().map(|k| (k.name, k.about)).collect()
}

/// How often a waiting call takes the GIL back to look for Ctrl-C.
const POLL: Duration = Duration::from_millis(50);

/// Runs `work` on a new thread with the GIL released, taking the GIL back
/// every [`POLL`] to run Python's signal handlers: on KeyboardInterrupt the
/// call returns at once with the exception, and `stop` is requested so that
/// the abandoned work stops at its next integration step or run (its
/// result is dropped).
pub fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    stop: &Interrupt,
    work: impl FnOnce() -> T + Send + 'static,
) -> PyResult<T> {
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name("pegdyn-run".into())
        .spawn(move || {
            // The receiver may be gone after an interrupt: nothing to do then.
            let _ = tx.send(work());
        })
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start a thread: {e}")))?;
    let mut rx = rx;
    loop {
        // The receiver is `Send` but not `Sync`: move it through the closure.
        let (got, back) = py.detach(move || (rx.recv_timeout(POLL), rx));
        rx = back;
        match got {
            Ok(v) => return Ok(v),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                if let Err(e) = py.check_signals() {
                    stop.request();
                    return Err(e);
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err("pegdyn: the run thread panicked"));
            }
        }
    }
}

/// What a run thread hands back.
pub enum Outcome {
    Invalid(pegdyn::error::SceneErrors),
    Failed(String),
    /// The summary and, for a run in memory with [`Keep::Tables`], the
    /// tables and the other files (the replay page) it wrote.
    Done(RunSummary, Vec<Table>, Vec<KeptFile>),
}

/// Where a run's outputs go.
pub enum Output {
    /// Files in this directory (created), as `pegdyn run --out`.
    Dir(PathBuf),
    /// No file: tables kept in memory or dropped.
    Memory(Keep),
}

/// Parses `text` under `limits` and runs it silently, writing into
/// `out`; stops when `stop` is requested.
pub fn run_text(
    text: &str,
    name: &str,
    out: Output,
    limits: &LimitOverrides,
    stop: &Interrupt,
) -> Outcome {
    let loaded = match scene::parse_named_with(text, name, limits) {
        Ok(s) => s,
        Err(e) => return Outcome::Invalid(e),
    };
    let (sink, record) = match out {
        Output::Dir(dir) => {
            if let Err(e) = std::fs::create_dir_all(&dir) {
                return Outcome::Failed(format!(
                    "cannot create output directory {}: {e}",
                    dir.display()
                ));
            }
            // Recorded as `pegdyn run` records it: `running` before any
            // output is replaced, then how the run ended.
            let scene = PathBuf::from(format!("(scene text given to Python, named {name})"));
            let origin = Origin {
                scene: &scene,
                text: text.as_bytes(),
                command: std::env::args_os().collect(),
                out: &dir,
            };
            let record = match RunRecord::start(&dir, &loaded.name, &origin) {
                Ok((record, _)) => record,
                Err(e) => return Outcome::Failed(e.to_string()),
            };
            (Sink::directory(&dir, &loaded.name), Some(record))
        }
        // Nothing is written: the summary lists no path.
        Output::Memory(keep) => (Sink::memory(&loaded.name, keep), None),
    };
    let mut ctx = RunContext::new(sink, Progress::silent().with_interrupt(stop.clone()));
    let result = loaded.run(&mut ctx);
    if let Some(record) = record {
        let status = match &result {
            Ok(s) if s.success() => "ok".to_owned(),
            Ok(s) => format!(
                "partial: integration stopped early: {}",
                s.integration.as_ref().map_or("", |i| i.stop.as_str())
            ),
            Err(pegdyn::error::RunError::Interrupted) => "interrupted: KeyboardInterrupt".into(),
            Err(e) => format!("failed: {e}"),
        };
        // The outputs are complete either way; a manifest that cannot be
        // written leaves the earlier one, which said `running`.
        let _ = record.finish(status, &ctx.sink().written());
    }
    match result {
        Ok(s) => {
            let files = ctx.sink().take_files();
            Outcome::Done(s, ctx.into_sink().into_tables(), files)
        }
        Err(e) => Outcome::Failed(e.to_string()),
    }
}

/// The summary as a dict: `integration` (None or a dict), `metrics`
/// (list of `(name, value, unit)`), `outputs` (paths), `success`, `text`
/// (what `pegdyn run` prints).
pub fn summary_dict<'py>(py: Python<'py>, s: &RunSummary) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    match &s.integration {
        Some(i) => {
            let id = PyDict::new(py);
            id.set_item("method", i.method.name())?;
            id.set_item("t_end", i.t_end)?;
            id.set_item("stop", &i.stop)?;
            id.set_item("success", i.success)?;
            id.set_item("steps", i.steps)?;
            id.set_item("rejected", i.rejected)?;
            id.set_item("rhs_calls", i.rhs_calls)?;
            d.set_item("integration", id)?;
        }
        None => d.set_item("integration", py.None())?,
    }
    let events = PyList::empty(py);
    for e in s.integration.iter().flat_map(|i| &i.events) {
        let details = PyDict::new(py);
        details.set_item("terminal", e.terminal)?;
        for (k, v) in &e.details {
            details.set_item(k, v)?;
        }
        events.append((e.t, e.name.as_str(), details))?;
    }
    d.set_item("events", events)?;
    let metrics = PyList::empty(py);
    for m in &s.metrics {
        // A note (a text without a value) or a coded metric carries its text.
        metrics.append((m.name.as_str(), m.value, m.unit, m.text.as_deref()))?;
    }
    d.set_item("metrics", metrics)?;
    let outputs: Vec<String> = s
        .outputs
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    d.set_item("outputs", outputs)?;
    d.set_item("success", s.success())?;
    d.set_item("text", s.to_string())?;
    Ok(d)
}

/// run(text, name, out_dir=None, limits=None) -> dict
///
/// Runs the scene under `limits` (as [`check`]) with the GIL released
/// (Ctrl-C returns at once and stops the run at its next step) into
/// `out_dir`, or, without it, in memory (no file is written); returns the
/// summary dict of [`summary_dict`] plus `tables`: None with `out_dir`,
/// else `{file stem: {column: array | list[str]}}` in the order the run
/// finished them; and `files`: None with `out_dir`, else `{file name:
/// bytes}` of the other files (the replay page). Raises SceneError for an
/// invalid scene and RunError when the run fails.
#[pyfunction]
#[pyo3(signature = (text, name, out_dir=None, limits=None))]
pub fn run<'py>(
    py: Python<'py>,
    text: String,
    name: String,
    out_dir: Option<PathBuf>,
    limits: Option<Vec<String>>,
) -> PyResult<Bound<'py, PyDict>> {
    let limits = overrides(limits)?;
    let in_memory = out_dir.is_none();
    let out = out_dir.map_or(Output::Memory(Keep::Tables), Output::Dir);
    let stop = Interrupt::new();
    let run_stop = stop.clone();
    match interruptible(py, &stop, move || {
        run_text(&text, &name, out, &limits, &run_stop)
    })? {
        Outcome::Invalid(e) => Err(scene_error(py, &e, None)),
        Outcome::Failed(msg) => Err(RunError::new_err(msg)),
        Outcome::Done(s, tables, files) => {
            let d = summary_dict(py, &s)?;
            if in_memory {
                d.set_item("tables", table::tables_dict(py, tables)?)?;
                let kept = PyDict::new(py);
                for f in files {
                    kept.set_item(f.file, PyBytes::new(py, &f.bytes))?;
                }
                d.set_item("files", kept)?;
            } else {
                d.set_item("tables", py.None())?;
                d.set_item("files", py.None())?;
            }
            Ok(d)
        }
    }
}
