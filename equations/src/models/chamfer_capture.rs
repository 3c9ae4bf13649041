//! The capture widths of a rounded chamfer as expression trees, so that the
//! generator differentiates them with respect to the geometry and the
//! friction (their parameter Jacobian, `Capture::sensitivities` in
//! `pegdyn::scene::kinds::design_margins::chamfer_sensitivity`).
//!
//! Parameters p = (r_peg, r_bore, rho_p, rho_h, mu): peg radius r, bore
//! radius R, rim fillet ρ_p, mouth fillet ρ_h (m) and the friction
//! coefficient μ. The capture rule (derivation in `docs/insertion.md`,
//! "Chamfer acceptance with a compliance centre") accepts an aligned peg
//! whose tube centre lies within
//!
//! ```text
//! W_0 = R + ρ_h                              (frictionless)
//! W_μ = W_0 − (ρ_h + ρ_p) μ/√(1 + μ²)
//! ```
//!
//! of the hole's axis, i.e. a lateral tip error below W_μ − (r − ρ_p).

use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};
use crate::model::Output;

/// The generated module's name.
pub const NAME: &str = "chamfer_capture";

/// Declares `chamfer_capture`: `widths(p)` with its parameter Jacobian
/// (`widths_p`).
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    b.doc(
        "Capture widths of a rounded chamfer for an aligned peg, frictionless and with \
         friction, as functions of p = (r_peg m, r_bore m, rho_p m, rho_h m, mu) for their \
         parameter Jacobian.",
    );
    b.outputs(Outputs::NONE);
    let g = b.g();
    let r = b.parameter("r_peg", "peg radius r, m")?;
    let big_r = b.parameter("r_bore", "bore radius R, m")?;
    let rho_p = b.parameter("rho_p", "rim fillet ρ_p of the peg, m")?;
    let rho_h = b.parameter(
        "rho_h",
        "mouth fillet ρ_h of the hole (the chamfer's width), m",
    )?;
    let mu = b.parameter("mu", "Coulomb friction coefficient μ, dimensionless")?;
    let w0 = big_r + rho_h;
    let w = w0 - (rho_h + rho_p) * mu / mu.hypot(g.constant(1.0));
    b.function(
        "widths",
        "The capture widths W_0 = R + ρ_h and W_μ = W_0 − (ρ_h + ρ_p) μ/√(1 + μ²) (m) of \
         the tube centre's distance from the hole's axis, and the aligned tip error \
         W_μ − (r − ρ_p) (m) the chamfer accepts.",
        &[],
        vec![
            ("frictionless_width", "W_0 = R + ρ_h, m", Output::scalar(w0)),
            (
                "width",
                "W_μ = R + ρ_h − (ρ_h + ρ_p) μ/√(1 + μ²), m",
                Output::scalar(w),
            ),
            (
                "aligned_tip_error",
                "largest lateral tip error of an aligned peg, W_μ − (r − ρ_p), m",
                Output::scalar(w - (r - rho_p)),
            ),
        ],
    )?;
    b.parameter_jacobian("widths")
}
