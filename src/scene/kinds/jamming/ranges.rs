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
//! - The sweep's loads, grid, run length, advance and window over the span
//!   where its runs can be classified and compared with the quasi-static
//!   diagram (each constant gives its reason); the window at most the run.

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

/// `sweep.fz_n`.
pub const FZ: FieldRange = FieldRange::new(
    "sweep.fz_n",
    1e-6,
    1e4,
    "N",
    "a micronewton to 10 kN: beyond, the 0.2 mm fillets of the sweep's steel peg are loaded far past Hertz's small-contact assumption and the runs no longer follow the quasi-static diagram",
);
/// `sweep.fx_over_fz_max`.
pub const FX_MAX: FieldRange = FieldRange::new(
    "sweep.fx_over_fz_max",
    1e-3,
    1e3,
    "",
    "the grid's half-width in F_x/F_z, around the diagram's width 1/mu",
);
/// `sweep.m_over_rfz_max`.
pub const M_MAX: FieldRange = FieldRange::new(
    "sweep.m_over_rfz_max",
    1e-3,
    1e3,
    "",
    "the grid's half-height in M/(r F_z), around the diagram's height l/(r mu)",
);
/// `sweep.t_max_s`.
pub const T_MAX: FieldRange = FieldRange::new(
    "sweep.t_max_s",
    1e-4,
    1e2,
    "s",
    "a run of 0.1 ms to 100 s; it must also hold at least one classification window",
);
/// `sweep.advance_m`.
pub const ADVANCE: FieldRange = FieldRange::new(
    "sweep.advance_m",
    5e-5,
    1.0,
    "m",
    "an advance well beyond the 2 um the stuck test allows per window and the contacts' elastic approach: at 1e-5 m the contacts' settling already counts as an insertion",
);
/// `sweep.window_s` (at most `sweep.t_max_s`; the check uses the scene's).
pub const WINDOW: FieldRange = FieldRange::new(
    "sweep.window_s",
    1e-6,
    1e2,
    "s",
    "the stuck test's window, at most sweep.t_max_s: a run shorter than its window is never classified",
);
/// `sweep.n`.
pub const N: FieldRange = FieldRange::new(
    "sweep.n",
    3.0,
    1e4,
    "",
    "grid points per axis: at least 3 so that the grid has an inside and an outside; the runs n^2 are bounded by [limits] max_runs",
);
/// `sweep.atol` (default `1e-8`; m, rad, m/s, rad/s).
pub const ATOL: FieldRange = FieldRange::new(
    "sweep.atol",
    1e-20,
    1e-6,
    "",
    "the absolute tolerance of the runs' lengths (m), angles (rad) and their rates: above 1e-6 the error allowed in a coordinate reaches the 2 um the stuck test measures per window (at 1e-2 every judged point of the shipped sweep contradicts the diagram); far below 1e-20 the error test of a component at zero asks for digits f64 does not hold (at 1e-50 every run exhausts its step budget)",
);

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
    FZ,
    FX_MAX,
    M_MAX,
    T_MAX,
    ADVANCE,
    WINDOW,
    N,
    ATOL,
];
