//! The compliant peg-in-hole model of paper 001 (sections 2–3): contact
//! geometry and Hertz stiffness ([`geometry`]).

pub mod geometry;

pub use geometry::{ContactPair, DEFAULT_FILLET, PegHoleGeometry};
