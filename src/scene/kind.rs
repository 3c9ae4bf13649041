//! What a scene kind provides: a registry entry ([`Kind`]) and, once its
//! tables are validated, a runnable [`Scene`].

use std::fmt;

use crate::error::{RunError, SceneErrors};
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::limits::WorkItem;
use crate::scene::ranges::FieldRange;
use crate::scene::summary::RunSummary;
use crate::scene::timescales::TimeScales;

/// A validated scene, ready to run.
pub trait Scene: fmt::Debug {
    /// One line saying what the scene simulates, with its key parameters.
    fn describe(&self) -> String;
    /// Integrates the scene and writes its outputs through `ctx`. Run a
    /// loaded scene with [`crate::scene::LoadedScene::run`], which lists the files written.
    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError>;
    /// The work the scene asks for (samples, steps, grid points, runs),
    /// compared with the scene's `[limits]` before it may run
    /// ([`crate::scene::limits::Limits::check`]).
    fn work(&self) -> Vec<WorkItem> {
        Vec::new()
    }
    /// The scene's time scales estimated from its parameters (the fastest
    /// bounds the step): named as the likely cause when a step becomes too
    /// small, and when a run is unusually slow. `None` when the kind
    /// estimates none.
    fn time_scales(&self) -> Option<TimeScales> {
        None
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
    /// The declared ranges of its fields, table by table (`docs/scenes.md`
    /// documents each; a test checks it).
    pub ranges: &'static [&'static [FieldRange]],
}
