//! Valid ranges of the textbook pendulum kinds (`pendulum`,
//! `double_pendulum`). The scenes study motion under gravity:
//!
//! - Lengths in `[1e-6, 1e6]` m, masses in `[1e-9, 1e9]` kg, gravity up to
//!   `1e3` m/s²: the energies `m g L` and `m L² ω²` stay far inside f64.
//! - An initial rate `ω` with kinetic energy `½ m L² ω²` more than
//!   [`MAX_SPIN_OVER_GRAVITY`] times the potential scale `m g L` makes
//!   gravity's effect on the motion smaller than `1e-12` relative, below
//!   any tolerance the integrators can meet (f64 resolves `2.2e-16`): the
//!   scene would show a free rotor, and its energy check would only
//!   measure rounding. The limit is `|ω| ≤ √(2e12 g/L)`.

use crate::error::SceneError;
use crate::scene::ranges::FieldRange;
use crate::scene::validate::Checker;

/// Largest ratio of the initial kinetic energy to `m g L`.
pub const MAX_SPIN_OVER_GRAVITY: f64 = 1e12;

const WHY_LENGTH: &str = "a micrometre to a thousand kilometres: energies stay far inside f64";
const WHY_MASS: &str = "a microgram to a million tonnes: energies stay far inside f64";
const WHY_GRAVITY: &str = "up to 100 g: energies stay far inside f64";

/// The `[pendulum]` table.
pub const PENDULUM: &[FieldRange] = &[
    FieldRange::new("pendulum.length", 1e-6, 1e6, "m", WHY_LENGTH),
    FieldRange::new("pendulum.mass", 1e-9, 1e9, "kg", WHY_MASS),
    FieldRange::new("pendulum.gravity", 1e-300, 1e3, "m/s^2", WHY_GRAVITY),
];

/// The `[double_pendulum]` table.
pub const DOUBLE_PENDULUM: &[FieldRange] = &[
    FieldRange::new("double_pendulum.length1", 1e-6, 1e6, "m", WHY_LENGTH),
    FieldRange::new("double_pendulum.length2", 1e-6, 1e6, "m", WHY_LENGTH),
    FieldRange::new("double_pendulum.mass1", 1e-9, 1e9, "kg", WHY_MASS),
    FieldRange::new("double_pendulum.mass2", 1e-9, 1e9, "kg", WHY_MASS),
    FieldRange::new("double_pendulum.gravity", 1e-300, 1e3, "m/s^2", WHY_GRAVITY),
];

/// Records every range violation of `values` (in the order of `ranges`).
pub fn check_all(c: &mut Checker, ranges: &[FieldRange], values: &[f64]) {
    for (r, &v) in ranges.iter().zip(values) {
        r.check(c, v);
    }
}

/// Records an initial rate `omega` (rad/s) of field `name` on a link of
/// length `length` under `gravity` whose kinetic energy exceeds
/// [`MAX_SPIN_OVER_GRAVITY`] times the potential scale.
pub fn check_spin(c: &mut Checker, name: &str, omega: f64, length: f64, gravity: f64) {
    let limit = (2.0 * MAX_SPIN_OVER_GRAVITY * gravity / length).sqrt();
    if omega.is_finite() && limit.is_finite() && limit > 0.0 && omega.abs() > limit {
        c.push(SceneError::invalid(
            name,
            omega,
            format!(
                "the kinetic energy is more than {MAX_SPIN_OVER_GRAVITY:e} times m g L: gravity \
                 would change the motion by less than f64 and the integrators resolve; limit \
                 |omega| <= sqrt(2e12 g/L) = {limit:.3e} rad/s"
            ),
        ));
    }
}
