//! Jamming and wedging: diagrams, the quasi-static and dynamic analyses, the
//! 3-D jamming space, the parallel sweep and the jamming scene.

#[path = "../common/mod.rs"]
mod common;

mod diagram;
mod dynamic;
mod input;
mod modules;
mod quasi_static;
mod scene;
mod sensitivities;
mod space3d;
mod sweep;
mod sweep_early_stop;
mod sweep_margin;
mod sweep_method;
mod wedging;
