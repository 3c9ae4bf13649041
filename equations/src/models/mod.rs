//! The models, one file or folder each. A model is a function building a [`Module`]
//! in a fresh [`Graph`]; register it in [`ALL`] (one line) to have its code
//! generated into `pegdyn::generated::<name>`.

use crate::graph::Graph;
use crate::model::Module;

pub mod cart_pole;
pub mod compliant_peg;
pub mod compliant_peg_3d;
pub mod double_pendulum;
pub mod hertz;
pub mod pendulum;
pub mod quasi_static;
pub mod rigid_peg;

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
    compliant_peg::variants::module,
    compliant_peg::variants::module_lean,
    compliant_peg::variants::module_elastic,
    quasi_static::module,
    rigid_peg::variants::module,
    rigid_peg::variants::module_frictionless,
    rigid_peg::variants::module_planar,
    rigid_peg::variants::module_planar_frictionless,
    compliant_peg_3d::module,
];
