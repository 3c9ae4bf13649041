//! The compliant planar peg of "Dynamic analysis for peg-in-hole assembly
//! with contact deformation" (sections 2–3): contact
//! geometry and Hertz stiffness ([`geometry`]), checked parameters
//! ([`params`]), the generated model as an ODE system ([`system`]), initial
//! states ([`initial`]), classified insertion runs ([`simulate`]) and
//! forward sensitivities ([`sensitivity`], and along design directions in
//! [`directions`]); the
//! stick-capable friction law's system in [`elastic`].
//! See `docs/compliant.md` and `docs/contact-geometry.md`.

pub mod directions;
pub mod elastic;
pub mod geometry;
pub mod initial;
mod ode_at_parameters;
pub mod params;
pub mod sensitivity;
pub mod simulate;
pub mod system;

pub use elastic::{ElasticSystem, N_STATE_ELASTIC};
pub use geometry::{ContactPair, DEFAULT_FILLET, PegHoleGeometry};
pub use initial::PegState;
pub use params::{CompliantParams, CompliantSpec, ContactSet, FrictionLaw, Load};
pub use simulate::{InsertionOptions, InsertionOutcome, InsertionRun, Settle, simulate_insertion};
pub use system::{CompliantSystem, Sample};
