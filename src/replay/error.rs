//! Why a run cannot be replayed.

use crate::hertz::HertzError;

/// Why no replay page was made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ReplayError {
    /// The run holds no state to draw (no output sample, no event, no
    /// final state).
    #[error("the run has no samples to replay")]
    NoFrames,
    /// A number of the record is NaN or infinite (non-finite states are
    /// refused before a run is reported; this guards the page against a
    /// model output that is not).
    #[error("{quantity} is not finite at t = {t} s: a replay draws finite values only")]
    NonFinite {
        /// What the number is, e.g. `contact normal force`.
        quantity: &'static str,
        /// Time of the frame that holds it (s); NaN for the geometry.
        t: f64,
    },
    /// The model refused a state while the frames were evaluated.
    #[error("evaluating a frame at t = {t} s: {source}")]
    Model {
        /// Time of the frame (s).
        t: f64,
        /// The model's error.
        source: HertzError,
    },
}
