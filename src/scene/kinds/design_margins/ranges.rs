//! Valid ranges of the `design_margins` kind's `[grid]` table (the other
//! tables are `insert_rcc`'s, checked by its validation):
//!
//! - Lateral errors of the compliance centre within a metre either way:
//!   engineering positioning errors; the tip's error they lead to,
//!   `e_c − L_c sin θ`, must also stay within the robot table's ±2 D
//!   (checked per grid point, naming the list entry).
//! - Angular errors within ±30 degrees, the robot table's range.
//! - The grid's seat depth from a micrometre to a kilometre, below the
//!   bore's depth (checked against `peg.bore_depth`).

use crate::scene::ranges::FieldRange;

/// `grid.centre_lateral_errors` (each entry).
pub const CENTRE_LATERAL_ERRORS: FieldRange = FieldRange::new(
    "grid.centre_lateral_errors",
    -1.0,
    1.0,
    "m",
    "engineering positioning errors; the tip's error e_c - L_c sin(theta) must also stay within 2 D",
);

/// `grid.angular_errors_deg` (each entry).
pub const ANGULAR_ERRORS: FieldRange = FieldRange::new(
    "grid.angular_errors_deg",
    -30.0,
    30.0,
    "deg",
    "the robot table's range of angular errors",
);

/// `grid.seat_depth`.
pub const SEAT_DEPTH: FieldRange = FieldRange::new(
    "grid.seat_depth",
    1e-6,
    1e3,
    "m",
    "engineering sizes; it must also lie below 0.999 peg.bore_depth",
);

/// The `[grid]` table.
pub const GRID: &[FieldRange] = &[CENTRE_LATERAL_ERRORS, ANGULAR_ERRORS, SEAT_DEPTH];
