//! The `[peg]` table of the rigid three-point peg kinds (`fig9`,
//! `align_forward`) and the valid ranges of their fields, from the
//! rigid-body model's assumptions:
//!
//! - The peg and the hole do not deform: speeds stay far below the elastic
//!   wave speed of the material (about 5000 m/s in steel), so the rim speed
//!   of a rotation, `|ψ̇| D/2` or `|γ̇| H`, is at most [`MAX_RIM_SPEED`];
//!   applied loads accelerate the peg by at most [`MAX_LOAD_ACCELERATION`]
//!   (10⁴ g), beyond which a real peg would yield at its contacts.
//! - Engineering sizes: lengths in `[1e-6, 1e3]` m (micro-assembly to a
//!   kilometre), masses in `[1e-9, 1e6]` kg. Within these, every term of
//!   the generated model (`m g H`, `m ψ̇² D H`, `m (3r² + H²)/12`) stays
//!   within `1e-40 … 1e40`, far from f64's overflow; outside, a fuzzed
//!   scene (H = 7.7e-154 m, m = 1.4e157 kg, ψ̇ = 6.3e76 1/s) produced
//!   reactions of 1e308 N.
//! - The radial clearance `D − d` is a difference of nearly equal lengths:
//!   the clearance ratio `(D − d)/D` must be at least
//!   [`MIN_CLEARANCE_RATIO`] for f64 to resolve it (and γ0 with it).

use serde::Deserialize;

use crate::error::SceneError;
use crate::rigid_peg::PegParams;
use crate::scene::ranges::{FieldRange, MIN_CLEARANCE_RATIO};
use crate::scene::validate::Checker;

/// The `[peg]` table (SI units).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PegTable {
    /// Hole diameter D, m.
    pub hole_diameter: f64,
    /// Peg diameter d, m.
    pub peg_diameter: f64,
    /// Peg height H, m.
    pub height: f64,
    /// Peg mass, kg.
    pub mass: f64,
    /// Gravitational acceleration, m/s².
    pub gravity: f64,
    /// Coulomb friction coefficient.
    pub friction: f64,
}

impl PegTable {
    /// The model parameters.
    pub fn params(&self) -> PegParams {
        PegParams {
            hole_diameter: self.hole_diameter,
            peg_diameter: self.peg_diameter,
            height: self.height,
            mass: self.mass,
            gravity: self.gravity,
            friction: self.friction,
        }
    }

    /// Validates the table, recording problems under `peg.<field>`.
    pub fn check_into(&self, c: &mut Checker) {
        c.positive("peg.hole_diameter", self.hole_diameter);
        c.positive("peg.peg_diameter", self.peg_diameter);
        c.positive("peg.height", self.height);
        c.positive("peg.mass", self.mass);
        // Every reported column is a reaction divided by m g: without
        // gravity there is no force scale to report in.
        if self.gravity.is_finite() && self.gravity <= 0.0 {
            c.push(SceneError::invalid(
                "peg.gravity",
                self.gravity,
                "must be > 0: fig9 reports every reaction divided by m g, which is zero without gravity",
            ));
        } else {
            c.finite("peg.gravity", self.gravity);
        }
        c.non_negative("peg.friction", self.friction);
        check_peg(c, self);
        if self.peg_diameter >= self.hole_diameter {
            c.push(SceneError::invalid(
                "peg.peg_diameter",
                self.peg_diameter,
                format!(
                    "must be smaller than peg.hole_diameter = {}",
                    self.hole_diameter
                ),
            ));
        }
    }
}

/// Largest rim speed of a rotation, m/s: a fifth of the elastic wave
/// speed in steel, where a rigid body is still a fair model.
pub const MAX_RIM_SPEED: f64 = 1e3;

/// Largest acceleration an applied load may give the peg, m/s² (10⁴ g).
pub const MAX_LOAD_ACCELERATION: f64 = 1e5;

const WHY_LENGTH: &str = "engineering sizes (micro-assembly to a kilometre); outside, the model's products of lengths, \
     masses and rates leave f64's range";

/// `peg.hole_diameter`.
pub const HOLE_DIAMETER: FieldRange =
    FieldRange::new("peg.hole_diameter", 1e-6, 1e3, "m", WHY_LENGTH);
/// `peg.peg_diameter`.
pub const PEG_DIAMETER: FieldRange =
    FieldRange::new("peg.peg_diameter", 1e-6, 1e3, "m", WHY_LENGTH);
/// `peg.height`.
pub const HEIGHT: FieldRange = FieldRange::new("peg.height", 1e-6, 1e3, "m", WHY_LENGTH);
/// `peg.mass`.
pub const MASS: FieldRange = FieldRange::new(
    "peg.mass",
    1e-9,
    1e6,
    "kg",
    "a microgram to a thousand tonnes; outside, the reactions m g and m psidot^2 D leave f64's range",
);
/// `peg.gravity`.
pub const GRAVITY: FieldRange = FieldRange::new(
    "peg.gravity",
    0.0,
    1e3,
    "m/s^2",
    "none to 100 g; more would deform the peg at its contacts (the model is rigid)",
);
/// `peg.friction`.
pub const FRICTION: FieldRange = FieldRange::new(
    "peg.friction",
    0.0,
    10.0,
    "",
    "Coulomb coefficients of material pairs lie below about 1.5; above 10 the three-point \
     sliding solution has no physical meaning",
);

/// The `[peg]` table shared by `fig9` and `align_forward`.
pub const PEG: &[FieldRange] = &[HOLE_DIAMETER, PEG_DIAMETER, HEIGHT, MASS, GRAVITY, FRICTION];

/// `initial.psidot` (bound shown for D = 1 m; the check uses the scene's D).
pub const PSIDOT: FieldRange = FieldRange::new(
    "initial.psidot",
    -2.0 * MAX_RIM_SPEED,
    2.0 * MAX_RIM_SPEED,
    "1/s",
    "rim speed |psidot| D/2 at most 1e3 m/s",
);
/// `initial.gammadot` (bound shown for H = 1 m; the check uses the scene's H).
pub const GAMMADOT: FieldRange = FieldRange::new(
    "initial.gammadot",
    -MAX_RIM_SPEED,
    MAX_RIM_SPEED,
    "1/s",
    "rim speed |gammadot| H at most 1e3 m/s",
);

/// The rates of `align_forward` (their limits scale with the peg).
pub const ALIGN_FORWARD: &[FieldRange] = &[PSIDOT, GAMMADOT];

/// Records every range violation of the `[peg]` table.
pub fn check_peg(c: &mut Checker, peg: &PegTable) {
    for (r, v) in PEG.iter().zip([
        peg.hole_diameter,
        peg.peg_diameter,
        peg.height,
        peg.mass,
        peg.gravity,
        peg.friction,
    ]) {
        r.check(c, v);
    }
    let (dh, dp) = (peg.hole_diameter, peg.peg_diameter);
    let ratio = (dh - dp) / dh;
    if ratio.is_finite() && ratio > 0.0 && ratio < MIN_CLEARANCE_RATIO {
        c.push(SceneError::invalid(
            "peg.peg_diameter",
            dp,
            format!(
                "the clearance ratio (D - d)/D = {ratio:.3e} is below {MIN_CLEARANCE_RATIO:e}: f64 \
                 does not resolve the clearance D - d (nor gamma0 = arccos(d/D)) to seven digits"
            ),
        ));
    }
}

/// Records a rate `rate` (1/s) of field `name` whose rim speed
/// `|rate| · radius` exceeds [`MAX_RIM_SPEED`]; `radius_name` says which
/// length the radius is (e.g. `D/2`).
pub fn check_rate(c: &mut Checker, name: &str, rate: f64, radius: f64, radius_name: &str) {
    let speed = rate.abs() * radius;
    if rate.is_finite() && radius.is_finite() && radius > 0.0 && speed > MAX_RIM_SPEED {
        c.push(SceneError::invalid(
            name,
            rate,
            format!(
                "the rim speed |{}| {radius_name} = {speed:.3e} m/s exceeds {MAX_RIM_SPEED:e} m/s: \
                 the rigid-body model needs speeds far below the elastic wave speed of the peg \
                 (about 5000 m/s in steel); limit {:.3e} 1/s for this peg",
                name.rsplit('.').next().unwrap_or(name),
                MAX_RIM_SPEED / radius
            ),
        ));
    }
}

/// Records a load `value` of field `name` whose acceleration
/// `|value| / per_kg` (`per_kg` = m for a force, m times a lever for a
/// moment) exceeds [`MAX_LOAD_ACCELERATION`].
pub fn check_load(c: &mut Checker, name: &str, value: f64, per_kg: f64, unit: &str) {
    let acc = value.abs() / per_kg;
    if value.is_finite() && per_kg.is_finite() && per_kg > 0.0 && acc > MAX_LOAD_ACCELERATION {
        c.push(SceneError::invalid(
            name,
            value,
            format!(
                "gives the peg an acceleration of {acc:.3e} m/s^2, above {MAX_LOAD_ACCELERATION:e} \
                 m/s^2 (1e4 g) where a real peg yields at its contacts (the model is rigid); \
                 limit {:.3e} {unit} for this peg",
                MAX_LOAD_ACCELERATION * per_kg
            ),
        ));
    }
}
