//! Scene kinds of the compliant 3-D peg: `drop_3d` (released leaning on
//! the mouth) and `insert_rcc` (a robot inserting it through a compliant
//! wrist), with their shared tables and outputs. See `docs/insertion.md`.

pub mod drop;
pub mod margins;
pub mod output;
pub mod rcc;
pub mod sweep;
pub mod tables;
