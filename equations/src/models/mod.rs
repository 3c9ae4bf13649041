//! The models, one file each. A model is a function building a [`Module`]
//! in a fresh [`Graph`]; register it in [`ALL`] (one line) to have its code
//! generated into `pegdyn::generated::<name>`.

use crate::graph::Graph;
use crate::model::Module;

pub mod cart_pole;
pub mod compliant_peg_3d;
pub mod double_pendulum;
pub mod hertz;
pub mod pendulum;
pub mod planar_peg;
pub mod planar_peg_geometry;
pub mod planar_peg_module;
pub mod quasi_static;
pub mod rigid_peg;
pub mod rigid_peg_geometry;
pub mod rigid_peg_module;

/// Builds one model's module in the given graph.
pub type ModelFn = fn(&Graph) -> Module;

/// Every model the build generates code for, in emission order. One model
/// per line (kept by `rustfmt::skip`) so that registrations merge cleanly.
#[rustfmt::skip]
pub const ALL: &[ModelFn] = &[
    pendulum::module,
    double_pendulum::module,
    cart_pole::module,
    hertz::module,
    planar_peg_module::module,
    planar_peg_module::module_lean,
    quasi_static::module,
    rigid_peg_module::module,
    rigid_peg_module::module_frictionless,
    rigid_peg_module::module_planar,
    rigid_peg_module::module_planar_frictionless,
    compliant_peg_3d::module,
];
