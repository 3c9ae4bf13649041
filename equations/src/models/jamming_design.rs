//! The quasi-static design quantities of a peg in two-point contact as
//! expression trees, so that the generator differentiates them with respect
//! to the geometry and the friction (their parameter Jacobians,
//! `pegdyn::jamming::sensitivities`).
//!
//! Parameters p = (r, c, μ, l): the peg radius r (m), the clearance ratio
//! c = (D − d)/D, the friction coefficient μ and the insertion depth l (m),
//! with d = 2r and D = d/(1 − c) (Whitney, "Quasi-static assembly of
//! compliantly supported rigid parts", 1982; the runtime forms are in
//! `pegdyn::jamming`).
//!
//! - Whitney's small-angle parallelogram: edge-only corner
//!   P₁ = (1/μ, 1 + 2λ), mirrored corner Q = (1/μ, 1), λ = l/(2rμ); the
//!   two-point line M/(rF_z) = μ(1 + λ) F_x/F_z + λ.
//! - The exact parallelogram at the exact two-point tilt
//!   θ = atan2(l, d) − atan2(√(ρ² − D²), D), ρ = √(l² + d²):
//!   P₁ = (k1/k2, (l + μr)/(r k2)), P₂ = (−1/μ, −k2/μ), slope
//!   s = (P₁ᵧ − P₂ᵧ)/(P₁ₓ − P₂ₓ), Q = (P₁ₓ, −P₁ᵧ + 2 s P₁ₓ),
//!   k1 = cos θ − μ sin θ, k2 = sin θ + μ cos θ.
//! - The wedging angle θ_c = atan μ − acos(D/(d √(1 + μ²))) (exact), its
//!   two-term series c/μ + (1 + 2μ²)c²/(2μ³) and Whitney's c/μ.

use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};
use crate::expr::Expr;
use crate::model::Output;

/// The generated module's name.
pub const NAME: &str = "jamming_design";

type Corner<'g> = [Expr<'g>; 2];

const EDGE: &str = "edge-only corner P₁ = (F_x/F_z, M/(r F_z)) of the reference two-point line";
const MIRRORED: &str = "corner Q = (F_x/F_z, M/(r F_z)) where the mirrored two-point line \
                        meets the edge cone limit through P₁";
const SLOPE: &str = "slope of the reference two-point line M/(r F_z) against F_x/F_z";
const INTERCEPT: &str = "intercept of the reference two-point line at F_x/F_z = 0";

/// The corners, slope and intercept of a parallelogram whose reference
/// two-point line runs from `p2` to `p1` (`pegdyn::jamming::diagram`).
fn corner_outputs<'g>(
    p1: Corner<'g>,
    slope: Expr<'g>,
) -> Vec<(&'static str, &'static str, Output)> {
    let q = [p1[0], -p1[1] + 2.0 * slope * p1[0]];
    vec![
        ("edge_corner", EDGE, Output::vector(&p1)),
        ("mirrored_corner", MIRRORED, Output::vector(&q)),
        ("slope", SLOPE, Output::scalar(slope)),
        (
            "intercept",
            INTERCEPT,
            Output::scalar(p1[1] - slope * p1[0]),
        ),
    ]
}

/// Declares `jamming_design`: `whitney_diagram(p)`, `exact_diagram(p)` and
/// `wedging(p)`, each with its parameter Jacobian (`<function>_p`).
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    b.doc(
        "Quasi-static design quantities of a peg in two-point contact (Whitney, *Quasi-static \
         assembly of compliantly supported rigid parts*): the corners of the jamming \
         parallelogram, Whitney's and exact, and the wedging angle, as functions of \
         p = (r m, c, mu, l m) for their parameter Jacobians.",
    );
    b.outputs(Outputs::NONE);
    let g = b.g();
    let r = b.parameter("r", "peg radius r, m")?;
    let c = b.parameter("c", "clearance ratio c = (D − d)/D, dimensionless")?;
    let mu = b.parameter("mu", "Coulomb friction coefficient μ, dimensionless")?;
    let l = b.parameter(
        "l",
        "insertion depth l along the peg's axis from the tip face to the edge contact, m",
    )?;
    let one = g.constant(1.0);
    let d = 2.0 * r;
    let big_d = d / (1.0 - c);

    // Whitney's small-angle parallelogram.
    let lam = l / (2.0 * r * mu);
    let whitney_p1 = [one / mu, 1.0 + 2.0 * lam];
    b.function(
        "whitney_diagram",
        "Whitney's small-angle jamming parallelogram: corners P₁ = (1/μ, 1 + 2λ) and \
         Q = (1/μ, 1) (the others are −P₁, −Q), slope μ(1 + λ) and intercept λ of the \
         two-point line, λ = l/(2rμ).",
        &[],
        corner_outputs(whitney_p1, mu * (1.0 + lam)),
    )?;

    // The exact finite-angle parallelogram at the exact two-point tilt.
    let rho = l.hypot(d);
    let lift = ((rho - big_d) * (rho + big_d)).sqrt();
    let theta = l.atan2(d) - lift.atan2(big_d);
    let (s, co) = (theta.sin(), theta.cos());
    let k1 = co - mu * s;
    let k2 = s + mu * co;
    let p1 = [k1 / k2, (l + mu * r) / (r * k2)];
    let p2 = [-(one / mu), -(k2 / mu)];
    let slope = (p1[1] - p2[1]) / (p1[0] - p2[0]);
    let mut exact = vec![(
        "tilt",
        "exact two-point tilt θ, the small root of l sin θ + d cos θ = D, rad",
        Output::scalar(theta),
    )];
    exact.extend(corner_outputs(p1, slope));
    b.function(
        "exact_diagram",
        "The exact finite-angle jamming parallelogram at the exact two-point tilt θ \
         (defined for l ≥ √(D² − d²)): corners P₁ = (k1/k2, (l + μr)/(r k2)) and \
         Q = (P₁ₓ, −P₁ᵧ + 2 s P₁ₓ) (the others are −P₁, −Q), slope s and intercept of the \
         two-point line through P₂ = (−1/μ, −k2/μ) and P₁.",
        &[],
        exact,
    )?;

    // Wedging.
    let x = big_d / (d * mu.hypot(one));
    let acos_x = ((1.0 - x) * (1.0 + x)).sqrt().atan2(x);
    let mu3 = mu.powi(3);
    b.function(
        "wedging",
        "The critical wedging tilt θ_c = atan μ − acos(D/(d √(1 + μ²))) (rad, defined when \
         D ≤ d √(1 + μ²)), its series c/μ + (1 + 2μ²) c²/(2μ³) and Whitney's c/μ.",
        &[],
        vec![
            (
                "exact",
                "critical wedging tilt θ_c, rad",
                Output::scalar(mu.atan() - acos_x),
            ),
            (
                "series",
                "two-term small-clearance series of θ_c, rad",
                Output::scalar(c / mu + (1.0 + 2.0 * mu * mu) * c * c / (2.0 * mu3)),
            ),
            (
                "whitney",
                "Whitney's small-clearance wedging angle c/μ, rad",
                Output::scalar(c / mu),
            ),
        ],
    )?;
    for f in ["whitney_diagram", "exact_diagram", "wedging"] {
        b.parameter_jacobian(f)?;
    }
    Ok(())
}
