//! Hertz's elliptical contact (the compliant-contact paper's (9)–(13)) as expression trees.
//!
//! The ellipticity solve is iterative and runs once at scene setup
//! (`pegdyn::hertz`); these trees take its results — the coefficients
//! `m_a, m_b`, the approach coefficient `δ*` (the paper's `K`), the curvature
//! sum `Σρ` and the contact modulus `E*` — as parameters and give the
//! load-dependent quantities. Units: N, m, Pa, 1/m.

use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};
use crate::expr::Expr;
use crate::graph::Graph;
use crate::model::Output;
use std::f64::consts::PI;

/// The load-independent data of one Hertz contact, as expressions
/// (normally parameters).
#[derive(Clone, Copy, Debug)]
pub struct HertzCoefficients<'g> {
    /// `Σρ`, the sum of the principal curvatures (1/m), (7).
    pub sum_curvature: Expr<'g>,
    /// `E* = [Σ (1 − νᵢ²)/Eᵢ]⁻¹` (Pa).
    pub contact_modulus: Expr<'g>,
    /// `m_a` of (9).
    pub m_a: Expr<'g>,
    /// `m_b` of (10).
    pub m_b: Expr<'g>,
    /// `δ*`, the paper's `K` of (13).
    pub delta_star: Expr<'g>,
}

impl<'g> HertzCoefficients<'g> {
    /// The coefficients as parameters named `<prefix>_sum`, `<prefix>_ma`,
    /// `<prefix>_mb`, `<prefix>_dstar`, and the shared `e_star`.
    pub fn params(g: &'g Graph, prefix: &str) -> HertzCoefficients<'g> {
        HertzCoefficients {
            sum_curvature: g.param(&format!("{prefix}_sum")),
            contact_modulus: g.param("e_star"),
            m_a: g.param(&format!("{prefix}_ma")),
            m_b: g.param(&format!("{prefix}_mb")),
            delta_star: g.param(&format!("{prefix}_dstar")),
        }
    }
}

/// Ellipse, pressure and approach at a load `q ≥ 0`, as expressions.
#[derive(Clone, Copy, Debug)]
pub struct HertzState<'g> {
    /// Semi-major axis `a` (m), (9).
    pub a: Expr<'g>,
    /// Semi-minor axis `b` (m), (10).
    pub b: Expr<'g>,
    /// Maximum pressure `p₀` (Pa), (11).
    pub p0: Expr<'g>,
    /// Approach `δ` (m), (13).
    pub delta: Expr<'g>,
}

/// The paper's (9)–(11) and (13) at load `q` (which must be `≥ 0`, e.g. a
/// `max0` contact force).
///
/// `p₀ = 3Q/(2πab)` is written as `s Σρ E* / (π m_a m_b)` with
/// `s = (3Q/(2ΣρE*))^{1/3}` the scale of `a` and `b` (so
/// `s ΣρE* = (1.5 Q)^{1/3} (Σρ E*)^{2/3}`): the same quantity, finite (zero)
/// at `Q = 0`, and one cube root for `a`, `b` and `p₀` together.
pub fn state<'g>(q: Expr<'g>, c: &HertzCoefficients<'g>) -> HertzState<'g> {
    let third = 1.0 / 3.0;
    let se = c.sum_curvature * c.contact_modulus;
    let scale = (1.5 * q / se).powf(third);
    let p0 = scale * se / (PI * c.m_a * c.m_b);
    let comp = 1.5 / c.contact_modulus;
    let delta = c.delta_star * (0.125 * comp.square() * q.square() * c.sum_curvature).powf(third);
    HertzState {
        a: c.m_a * scale,
        b: c.m_b * scale,
        p0,
        delta,
    }
}

/// The stiffness `k = (2E*/3) √(8/(δ*³ Σρ))` of `Q = k δ^{3/2}` ((13) inverted).
pub fn stiffness<'g>(c: &HertzCoefficients<'g>) -> Expr<'g> {
    (2.0 / 3.0) * c.contact_modulus * (8.0 / (c.delta_star.powi(3) * c.sum_curvature)).sqrt()
}

/// The load `Q = k max(δ, 0)^{3/2}` at approach `delta` for stiffness `k`.
pub fn load<'g>(k: Expr<'g>, delta: Expr<'g>) -> Expr<'g> {
    k * delta.max0().powf(1.5)
}

/// The elastic energy `∫₀^δ Q dξ = (2/5) k max(δ, 0)^{5/2}` (the paper's
/// (62)); its derivative in `δ` is [`load`].
pub fn potential<'g>(k: Expr<'g>, delta: Expr<'g>) -> Expr<'g> {
    0.4 * k * delta.max0().powf(2.5)
}

/// Declares the `hertz` model: the load-dependent Hertz quantities
/// (`ellipse`, `stiffness`) from the setup-time coefficients
/// `c = (c_sum, e_star, c_ma, c_mb, c_dstar)`.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    b.doc(
        "Hertz elliptical contact (*Dynamic analysis for peg-in-hole assembly with contact deformation*, (9)-(13)) from setup-time coefficients \
         c = (sum of curvatures 1/m, contact modulus Pa, m_a, m_b, delta_star). SI units.",
    );
    b.outputs(Outputs::NONE);
    b.parameters_named("c")?;
    let c = HertzCoefficients {
        sum_curvature: b.parameter(
            "c_sum",
            "sum of the principal curvatures Σρ of the two bodies, 1/m",
        )?,
        contact_modulus: b.parameter("e_star", "contact modulus E* = [Σ (1 − νᵢ²)/Eᵢ]⁻¹, Pa")?,
        m_a: b.parameter(
            "c_ma",
            "ellipse coefficient m_a of the semi-major axis (9), dimensionless",
        )?,
        m_b: b.parameter(
            "c_mb",
            "ellipse coefficient m_b of the semi-minor axis (10), dimensionless",
        )?,
        delta_star: b.parameter(
            "c_dstar",
            "approach coefficient δ* (the paper's K of (13)), dimensionless",
        )?,
    };
    let q = b.symbol(
        "load",
        "normal load Q on the contact, N (negative counts as 0)",
    )?;
    // A negative load (no contact) gives the zero ellipse, not NaN.
    let s = state(q.max0(), &c);
    let coeffs = b.parameters();
    b.function(
        "ellipse",
        "Semi-axes a, b (m) (9)-(10), maximum pressure p0 (Pa) (11) and approach delta (m) (13) \
         at load Q (N); negative loads count as 0.",
        &[("load", &[q]), ("c", &coeffs)],
        vec![
            (
                "a",
                "semi-major axis a of the contact ellipse (9), m",
                Output::scalar(s.a),
            ),
            (
                "b",
                "semi-minor axis b of the contact ellipse (10), m",
                Output::scalar(s.b),
            ),
            (
                "p0",
                "maximum contact pressure p₀ (11), Pa",
                Output::scalar(s.p0),
            ),
            (
                "delta",
                "approach δ of the two bodies (13), m",
                Output::scalar(s.delta),
            ),
        ],
    )?;
    b.function(
        "stiffness",
        "Stiffness k (N/m^1.5) of Q = k delta^1.5 ((13) inverted).",
        &[("c", &coeffs)],
        vec![(
            "k",
            "stiffness k of Q = k δ^{3/2}, N/m^1.5",
            Output::scalar(stiffness(&c)),
        )],
    )
}
