//! The `pegdyn` command line and scene files: every subcommand, refused scenes
//! with the field named, and fuzzed scene files.

#[path = "../common/mod.rs"]
mod common;

mod bounded_work;
mod cli;
mod errors;
mod fuzz;
mod hostile_scenes;
mod modules;
mod replay;
mod run_record;
mod step_causes;
