//! The tree itself: every path the docs name exists, and the module layers.

#[path = "../common/mod.rs"]
mod common;

mod docs_paths;
mod layers;
