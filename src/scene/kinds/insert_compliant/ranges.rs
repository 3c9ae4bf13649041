//! The ranges of the `insert_compliant` kind's fields that depend on each
//! other (the compliant planar peg):
//!
//! - Hertz contact theory needs the contact small against the radii of
//!   curvature: at the applied load the contact radius of the sharper
//!   fillet, `a = (3 F R / (4 E*))^{1/3}`, must stay below
//!   [`MAX_CONTACT_OVER_RADIUS`] times that radius `R`.
//! - The radial gap `c D` of a clearance ratio `c` is the difference of two
//!   nearly equal lengths; below [`MIN_CLEARANCE_RATIO`] its f64 rounding
//!   error exceeds `1e-7` of the gap and the geometry loses its digits.
//! - Depths are measured along the peg: a depth at or beyond the peg's
//!   length would put the peg's top below the hole edge, outside the model.
//! - Young's moduli lie between [`MIN_YOUNGS_MODULUS`] (soft foams) and
//!   [`MAX_YOUNGS_MODULUS`] (ten times diamond).

use crate::error::SceneError;
use crate::scene::numbers::significant;
use crate::scene::ranges::{
    FieldRange, MAX_CONTACT_OVER_RADIUS, MAX_YOUNGS_MODULUS, MIN_CLEARANCE_RATIO,
    MIN_YOUNGS_MODULUS,
};
use crate::scene::validate::Checker;

const WHY_SIZE: &str = "engineering sizes, a micrometre to a kilometre: the peg's mass and inertia and the contact energies stay far inside f64";

/// `insert_compliant.hole_diameter`.
pub const HOLE_DIAMETER: FieldRange =
    FieldRange::new("insert_compliant.hole_diameter", 1e-6, 1e3, "m", WHY_SIZE);
/// `insert_compliant.peg_length`.
pub const PEG_LENGTH: FieldRange =
    FieldRange::new("insert_compliant.peg_length", 1e-6, 1e3, "m", WHY_SIZE);
/// `insert_compliant.density`.
pub const DENSITY: FieldRange = FieldRange::new(
    "insert_compliant.density",
    1.0,
    1e5,
    "kg/m^3",
    "foams to beyond the densest metals (osmium: 22,600 kg/m^3)",
);

/// The declared ranges of the `[insert_compliant]` table (the others
/// depend on each other: [`check_compliant`]).
pub const INSERT_COMPLIANT: &[FieldRange] = &[HOLE_DIAMETER, PEG_LENGTH, DENSITY];

/// The fields of a compliant peg-in-hole scene whose ranges depend on each
/// other (SI units).
#[derive(Debug, Clone, Copy)]
pub struct CompliantFields {
    /// `D`, m.
    pub hole_diameter: f64,
    /// `c`.
    pub clearance_ratio: f64,
    /// `L`, m.
    pub peg_length: f64,
    /// Peg edge fillet radius, m.
    pub peg_fillet: f64,
    /// Hole edge fillet radius, m.
    pub hole_fillet: f64,
    /// Young's moduli of peg and hole, Pa.
    pub youngs_modulus: [f64; 2],
    /// Poisson's ratios of peg and hole.
    pub poisson_ratio: [f64; 2],
    /// The applied force scale `|f1| + |f2| + |M|/r`, N.
    pub load: f64,
    /// Initial depth, m.
    pub initial_depth: f64,
    /// Target depth, m.
    pub target_depth: f64,
}

/// Records in `c` every range violation of `f`, each naming its field under
/// `table` (e.g. `insert_compliant`).
pub fn check_compliant(c: &mut Checker, table: &str, f: &CompliantFields) {
    let name = |k: &str| format!("{table}.{k}");
    let cr = f.clearance_ratio;
    if cr.is_finite() && !(MIN_CLEARANCE_RATIO..1.0).contains(&cr) {
        c.push(SceneError::invalid(
            name("clearance_ratio"),
            cr,
            format!(
                "must lie in [{MIN_CLEARANCE_RATIO:e}, 1): below {MIN_CLEARANCE_RATIO:e} the radial gap \
                 c D is lost in f64 rounding (and c <= 0 leaves no clearance), at 1 the peg has no radius"
            ),
        ));
    }
    let r = 0.5 * f.hole_diameter * (1.0 - cr);
    for (k, fillet) in [("peg_fillet", f.peg_fillet), ("hole_fillet", f.hole_fillet)] {
        if !(fillet.is_finite() && fillet > 0.0) {
            c.push(SceneError::invalid(
                name(k),
                fillet,
                "must be finite and > 0",
            ));
        } else if r.is_finite() && r > 0.0 && fillet >= r {
            c.push(SceneError::invalid(
                name(k),
                fillet,
                format!("must be smaller than the peg radius r = D (1 - c)/2 = {r:e} m"),
            ));
        }
    }
    let material = ["peg_material", "hole_material"];
    for (i, e) in f.youngs_modulus.iter().enumerate() {
        if e.is_finite() && !(MIN_YOUNGS_MODULUS..=MAX_YOUNGS_MODULUS).contains(e) {
            c.push(SceneError::invalid(
                name(&format!("{}.youngs_modulus", material[i])),
                *e,
                format!(
                    "must lie in [{MIN_YOUNGS_MODULUS:e}, {MAX_YOUNGS_MODULUS:e}] Pa \
                     (soft foams to ten times diamond)"
                ),
            ));
        }
    }
    // Hertz's assumption, a << R, at the applied load.
    let e_star = 1.0
        / f.youngs_modulus
            .iter()
            .zip(f.poisson_ratio)
            .map(|(e, nu)| (1.0 - nu * nu) / e)
            .sum::<f64>();
    let radius = f.peg_fillet.min(f.hole_fillet);
    if e_star.is_finite() && e_star > 0.0 && radius > 0.0 && f.load.is_finite() && f.load > 0.0 {
        let a = (3.0 * f.load * radius / (4.0 * e_star)).cbrt();
        let ratio = a / radius;
        if ratio.is_nan() || ratio > MAX_CONTACT_OVER_RADIUS {
            let field = if f.peg_fillet <= f.hole_fillet {
                "peg_fillet"
            } else {
                "hole_fillet"
            };
            c.push(SceneError::invalid(
                name(field),
                radius,
                format!(
                    "Hertz contact needs the contact small against the fillet: at the applied load \
                     {} N ({t}.axial_force, {t}.radial_force, {t}.torque / r) and E* = {} Pa the \
                     contact radius would be {ratio:.3e} times the fillet radius (limit \
                     {MAX_CONTACT_OVER_RADIUS}); use a larger fillet, a stiffer material or a \
                     smaller load",
                    significant(f.load),
                    significant(e_star),
                    t = table
                ),
            ));
        }
    }
    let len = f.peg_length;
    for (k, depth) in [
        ("initial_depth", f.initial_depth),
        ("target_depth", f.target_depth),
    ] {
        if depth.is_finite() && len.is_finite() && depth >= len {
            c.push(SceneError::invalid(
                name(k),
                depth,
                format!(
                    "must be less than peg_length = {len:e} m: deeper, the peg's top passes the hole \
                     edge and the edge contacts of the model no longer exist"
                ),
            ));
        }
    }
}
