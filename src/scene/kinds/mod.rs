//! The scene kinds, each in a file or folder named exactly as its `kind`
//! string, and the registry [`KINDS`]. A kind imports the framework
//! (`crate::scene::*`) and the tables in [`crate::scene::shared`], never
//! another kind.

pub mod align_forward;
pub mod design_margins;
pub mod double_pendulum;
pub mod drop_3d;
pub mod fig9;
pub mod insert_compliant;
pub mod insert_rcc;
pub mod jamming;
pub mod pendulum;
pub mod rotation_assist;

use crate::scene::kind::Kind;

/// Every scene kind `pegdyn` knows. Add a row here for a new kind.
pub const KINDS: &[Kind] = &[
    pendulum::KIND,
    double_pendulum::KIND,
    jamming::KIND,
    insert_compliant::KIND,
    fig9::KIND,
    align_forward::KIND,
    drop_3d::KIND,
    insert_rcc::KIND,
    rotation_assist::KIND,
    design_margins::KIND,
];
