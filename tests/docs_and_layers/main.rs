//! The tree itself: every path the docs name exists, and the module layers.

mod docs_paths;
mod layers;
