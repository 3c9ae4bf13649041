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
use std::path::{Path, PathBuf};

pub use document::Document;
pub use integrator::{IntegratorSpec, Method};
pub use progress::{Progress, par_map_counted};
pub use summary::{EventRecord, IntegrationSummary, Metric, RunSummary, significant};

use crate::error::{RunError, SceneError, SceneErrors};

/// A validated scene, ready to run.
pub trait Scene: fmt::Debug {
    /// One line saying what the scene simulates, with its key parameters.
    fn describe(&self) -> String;
    /// Integrates the scene and writes its outputs through `ctx`.
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

/// What a running scene gets from the caller.
#[derive(Debug)]
pub struct RunContext {
    /// Directory for the outputs: exists when the run starts, or is a
    /// [`crate::output::memory::Capture`] directory held in memory (write
    /// only through `CsvWriter`, `Figure::save` and `atomic::write`).
    pub out_dir: PathBuf,
    /// Scene name (file stem), the stem of every output file.
    pub name: String,
    /// Progress reporter.
    pub progress: Progress,
}

impl RunContext {
    /// `<out_dir>/<name>.<ext>`, e.g. `ctx.output("csv")`.
    pub fn output(&self, ext: &str) -> PathBuf {
        self.out_dir.join(format!("{}.{ext}", self.name))
    }

    /// `<out_dir>/<name>_<suffix>.<ext>`, for scenes with several outputs.
    pub fn output_with(&self, suffix: &str, ext: &str) -> PathBuf {
        self.out_dir.join(format!("{}_{suffix}.{ext}", self.name))
    }
}
