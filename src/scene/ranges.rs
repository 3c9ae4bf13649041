//! Valid ranges of scene fields that follow from the models' assumptions,
//! beyond "finite" and "positive" (see `docs/scenes.md`, "Valid ranges").
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

//!
//! Each kind declares the ranges of its fields as [`FieldRange`] constants
//! (in `src/scene/ranges/<kind>.rs` for the built-in kinds), checks them in
//! its validation with [`FieldRange::check`], and lists them in [`ALL`] so
//! that `docs/scenes.md` is checked to document every one.

pub mod design_margins;
pub mod jamming;
pub mod pendulum;
pub mod rigid;

use crate::error::SceneError;
use crate::scene::validate::Checker;

/// The documented valid range of one scene field: the closed interval
/// `[min, max]` in `unit`, and why the model needs it. Non-finite values
/// are left to the finiteness checks, which every field has.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldRange {
    /// Dotted path of the field in the scene file, e.g. `peg.height`.
    pub field: &'static str,
    /// Smallest valid value.
    pub min: f64,
    /// Largest valid value.
    pub max: f64,
    /// Unit of the bounds (empty for a ratio).
    pub unit: &'static str,
    /// Why the model needs the range (shown in the refusal).
    pub why: &'static str,
}

impl FieldRange {
    /// A range `[min, max]` of `field` in `unit`, with its reason.
    pub const fn new(
        field: &'static str,
        min: f64,
        max: f64,
        unit: &'static str,
        why: &'static str,
    ) -> Self {
        FieldRange {
            field,
            min,
            max,
            unit,
            why,
        }
    }

    /// Whether `v` is finite and inside the range.
    pub fn contains(&self, v: f64) -> bool {
        v.is_finite() && (self.min..=self.max).contains(&v)
    }

    /// Records in `c` a finite `v` outside the range, naming the field,
    /// the value, the limits and why.
    pub fn check(&self, c: &mut Checker, v: f64) {
        self.check_as(c, self.field, v);
    }

    /// As [`FieldRange::check`] under another name, e.g. an element
    /// `motion.psidot[1]` of a list whose range is `motion.psidot`.
    /// A field that already has a recorded problem (e.g. "must be > 0")
    /// is not reported twice.
    pub fn check_as(&self, c: &mut Checker, name: &str, v: f64) {
        if v.is_finite() && !self.contains(v) && !c.has_error(name) {
            let unit = if self.unit.is_empty() {
                String::new()
            } else {
                format!(" {}", self.unit)
            };
            // Zero reads as `0`, not `0e0`.
            let limit = |x: f64| {
                if x == 0.0 {
                    "0".to_owned()
                } else {
                    format!("{x:e}")
                }
            };
            c.push(SceneError::invalid(
                name,
                v,
                format!(
                    "must lie in [{}, {}]{unit}: {}",
                    limit(self.min),
                    limit(self.max),
                    self.why
                ),
            ));
        }
    }
}

/// Every kind's declared field ranges, by kind name (`docs/scenes.md`
/// documents each; a test checks it). A new kind appends its row.
pub const ALL: &[(&str, &[FieldRange])] = &[
    ("fig9", rigid::PEG),
    ("align_forward", rigid::PEG),
    ("align_forward", rigid::ALIGN_FORWARD),
    ("pendulum", pendulum::PENDULUM),
    ("double_pendulum", pendulum::DOUBLE_PENDULUM),
    ("jamming", jamming::JAMMING),
    ("jamming", jamming::SWEEP),
    ("design_margins", design_margins::GRID),
];

/// Largest contact radius, as a fraction of the fillet radius, at which
/// Hertz's half-space assumption is still accepted.
pub const MAX_CONTACT_OVER_RADIUS: f64 = 0.3;

/// Smallest clearance ratio `c = (D − 2r)/D` whose gap f64 resolves to
/// seven digits (`ε / c ≤ 2.2e-7`).
pub const MIN_CLEARANCE_RATIO: f64 = 1e-9;

/// Softest material accepted, Pa (soft polymer foams are about `1e4` Pa).
pub const MIN_YOUNGS_MODULUS: f64 = 1e3;

/// Stiffest material accepted, Pa (diamond is about `1.2e12` Pa).
pub const MAX_YOUNGS_MODULUS: f64 = 1e13;

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
                     {:e} N and E* = {e_star:e} Pa the contact radius would be {ratio:.3e} times the \
                     fillet radius (limit {MAX_CONTACT_OVER_RADIUS}); use a larger fillet, a stiffer \
                     material or a smaller load",
                    f.load
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_field_already_refused_is_not_refused_twice() {
        let range = FieldRange::new("pendulum.length", 1e-6, 1e6, "m", "test");
        let mut c = Checker::default();
        c.positive("pendulum.length", -1.0);
        range.check(&mut c, -1.0);
        range.check_as(&mut c, "pendulum.mass", -1.0);
        let e = c.finish().unwrap_err();
        let fields: Vec<_> = e.errors.iter().map(|l| l.error.field()).collect();
        assert_eq!(fields, [Some("pendulum.length"), Some("pendulum.mass")]);
    }

    fn shipped() -> CompliantFields {
        CompliantFields {
            hole_diameter: 0.05,
            clearance_ratio: 0.002,
            peg_length: 0.1,
            peg_fillet: 2e-4,
            hole_fillet: 2e-4,
            youngs_modulus: [210e9, 210e9],
            poisson_ratio: [0.3, 0.3],
            load: 5.0 + 0.002 / 0.025,
            initial_depth: 0.0,
            target_depth: 0.03,
        }
    }

    fn errors(f: &CompliantFields) -> String {
        let mut c = Checker::default();
        check_compliant(&mut c, "insert_compliant", f);
        c.finish().err().map(|e| e.to_string()).unwrap_or_default()
    }

    #[test]
    fn every_declared_range_is_documented_and_sound() {
        let doc = include_str!("../../docs/scenes.md");
        for (kind, ranges) in ALL {
            for r in *ranges {
                assert!(r.min < r.max && !r.why.is_empty(), "{kind} {}", r.field);
                let last = r.field.rsplit('.').next().unwrap_or(r.field);
                assert!(
                    doc.contains(&format!("`{}`", r.field)) || doc.contains(&format!("`{last}`")),
                    "docs/scenes.md does not document {kind} {}",
                    r.field
                );
            }
        }
    }

    #[test]
    fn a_range_names_field_value_limits_and_reason() {
        let r = FieldRange::new("peg.height", 1e-6, 1e3, "m", "a reason");
        let mut c = Checker::default();
        r.check(&mut c, 7.7e-154);
        r.check(&mut c, 0.07);
        r.check(&mut c, f64::NAN);
        r.check_as(&mut c, "peg.height[1]", 2e3);
        let e = c.finish().unwrap_err();
        assert_eq!(e.errors.len(), 2);
        let text = e.to_string();
        assert!(text.contains("peg.height` = 7.7e-154"), "{text}");
        assert!(text.contains("[1e-6, 1e3] m: a reason"), "{text}");
        assert!(text.contains("peg.height[1]` = 2000.0"), "{text}");
    }

    #[test]
    fn the_shipped_scene_is_in_range() {
        assert_eq!(errors(&shipped()), "");
    }

    #[test]
    fn hostile_values_are_refused_with_their_own_value() {
        let e = errors(&CompliantFields {
            peg_fillet: 1e-200,
            ..shipped()
        });
        assert!(
            e.contains("insert_compliant.peg_fillet") && e.contains("1e-200"),
            "{e}"
        );
        let e = errors(&CompliantFields {
            youngs_modulus: [1e-30, 210e9],
            ..shipped()
        });
        assert!(
            e.contains("peg_material.youngs_modulus") && e.contains("1e-30"),
            "{e}"
        );
        let e = errors(&CompliantFields {
            clearance_ratio: 0.0,
            ..shipped()
        });
        assert!(e.contains("clearance_ratio` = 0.0"), "{e}");
        let e = errors(&CompliantFields {
            clearance_ratio: 1e-15,
            ..shipped()
        });
        assert!(e.contains("clearance_ratio` = 1e-15"), "{e}");
        let e = errors(&CompliantFields {
            target_depth: 0.2,
            ..shipped()
        });
        assert!(
            e.contains("target_depth` = 0.2") && e.contains("peg_length"),
            "{e}"
        );
    }
}
