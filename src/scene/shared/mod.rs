//! Tables and code that several scene kinds share; a kind imports from
//! here, never from another kind.
//!
//! - [`material`]: the material table (compliant planar and 3-D pegs);
//! - [`rigid_peg`]: the `[peg]` table of the rigid three-point peg kinds
//!   (`fig9`, `align_forward`) and their ranges;
//! - [`pendulum`]: the ranges of the textbook pendulum kinds;
//! - [`compliant_peg_3d`]: the `[peg]`, `[wrist]`, `[robot]` and
//!   `[criteria]` tables of the compliant 3-D peg kinds (`drop_3d`,
//!   `insert_rcc`, `rotation_assist`, `design_margins`), their ranges, one
//!   held-peg insertion run, its outputs, margins and replay page;
//! - [`replay`]: the `[replay]` table of the kinds that write a replay
//!   page, and the page's file;
//! - [`sensitivities`]: the rows, files and ranking of a `[sensitivities]`
//!   table (`insert_compliant`, `insert_rcc`).

pub mod compliant_peg_3d;
pub mod material;
pub mod pendulum;
pub mod replay;
pub mod rigid_peg;
pub mod sensitivities;
