//! Jamming and wedging of a peg in two-point contact (paper Eqs. 52–54 and
//! 65–86; Whitney, "Quasi-static assembly of compliantly supported rigid
//! parts", 1982).
//!
//! - [`params`]: the peg/hole parameters (r, c, μ), checked.
//! - [`geometry`]: exact two-point tilt θ(l), too-shallow limit.
//! - [`forces`]: quasi-static contact forces in Whitney's frame.
//! - [`quasi_static`]: the paper's Eqs. 51–54 in the paper's frame.
//! - [`diagram`]: the jamming parallelogram, Whitney's and exact.
//! - [`wedging`]: the wedging angle θ_c, exact and series.
//! - [`mod@sensitivities`]: derivatives of the corners, tilt and wedging
//!   angles with respect to r, c, μ and l (generated, `jamming_design`;
//!   [`sensitivities()`](fn@sensitivities) is re-exported here).
//! - [`space3d`]: the 3-D no-jamming inequalities (Eqs. 81–82).
//! - [`dynamic`]: the sweep of compliant-contact insertions (needs `compliant`).
//! - [`sweep`]: the dynamic sweep driver (rayon) and its comparison with the diagram.
//! - [`sweep_margin`]: the sweep's margin to its exact parallelogram with its
//!   derivatives along r, c, μ and the depth.
//! - `table` (crate-internal): the corner/wedging tables of the jamming scene
//!   (its Fig. 6-style panels are drawn by `scene::kinds::jamming::figure`).
//!
//! The derivation and the comparison with the paper are in `docs/jamming.md`.

pub mod diagram;
pub mod dynamic;
mod error;
pub mod forces;
pub mod geometry;
pub mod params;
pub mod quasi_static;
pub mod sensitivities;
pub mod space3d;
pub mod statics;
pub mod sweep;
pub mod sweep_margin;
#[cfg(feature = "scenes")]
pub(crate) mod table;
pub mod wedging;

pub use error::{ParamError, SlidingIndeterminate};
pub use params::PegHole;
pub use sensitivities::sensitivities;
