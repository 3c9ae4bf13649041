//! One file per module of the library, named after its path under
//! `src/`: the module's own items, tested through the crate's paths.

mod scene_kinds_design_margins_chamfer;
mod scene_kinds_rotation_assist_figure;
