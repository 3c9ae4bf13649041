//! The rigid three-point peg: geometry, dynamics, the generated variants,
//! forward motion, sticking, Painlevé cases and the Fig. 9 study.

#[path = "../common/mod.rs"]
mod common;

mod align_forward_scene;
mod dynamics;
mod fig9_findings;
mod fig9_scene;
mod forward;
mod generated;
mod generated_runtime;
mod geometry;
mod painleve;
mod reaction_sensitivity;
mod stick;
