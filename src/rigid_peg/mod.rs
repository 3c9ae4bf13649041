//! The rigid three-point peg of "Peg-on-hole: fundamental principles of motion
//! of a peg leaning on a horizontal hole edge": a rigid peg leaning on a
//! horizontal hole edge at three points
//! K, B1, B2, with two degrees of freedom: nutation γ and precession ψ.
//!
//! - [`PegParams`], [`Loads`]: dimensions, mass, friction and loads;
//! - [`kinematics`]: geometry, poses, velocities and contact Jacobians
//!   (hand-derived, corrected paper forms), used by every path below;
//! - [`dynamics`]: the hand-derived equations of motion and reactions: the
//!   linear systems of the static-hold and prescribed-motion checks, the
//!   shared LU [`dynamics::solve`] and friction directions, and the oracle
//!   the generated model is tested against;
//! - [`generated_model`]: the same model derived by the generator
//!   (`pegdyn::generated::rigid_peg*`), in four variants;
//! - [`reaction_sensitivity`]: derivatives of the accelerations and
//!   reactions with respect to the geometry (γ0 following D and d);
//! - [`prescribed`]: reactions and driving moments of a prescribed motion
//!   (Fig. 9), through the generated model;
//! - [`forward`], [`forward_events`], [`trajectory`], [`stop`]: forward
//!   dynamics with contact-state events;
//! - [`stick`]: stick or slip from rest; [`modes`]: contact modes
//!   (lift-off, Painlevé).
//!
//! Derivation and findings: `docs/rigid-peg.md`; the generated model:
//! `docs/rigid-model.md`.

pub mod dynamics;
pub mod forward;
pub mod forward_events;
mod generated_inputs;
pub mod generated_model;
pub mod kinematics;
pub mod modes;
mod params;
pub mod prescribed;
pub mod reaction_sensitivity;
pub mod static_hold;
pub mod stick;
pub mod stop;
pub mod trajectory;

pub use params::{Loads, PegParams};

/// Why a rigid-peg computation cannot return a physical answer.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RigidError {
    /// A parameter is out of range.
    #[error("parameter `{field}` = {value}: {reason}")]
    Param {
        /// Parameter name.
        field: &'static str,
        /// Offending value.
        value: f64,
        /// What is required.
        reason: &'static str,
    },
    /// γ is outside the three-point-contact range γ0 < γ < π/2.
    #[error(
        "gamma = {gamma} rad is outside the three-point contact range (gamma0 = {gamma0} rad, pi/2)"
    )]
    NotThreePoint {
        /// The requested γ (rad).
        gamma: f64,
        /// γ0 = arccos(d/D) (rad).
        gamma0: f64,
    },
    /// The linear system for accelerations and reactions is singular.
    #[error("singular contact system at gamma = {gamma} rad (Painleve-type indeterminacy)")]
    Singular {
        /// γ (rad).
        gamma: f64,
    },
    /// The chosen generated-model variant cannot represent the request
    /// (e.g. a planar variant with ψ̇ ≠ 0, a frictionless one with f > 0).
    #[error("variant `{variant}` cannot represent this request: {reason}")]
    Unrepresentable {
        /// The variant's module name.
        variant: &'static str,
        /// What it cannot represent.
        reason: &'static str,
    },
    /// Friction direction undefined: a contact does not slide.
    #[error("contact {contact} has zero sliding speed; Coulomb friction has no direction")]
    NoSliding {
        /// Contact name (K, B1, B2).
        contact: &'static str,
    },
}
