//! A run as a replay page: one self-contained HTML file that opens from disk
//! with no network and draws the peg and the hole at their real dimensions,
//! the contact points with their normal and friction forces, the wrist's
//! compliance centre and the robot frame, the trajectory, a timeline with
//! the run's events and plots linked to the same cursor.
//!
//! Three steps, each its own module:
//!
//! 1. a model's run becomes a [`Replay`] record (SI units, hole frame):
//!    [`peg3d`] for the compliant 3-D peg (free or held by a wrist),
//!    [`planar`] for the compliant planar peg (drawn as a section);
//! 2. [`decimate`] keeps at most [`Budget::max_frames`] frames, every event
//!    state among them;
//! 3. [`html`] writes the record as JSON ([`json`]) into the page
//!    ([`page`]), with the renderer (three.js, embedded) and the page's own
//!    scripts.
//!
//! ```
//! use pegdyn::replay::{self, Replay, ReplayError};
//! // A run with no sample is refused with a typed error, not an empty page.
//! let empty = Replay::empty("nothing", replay::View::Solid);
//! assert!(matches!(replay::html(&empty), Err(ReplayError::NoFrames)));
//! ```

pub mod decimate;
pub mod error;
pub mod json;
pub mod page;
pub mod peg3d;
pub mod planar;
pub mod record;
pub mod states;

pub use decimate::Budget;
pub use error::ReplayError;
pub use record::{Contact, Frame, Geometry, Mark, MarkKind, Panel, Replay, Series, View};

/// The replay page of `replay`: one HTML document with everything it needs
/// (renderer, scripts, styles, data) inside.
///
/// # Errors
/// [`ReplayError::NoFrames`] for a record without frames,
/// [`ReplayError::NonFinite`] for a non-finite number anywhere in it.
pub fn html(replay: &Replay) -> Result<String, ReplayError> {
    let data = json::replay(replay)?;
    Ok(page::document(&replay.title, &data))
}
