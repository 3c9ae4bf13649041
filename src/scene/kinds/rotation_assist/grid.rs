//! Valid ranges of the `rotation_assist` kind's `[grid]` table (the other
//! tables are `insert_rcc`'s): each list entry replaces a `[robot]` field
//! and has that field's range; the yield pressure spans soft polymers to
//! far above the hardest steels.

use crate::scene::ranges::FieldRange;
use crate::scene::shared::compliant_peg_3d::ranges;

/// `grid.yield_pressure`.
pub const YIELD_PRESSURE: FieldRange = FieldRange::new(
    "grid.yield_pressure",
    1e3,
    1e12,
    "Pa",
    "a yield pressure from soft polymers (kPa) to far above the hardest steels (a few GPa)",
);

/// `grid.lateral_errors` (each entry; the robot's range, within two bore
/// diameters: the check uses the scene's `D`).
pub const LATERAL_ERRORS: FieldRange = FieldRange {
    field: "grid.lateral_errors",
    ..ranges::LATERAL_ERROR
};
/// `grid.angular_errors_deg` (each entry; the robot's range).
pub const ANGULAR_ERRORS: FieldRange = FieldRange {
    field: "grid.angular_errors_deg",
    ..ranges::ANGULAR_ERROR
};
/// `grid.precession_rates` (each entry; the robot's range).
pub const PRECESSION_RATES: FieldRange = FieldRange {
    field: "grid.precession_rates",
    ..ranges::PRECESSION_RATE
};
/// `grid.spin_rates` (each entry; the robot's range).
pub const SPIN_RATES: FieldRange = FieldRange {
    field: "grid.spin_rates",
    ..ranges::SPIN_RATE
};

/// The `[grid]` table.
pub const GRID: &[FieldRange] = &[
    LATERAL_ERRORS,
    ANGULAR_ERRORS,
    PRECESSION_RATES,
    SPIN_RATES,
    YIELD_PRESSURE,
];
