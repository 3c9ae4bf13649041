//! The integrators: tableaux and order conditions, events on dense output, the
//! Rosenbrock methods on stiff problems, no allocation on the hot path, hostile
//! options.

#[path = "../common/mod.rs"]
mod common;

mod component_atol;
mod error_components;
mod events;
mod hostile;
mod integrators;
mod kinematic;
mod modules;
mod no_alloc;
mod rosenbrock;
mod sensitivity_budget;
mod sensitivity_jump;
mod sensitivity_rosenbrock;
mod step_observer;
mod stiff;
