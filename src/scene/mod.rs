//! Scenes: TOML files that describe one simulation, and the framework that
//! parses, validates and runs them.
//!
//! A scene file has a top-level `kind = "..."`, an optional
//! `description = "..."`, kind-specific tables and usually an
//! `[integrator]` table ([`IntegratorSpec`]). [`load`] reads the file,
//! dispatches on `kind` through the [`KINDS`] registry, and returns a
//! validated [`LoadedScene`] whose [`Scene::run`] writes
//! `<out>/<name>.csv` and `<out>/<name>.svg`.
//!
//! Adding a kind: one file with a [`Kind`] constant and a type implementing
//! [`Scene`], plus one row in [`KINDS`]; see `docs/scenes.md`.
//!
//! ```
//! let text = r#"
//! kind = "pendulum"
//! [pendulum]
//! length = -1.0
//! mass = 1.0
//! theta0_deg = 30.0
//! [integrator]
//! method = "dopri5"
//! t_end = 1.0
//! "#;
//! let err = pegdyn::scene::parse(text).unwrap_err().to_string();
//! assert!(err.contains("pendulum.length") && err.contains("-1.0"), "{err}");
//! ```

pub mod align_forward;
pub mod design_margins;
pub mod document;
pub mod double_pendulum;
pub mod fig9;
pub mod insert_3d;
pub mod insert_compliant;
pub mod integrator;
pub mod jamming;
pub(crate) mod jamming_figure;
pub mod jamming_sweep;
pub mod limits;
pub mod pendulum;
mod progress;
pub mod ranges;
pub(crate) mod simulate;
mod summary;
pub mod validate;

use std::fmt;
use std::path::Path;

pub use document::Document;
pub use integrator::{IntegratorSpec, Method};
pub use progress::{Progress, par_map_counted};
pub use summary::{EventRecord, IntegrationSummary, Metric, RunSummary, significant};

use crate::error::{OutputError, RunError, SceneError, SceneErrors};
use crate::output::names::Part;
use crate::output::plot::Figure;
use crate::output::sink::{Sink, TableWriter};

/// A validated scene, ready to run.
pub trait Scene: fmt::Debug {
    /// One line saying what the scene simulates, with its key parameters.
    fn describe(&self) -> String;
    /// Integrates the scene and writes its outputs through `ctx`. Run a
    /// loaded scene with [`LoadedScene::run`], which lists the files written.
    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError>;
    /// The work the scene asks for (samples, steps, grid points, runs),
    /// compared with the scene's `[limits]` before it may run
    /// ([`limits::Limits::check`]).
    fn work(&self) -> Vec<limits::WorkItem> {
        Vec::new()
    }
}

/// One entry of the scene-kind registry.
pub struct Kind {
    /// The value of `kind` in scene files.
    pub name: &'static str,
    /// Short description for listings.
    pub about: &'static str,
    /// Deserializes ([`Document::body`]) and validates the kind's tables.
    pub parse: fn(&Document<'_>) -> Result<Box<dyn Scene>, SceneErrors>,
}

/// Every scene kind `pegdyn` knows. Add a row here for a new kind.
pub const KINDS: &[Kind] = &[
    pendulum::KIND,
    double_pendulum::KIND,
    jamming::KIND,
    insert_compliant::KIND,
    fig9::KIND,
    align_forward::KIND,
    insert_3d::drop::KIND,
    insert_3d::rcc::KIND,
    insert_3d::sweep::KIND,
    design_margins::KIND,
];

/// A scene read from a file.
#[derive(Debug)]
pub struct LoadedScene {
    /// File stem, used to name the outputs.
    pub name: String,
    /// The `kind` field.
    pub kind: &'static str,
    /// The optional `description` field.
    pub description: Option<String>,
    /// The validated scene.
    pub scene: Box<dyn Scene>,
}

impl LoadedScene {
    /// Runs the scene into `ctx`; the summary's `outputs` are the files the
    /// run wrote, as its sink recorded them.
    ///
    /// # Errors
    /// The scene's run error (files completed before it stay recorded in
    /// `ctx`'s sink).
    pub fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let mut summary = self.scene.run(ctx)?;
        summary.outputs = ctx.sink().written();
        Ok(summary)
    }
}

/// Parses and validates scene text (no file name: the scene is named `scene`).
pub fn parse(text: &str) -> Result<LoadedScene, SceneErrors> {
    parse_named(text, "scene")
}

/// Parses and validates scene text, naming the outputs after `name`.
pub fn parse_named(text: &str, name: &str) -> Result<LoadedScene, SceneErrors> {
    parse_named_with(text, name, &limits::LimitOverrides::default())
}

/// As [`parse_named`], with the scene's `[limits]` replaced key by key by
/// `overrides` (the `--limit` option of `pegdyn check` and `pegdyn run`).
pub fn parse_named_with(
    text: &str,
    name: &str,
    overrides: &limits::LimitOverrides,
) -> Result<LoadedScene, SceneErrors> {
    let doc = Document::parse(text)?;
    let kind = KINDS.iter().find(|k| k.name == doc.kind()).ok_or_else(|| {
        doc.locate_all(SceneErrors::from(SceneError::UnknownKind {
            value: doc.kind().to_string(),
            known: KINDS.iter().map(|k| k.name).collect::<Vec<_>>().join(", "),
        }))
    })?;
    let scene = (kind.parse)(&doc).map_err(|e| doc.locate_all(e))?;
    overrides
        .apply(doc.limits()?)
        .check(&scene.work())
        .map_err(|e| doc.locate_all(e))?;
    Ok(LoadedScene {
        name: name.to_string(),
        kind: kind.name,
        description: doc.description().map(str::to_string),
        scene,
    })
}

/// Reads, parses and validates the scene file at `path`.
pub fn load(path: &Path) -> Result<LoadedScene, SceneErrors> {
    load_with(path, &limits::LimitOverrides::default())
}

/// As [`load`], with `overrides` applied to the scene's `[limits]`.
pub fn load_with(
    path: &Path,
    overrides: &limits::LimitOverrides,
) -> Result<LoadedScene, SceneErrors> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let name = path
        .file_stem()
        .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
    parse_named_with(&text, &name, overrides)
}

/// What a running scene gets from the caller: the sink its outputs go to
/// (a directory or memory; the only way a scene writes a file) and a
/// progress reporter.
#[derive(Debug)]
pub struct RunContext {
    sink: Sink,
    /// Progress reporter.
    pub progress: Progress,
}

impl RunContext {
    /// A context writing into `sink`.
    pub fn new(sink: Sink, progress: Progress) -> Self {
        RunContext { sink, progress }
    }

    /// The scene's name (file stem), the stem of every output file.
    pub fn name(&self) -> &str {
        self.sink.scene()
    }

    /// Starts the CSV table of `part` ([`Sink::table`]), e.g.
    /// `ctx.table(Part::Main, &["t_s", "x_m"])` for `<name>.csv`.
    ///
    /// # Errors
    /// The file cannot be created, or would replace the scene file.
    pub fn table(&self, part: Part, header: &[&str]) -> Result<TableWriter, OutputError> {
        self.sink.table(part, header)
    }

    /// Draws `fig` as the SVG file of `part` ([`Sink::figure`]).
    ///
    /// # Errors
    /// A panel without a drawable point, or the file cannot be written.
    pub fn figure(&self, part: Part, fig: &Figure) -> Result<(), OutputError> {
        self.sink.figure(part, fig)
    }

    /// Writes `bytes` as the file of `part` with extension `ext`
    /// ([`Sink::file`]).
    ///
    /// # Errors
    /// The file cannot be written, or would replace the scene file.
    pub fn file(&self, part: Part, ext: &str, bytes: &[u8]) -> Result<(), OutputError> {
        self.sink.file(part, ext, bytes)
    }

    /// The sink: what the run has written so far ([`Sink::written`]).
    pub fn sink(&self) -> &Sink {
        &self.sink
    }

    /// Ends the run's context, handing back its sink (e.g. for the tables
    /// kept in memory, [`Sink::into_tables`]).
    pub fn into_sink(self) -> Sink {
        self.sink
    }
}
