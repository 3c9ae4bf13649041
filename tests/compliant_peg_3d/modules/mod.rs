//! One file per module of the library, named after its path under
//! `src/`: the module's own items, tested through the crate's paths.

mod compliant_peg_3d_contact;
mod compliant_peg_3d_frame;
mod compliant_peg_3d_mindlin;
mod compliant_peg_3d_search_interval;
mod compliant_peg_3d_search_trig;
mod compliant_peg_3d_wrist;
