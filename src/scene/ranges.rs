//! Declared valid ranges of scene fields ([`FieldRange`]), from the
//! models' assumptions beyond "finite" and "positive" (see
//! `docs/scenes.md`, "Valid ranges"), and the physical limits several
//! kinds share.
//!
//! Each kind declares the ranges of its fields as [`FieldRange`] constants
//! (beside the kind, or beside a table several kinds share in
//! `crate::scene::shared`), checks them in its validation with
//! [`FieldRange::check`] or [`FieldRange::require`], and lists them in its
//! registry entry (`Kind::ranges`), so that `docs/scenes.md` is checked to
//! document every one.

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

    /// The same field, unit and reason with the bounds narrowed to
    /// `[max(min, lo), min(max, hi)]`: a range that depends on other fields
    /// of the scene (e.g. a fillet of at most half the peg radius), shown
    /// with the scene's own bounds when refused. A NaN bound leaves the
    /// declared one.
    #[must_use]
    pub fn within(self, lo: f64, hi: f64) -> FieldRange {
        FieldRange {
            min: self.min.max(lo),
            max: self.max.min(hi),
            ..self
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

    /// Records in `c` a non-finite `v` ("must be a finite number") or one
    /// outside the range, as [`FieldRange::check`]; returns `v`, so that a
    /// checked value can be used inline.
    pub fn require(&self, c: &mut Checker, v: f64) -> f64 {
        c.finite(self.field, v);
        self.check(c, v);
        v
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
            // Zero reads as `0`, not `0e0`; a bound computed from other
            // fields (`within`) is shown to six digits, not with the
            // rounding noise of its computation.
            let limit = |x: f64| {
                if x == 0.0 {
                    "0".to_owned()
                } else {
                    let x: f64 = format!("{x:.5e}").parse().unwrap_or(x);
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

/// Why Hunt–Crossley contact damping is bounded (the jamming sweep's and
/// the compliant 3-D peg's `contact_damping`).
pub const WHY_CONTACT_DAMPING: &str = "Hunt-Crossley alpha: 0 is elastic; at 1e3 s/m a contact closing at 0.25 mm/s already loses a third of its impact energy (1 - e^2 = 4 alpha v / 3)";
