//! The compliant 3-D peg: contact search, Jacobian, curvature stiffness,
//! seating, the side wall, and its limits (rigid, planar, quasi-static,
//! energy).

#[path = "../common/mod.rs"]
mod common;

mod contact;
mod curvature_stiffness;
mod elastic_friction;
mod flat_minimum;
mod insertion_split;
mod jacobian;
mod limits_energy;
mod limits_planar;
mod limits_rigid;
mod limits_statics;
mod modules;
mod reuse_bounds;
mod search_property;
mod seated;
mod side_wall;
mod split_minimum;
mod symmetric_minimum;
mod tracked_search;
mod wedged_elastic;
