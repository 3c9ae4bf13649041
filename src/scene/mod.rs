//! Scenes: TOML files that describe one simulation, and the framework that
//! parses, validates and runs them.
//!
//! A scene file has a top-level `kind = "..."`, an optional
//! `description = "..."`, kind-specific tables and usually an
//! `[integrator]` table ([`IntegratorSpec`]). [`load`] reads the file,
//! dispatches on `kind` through the [`KINDS`] registry, and returns a
//! validated [`LoadedScene`] whose [`LoadedScene::run`] writes its outputs
//! through a [`RunContext`] (e.g. `<out>/<name>.csv` and `<out>/<name>.svg`).
//!
//! The framework: [`kind`] (what a kind provides), [`loader`]
//! (parse, dispatch, validate), [`document`], [`validate`], [`ranges`]
//! (declared valid ranges), [`limits`] (and [`reserve`]), [`integrator`], [`context`] (the run
//! context and its output sink), progress, summary and [`timescales`]. Each kind lives in
//! [`kinds`], in a file or folder named as its `kind` string; tables and
//! code several kinds share are in [`shared`] (a kind imports from there,
//! never from another kind).
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

pub mod context;
pub mod document;
pub mod integrator;
pub mod kind;
pub mod kinds;
pub mod limits;
pub mod loader;
mod numbers;
pub(crate) mod progress;
pub mod ranges;
pub mod reserve;
pub mod shared;
pub(crate) mod simulate;
pub(crate) mod summary;
pub mod timescales;
pub(crate) mod translate;
pub mod validate;

pub use context::RunContext;
pub use document::Document;
pub use integrator::{IntegratorSpec, Method};
pub use kind::{Kind, Scene, Written};
pub use kinds::KINDS;
pub use loader::{LoadedScene, load, load_with, parse, parse_named, parse_named_with};
pub use numbers::significant;
pub use progress::{Progress, par_map_counted};
pub use summary::{
    ENERGY_DRIFT_WARNING, EventRecord, IntegrationSummary, Metric, RunSummary, StepFailure,
    energy_drift_warning,
};
pub use timescales::{TimeScale, TimeScales};
