//! Output files written by scene runs: CSV tables ([`csv`]) and SVG line
//! plots ([`plot`] describes a figure, [`svg`] renders it); [`memory`] runs a
//! scene without files.

pub mod atomic;
pub mod csv;
pub mod decimate;
pub mod manifest;
pub mod memory;
pub mod plot;
pub mod svg;
