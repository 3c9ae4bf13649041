//! The tree itself: every path and section the docs name exists, the module layers, and
//! no import cycle between files.

#[path = "../common/mod.rs"]
mod common;

mod docs_paths;
mod docs_sections;
mod import_cycles;
mod import_graph;
mod layers;
mod no_unit_tests;
