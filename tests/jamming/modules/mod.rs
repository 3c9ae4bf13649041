//! One file per module of the library, named after its path under
//! `src/`: the module's own items, tested through the crate's paths.

mod jamming_forces;
mod scene_kinds_jamming_comparison;
