//! Reading a scene: parse the TOML, dispatch on `kind` through the
//! registry ([`crate::scene::kinds::KINDS`]), check the kind's tables,
//! bound the work they ask for by the scene's `[limits]`, and only then
//! build the runnable scene.

use std::path::Path;

use crate::error::{RunError, SceneError, SceneErrors};
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::kind::Scene;
use crate::scene::kinds::KINDS;
use crate::scene::limits::{LimitOverrides, WorkItem};
use crate::scene::summary::{RunSummary, StepFailure};

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
    /// The work it asks for, as checked against its limits.
    pub work: Vec<WorkItem>,
}

impl LoadedScene {
    /// Runs the scene into `ctx`; the summary's `outputs` are the files the
    /// run wrote, as its sink recorded them.
    ///
    /// # Errors
    /// The scene's run error (files completed before it stay recorded in
    /// `ctx`'s sink).
    pub fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let scales = self.scene.time_scales();
        ctx.progress.explain(scales.as_ref());
        let mut summary = self.scene.run(ctx)?;
        if let Some(i) = summary.integration.as_mut()
            && let Some(failure) = i.step_failure
            && let Some(scales) = &scales
        {
            i.stop.push_str("; likely cause: ");
            i.stop.push_str(&match failure {
                StepFailure::TooSmall { t, h } => scales.step_failure_cause(t, h),
                StepFailure::Budget { t, mean } => scales.budget_cause(t, mean),
            });
        }
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
    parse_named_with(text, name, &LimitOverrides::default())
}

/// As [`parse_named`], with the scene's `[limits]` replaced key by key by
/// `overrides` (the `--limit` option of `pegdyn check` and `pegdyn run`).
pub fn parse_named_with(
    text: &str,
    name: &str,
    overrides: &LimitOverrides,
) -> Result<LoadedScene, SceneErrors> {
    crate::output::names::check_scene_name(name).map_err(SceneError::from)?;
    let doc = Document::parse(text)?;
    let kind = KINDS.iter().find(|k| k.name == doc.kind()).ok_or_else(|| {
        doc.locate_all(SceneErrors::from(SceneError::UnknownKind {
            value: doc.kind().to_string(),
            known: KINDS.iter().map(|k| k.name).collect::<Vec<_>>().join(", "),
        }))
    })?;
    let written = (kind.parse)(&doc).map_err(|e| doc.locate_all(e))?;
    // Bounded before anything the scene sizes is built.
    let work = written.work();
    overrides
        .apply(doc.limits()?)
        .check(&work)
        .map_err(|e| doc.locate_all(e))?;
    let scene = written.build().map_err(|e| doc.locate_all(e))?;
    Ok(LoadedScene {
        name: name.to_string(),
        kind: kind.name,
        description: doc.description().map(str::to_string),
        scene,
        work,
    })
}

/// Reads, parses and validates the scene file at `path`.
pub fn load(path: &Path) -> Result<LoadedScene, SceneErrors> {
    load_with(path, &LimitOverrides::default())
}

/// As [`load`], with `overrides` applied to the scene's `[limits]`.
pub fn load_with(path: &Path, overrides: &LimitOverrides) -> Result<LoadedScene, SceneErrors> {
    let (text, name) = read(path)?;
    parse_named_with(&text, &name, overrides)
}

/// The text of the scene file at `path` and the scene's name, its file
/// stem (lossy where the stem is not UTF-8). Read once: the text returned
/// is the text to parse and to record.
///
/// # Errors
/// [`SceneError::Io`] if the file cannot be read or is not UTF-8.
pub fn read(path: &Path) -> Result<(String, String), SceneErrors> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let name = path
        .file_stem()
        .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
    Ok((text, name))
}
