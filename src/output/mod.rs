//! Outputs of scene runs: a run writes through its [`sink::Sink`] (a
//! directory or memory, named by [`names`]), which is the only way a scene
//! writes a file: CSV tables ([`csv`], or [`memory`] tables), SVG line plots
//! ([`plot`] describes a figure, [`svg`] renders it) and other files, each
//! whole or not at all ([`atomic`]). The run manifest ([`manifest`]) records
//! what a run wrote and how it ended, kept true from its start by the run's
//! [`record`].

pub mod atomic;
pub(crate) mod axes;
pub mod csv;
pub mod decimate;
pub(crate) mod legend;
pub mod manifest;
pub mod memory;
pub mod names;
pub mod plot;
pub mod record;
pub mod sink;
pub mod svg;
