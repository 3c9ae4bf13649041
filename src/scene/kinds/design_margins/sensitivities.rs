//! The `[sensitivities]` table of a `design_margins` scene: the
//! derivatives of the chamfer's capture widths with respect to the scene
//! fields that set them, exact and without a run (the generated parameter
//! Jacobian of [`super::chamfer_sensitivity`], chained through the
//! scene's translation `R = D/2`, `r = D (1 − c)/2`):
//!
//! ```text
//! ∂W/∂D = ½ ∂W/∂R + ½ (1 − c) ∂W/∂r,   ∂W/∂c = −½ D ∂W/∂r,
//! ∂W/∂ρ_p, ∂W/∂ρ_h, ∂W/∂μ as generated,   ∂W/∂L_c = 0
//! ```
//!
//! for `W` each of `W_μ` (`capture_width_m`), `W_0 = R + ρ_h`
//! (`frictionless_capture_width_m`) and the largest aligned tip error
//! `W_μ − (r − ρ_p)` (`aligned_tip_error_m`). The compliance centre's
//! height does not enter them (it moves the tip's error, not the band an
//! aligned peg is captured in): named, it is a zero flagged as not used.
//!
//! ```toml
//! [sensitivities]
//! parameters = ["peg.mouth_fillet", "peg.rim_fillet", "peg.friction"]
//! ```
//!
//! Written as the other kinds' tables are
//! ([`crate::scene::shared::sensitivities::output`]): `<scene>.sensitivities.csv`,
//! the tornado plot and the ranking in the summary.

use serde::Deserialize;

use super::chamfer::Capture;
use super::chamfer_sensitivity::CaptureGradient;
use crate::error::SceneErrors;
use crate::scene::shared::sensitivities::{self, Measured, Row, choose};

/// The fields a `design_margins` `[sensitivities]` table may name, in
/// slot order.
pub const FIELDS: [&str; 6] = [
    "peg.hole_diameter",
    "peg.clearance_ratio",
    "peg.rim_fillet",
    "peg.mouth_fillet",
    "peg.friction",
    "wrist.centre_height",
];

/// The metrics, in output order.
pub const METRICS: [&str; 3] = [
    "capture_width_m",
    "frictionless_capture_width_m",
    "aligned_tip_error_m",
];

/// The fields that move none of the widths ([`FIELDS`] order).
const UNUSED: [bool; 6] = [false, false, false, false, false, true];

/// The `[sensitivities]` table of a `design_margins` scene (no
/// `error_control`: nothing is integrated).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaptureSensitivitiesTable {
    /// The scene fields, by their names ([`FIELDS`]).
    pub parameters: Vec<String>,
}

impl CaptureSensitivitiesTable {
    /// The chosen fields' slots in [`FIELDS`].
    ///
    /// # Errors
    /// An empty list, an unknown name (with the valid ones) or a name
    /// given twice, naming `sensitivities.parameters`.
    pub fn chosen(&self) -> Result<Vec<usize>, SceneErrors> {
        let (chosen, errors) = choose(&self.parameters, &FIELDS);
        if errors.is_empty() {
            Ok(chosen)
        } else {
            Err(SceneErrors::new(errors))
        }
    }
}

/// The scene's values of [`FIELDS`] that the widths depend on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CaptureFields {
    /// `peg.hole_diameter`, `D` (m).
    pub hole_diameter: f64,
    /// `peg.clearance_ratio`, `c = (D − d)/D`.
    pub clearance_ratio: f64,
}

impl CaptureGradient {
    /// The derivatives along [`FIELDS`] of a width whose derivatives along
    /// the capture geometry are `self`, at the scene's `D` and `c`.
    #[must_use]
    pub fn along_fields(&self, f: CaptureFields) -> [f64; 6] {
        let (d, c) = (f.hole_diameter, f.clearance_ratio);
        [
            0.5 * self.bore_radius + 0.5 * (1.0 - c) * self.peg_radius,
            -0.5 * d * self.peg_radius,
            self.rim_fillet,
            self.mouth_fillet,
            self.friction,
            0.0,
        ]
    }
}

/// The rows of the `chosen` fields for `capture` and the scene's `fields`.
#[must_use]
pub fn rows(capture: &Capture, fields: CaptureFields, chosen: &[usize]) -> Vec<Row> {
    let s = capture.sensitivities();
    let values = [
        fields.hole_diameter,
        fields.clearance_ratio,
        capture.rim_fillet,
        capture.mouth_fillet,
        capture.friction,
        capture.centre_height,
    ];
    let metrics: Vec<Measured> = [
        (METRICS[0], capture.width(), s.width),
        (
            METRICS[1],
            capture.frictionless_width(),
            s.frictionless_width,
        ),
        (METRICS[2], capture.aligned_tip_error(), s.aligned_tip_error),
    ]
    .into_iter()
    .map(|(name, value, gradient)| Measured {
        name,
        value: Some(value),
        derivative: gradient.along_fields(fields).to_vec(),
        flag: Box::new(|_| None),
    })
    .collect();
    sensitivities::rows(&metrics, chosen, &UNUSED, &values, &FIELDS)
}
