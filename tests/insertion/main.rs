//! Robot insertion through a compliant wrist: the wrist, outcomes, the quasi-
//! static limit and design margins.

mod design_margins;
mod outcomes;
mod quasi_static;
mod wrist;
