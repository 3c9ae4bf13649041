//! One file per module of the library, named after its path under
//! `src/`: the module's own items, tested through the crate's paths.

mod integrate_iteration;
mod integrate_kinematic;
mod integrate_lu;
