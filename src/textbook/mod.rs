//! Textbook systems generated from their Lagrangians, as ODE systems: the
//! simple pendulum and the planar double pendulum. They check the generator
//! and the integrators against known invariants (energy, period); the scene
//! kinds `pendulum` and `double_pendulum` run them from TOML.

pub mod double_pendulum;
pub mod pendulum;
