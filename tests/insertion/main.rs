//! Robot insertion through a compliant wrist: the wrist, outcomes, the quasi-
//! static limit and design margins.

#[path = "../common/mod.rs"]
mod common;

mod design;
mod design_margins;
mod design_sensitivities;
mod industreal;
mod jacobian;
mod modules;
mod outcomes;
mod quasi_static;
mod start_poses;
mod summaries;
mod wrist;
