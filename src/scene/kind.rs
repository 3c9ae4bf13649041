//! What a scene kind provides: a registry entry ([`Kind`]) whose `parse`
//! reads the kind's tables into a [`Written`] scene — each field checked,
//! nothing built whose size the scene sets —, the work that scene asks for
//! ([`Written::work`], from its tables' lengths and spans), and, once the
//! work is within the limits, the runnable [`Scene`] ([`Written::build`]).
//! The loader calls them in that order, so that no grid is built before it
//! is bounded.

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
    /// The scene's time scales estimated from its parameters (the fastest
    /// bounds the step): named as the likely cause when a step becomes too
    /// small, and when a run is unusually slow. `None` when the kind
    /// estimates none.
    fn time_scales(&self) -> Option<TimeScales> {
        None
    }
}

/// A scene as read from its tables, each field checked on its own, before
/// anything whose size the scene sets (grid points, runs) is built.
pub trait Written: fmt::Debug {
    /// The work the scene asks for (samples, steps, grid points, runs, and
    /// the bytes each stores), estimated from the tables alone (list
    /// lengths, spans, counts; in floating point, never allocating), and
    /// compared with the scene's `[limits]` before [`Written::build`]
    /// ([`crate::scene::limits::Limits::check`]).
    fn work(&self) -> Vec<WorkItem>;
    /// Builds the runnable scene (its grid points, its runs), checking
    /// what depends on several fields at once.
    ///
    /// # Errors
    /// Every invalid field or combination, named.
    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors>;
}

/// One entry of the scene-kind registry.
pub struct Kind {
    /// The value of `kind` in scene files.
    pub name: &'static str,
    /// Short description for listings.
    pub about: &'static str,
    /// Deserializes ([`Document::body`]) and checks the kind's tables
    /// field by field, building nothing whose size the scene sets.
    pub parse: fn(&Document<'_>) -> Result<Box<dyn Written>, SceneErrors>,
    /// The declared ranges of its fields, table by table (`docs/scenes.md`
    /// documents each; a test checks it).
    pub ranges: &'static [&'static [FieldRange]],
}
