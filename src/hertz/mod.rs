//! Hertz contact mechanics ("Dynamic analysis for peg-in-hole assembly with
//! contact deformation", section 2.3, eqs. (6)–(13)).
//!
//! Given the principal curvatures of two bodies at their point of contact
//! ([`Curvatures`]) and their materials ([`Material`]), [`HertzContact`]
//! computes the contact ellipse `a, b`, the maximum pressure `p₀`, the
//! approach `δ` and the stiffness `k` of the force–approach law
//! `Q = k δ^{3/2}` that the compliant dynamics uses.
//!
//! The ellipticity `a/b` follows from the curvature ratio through complete
//! elliptic integrals ([`ellipticity::solve`], exact to rounding); the
//! Hamrock–Brewe curve fit is available as a cheaper option
//! ([`EllipticityMethod::HamrockBrewe`]).
//!
//! Units are SI throughout: m, 1/m, N, Pa.

mod contact;
mod curvature;
pub mod elliptic;
pub mod ellipticity;
mod error;
mod material;

pub use contact::{ContactState, EllipticityMethod, HertzContact};
pub use curvature::Curvatures;
pub use ellipticity::{Coefficients, Ellipticity};
pub use error::HertzError;
pub use material::{Material, contact_modulus};
