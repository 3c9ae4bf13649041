//! What the scene kinds of the compliant 3-D peg share (`drop_3d`,
//! `insert_rcc`, `rotation_assist`, `design_margins`; `docs/insertion.md`):
//! the `[peg]`, `[wrist]`, `[robot]` and `[criteria]` tables ([`tables`])
//! and their declared ranges ([`ranges`]), one held-peg insertion run
//! ([`insertion`]), its time series and events ([`output`]) and views
//! ([`views`]), its no-jam margins ([`margins`]), the check of its start
//! pose ([`start`]), its time scales ([`timescales`]) and its replay page
//! ([`replay`]).

pub mod design;
pub mod insertion;
pub mod margins;
pub mod output;
pub mod ranges;
pub mod replay;
pub mod start;
pub mod tables;
pub mod timescales;
pub mod views;
