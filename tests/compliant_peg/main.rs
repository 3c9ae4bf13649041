//! The compliant planar peg and Hertz contact: geometry, the model, energy
//! balance, friction laws, stiff integration, the insertion scene, and the
//! Hertz kernels under hostile inputs.

#[path = "../common/mod.rs"]
mod common;

mod elastic_friction;
mod energy;
mod geometry;
mod hertz;
mod hertz_hostile;
mod insertion;
mod model;
mod modules;
mod runtime;
mod scene;
mod scene_sensitivities;
mod sensitivity;
mod stiff;
