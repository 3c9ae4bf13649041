//! The compliant 3-D peg: a rigid cylinder with a filleted bottom rim in a
//! bore with a filleted mouth, six degrees of freedom (centre of mass, unit
//! quaternion, body angular velocity; Newton–Euler), Hertz point contacts
//! found along the edge circles at every right-hand-side call.
//!
//! - [`params`]: bodies, materials, loads and contact laws, and the
//!   generated functions' parameter vector.
//! - [`search`]: the local maxima of penetration of each contact pair by
//!   Newton in the edge angle, warm-started, with a bracketing scan.
//! - [`merge`]: the continuous rule by which two points of one pair share
//!   their force as they merge (prominence above the col between them).
//! - [`jacobian`]: the exact Jacobian, the generated partial derivatives
//!   and the chain rule through the contact wrench, in [`dual`] numbers.
//! - [`prune`]: cheap bounds that skip the pairs a pose cannot touch.
//! - [`face`]: the peg's bottom on a flat at small tilt: the rim circle
//!   as a distributed line contact (closed-form ring potential), handed
//!   over to the rim's Hertz point contact as the tilt grows.
//! - [`curvature`]: the principal curvatures of both surfaces at a contact
//!   point, for the Hertz ellipse.
//! - [`stiffness`]: the pose derivative of the curvature stiffness, whose
//!   term `−(2/5) δ^{5/2} ∂k/∂(pose)` completes the elastic force.
//! - [`system`]: contact forces (Hertz, Hunt–Crossley damping, regularized
//!   Coulomb friction with the material point's velocity) summed into the
//!   wrench of the generated Newton–Euler right-hand side.
//!
//! See `docs/compliant-peg-3d.md`.

pub mod curvature;
pub mod dual;
pub mod face;
pub mod jacobian;
pub mod merge;
pub mod params;
pub mod prescribed;
pub mod prune;
pub mod search;
pub mod stiffness;
pub mod system;

pub use merge::Saddle;
pub use params::{HertzMode, Peg3dParams};
pub use search::{ContactPoint, Pair, Search};
pub use system::{Peg3d, pose_state};
pub mod insertion;
pub mod outcome;
pub mod robot;
pub mod wrist;
