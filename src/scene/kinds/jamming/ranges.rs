//! Valid ranges of the `jamming` kind (Whitney's quasi-static analysis and
//! the compliant-peg sweep):
//!
//! - The clearance ratio `c = (D − d)/D` is at least
//!   [`MIN_CLEARANCE_RATIO`]: the hole diameter is computed as
//!   `d/(1 − c)` and the two-point geometry from `D − d`, which f64 does not
//!   resolve below (as for `insert_compliant`); `c < 1` leaves a peg.
//! - Friction coefficients in `(0, 10]`: engineering pairs lie below about
//!   1.5, and the jamming diagram's `λ = l/(2 r μ)` degenerates at `μ → 0`.
//! - Lengths (radius, depths, peg length) in `[1e-6, 1e3]` m, engineering
//!   sizes.
//! - Hunt–Crossley contact damping in `[0, 1e3]` s/m, as for the 3-D
//!   kinds' `contact_damping`.

use crate::scene::ranges::{FieldRange, MIN_CLEARANCE_RATIO, WHY_CONTACT_DAMPING};

const WHY_C: &str =
    "below 1e-9 f64 does not resolve the clearance D - d; at 1 the peg has no radius";
const WHY_MU: &str = "Coulomb coefficients of material pairs lie below about 1.5; lambda = l/(2 r mu) degenerates at 0";
const WHY_LENGTH: &str = "engineering sizes, a micrometre to a kilometre";

/// Largest clearance ratio (just below 1).
const C_MAX: f64 = 1.0 - f64::EPSILON;

/// The `[jamming]` table (list entries are checked one by one).
pub const JAMMING: &[FieldRange] = &[
    FieldRange::new("jamming.r_m", 1e-6, 1e3, "m", WHY_LENGTH),
    FieldRange::new("jamming.c", MIN_CLEARANCE_RATIO, C_MAX, "", WHY_C),
    FieldRange::new("jamming.mu", 1e-6, 10.0, "", WHY_MU),
    FieldRange::new("jamming.l_m", 1e-6, 1e3, "m", WHY_LENGTH),
];

/// The `[sweep]` table.
pub const SWEEP: &[FieldRange] = &[
    FieldRange::new("sweep.r_m", 1e-6, 1e3, "m", WHY_LENGTH),
    FieldRange::new("sweep.c", MIN_CLEARANCE_RATIO, C_MAX, "", WHY_C),
    FieldRange::new("sweep.mu", 1e-6, 10.0, "", WHY_MU),
    FieldRange::new("sweep.l_m", 1e-6, 1e3, "m", WHY_LENGTH),
    FieldRange::new("sweep.peg_length_m", 1e-6, 1e3, "m", WHY_LENGTH),
    FieldRange::new(
        "sweep.contact_damping",
        0.0,
        1e3,
        "s/m",
        WHY_CONTACT_DAMPING,
    ),
];
