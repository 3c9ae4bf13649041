//! One file per module of the library, named after its path under
//! `src/`: the module's own items, tested through the crate's paths.

mod textbook_double_pendulum;
mod textbook_pendulum;
