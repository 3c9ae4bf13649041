//! Output files written by scene runs: CSV tables ([`csv`]) and SVG line
//! plots ([`plot`] describes a figure, [`svg`] renders it).

pub mod atomic;
pub mod csv;
pub mod decimate;
pub mod manifest;
pub mod plot;
pub mod svg;
