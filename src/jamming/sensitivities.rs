//! Derivatives of the quasi-static design quantities with respect to the
//! geometry and the friction: the corners of the jamming parallelogram
//! (Whitney's and the exact one, [`super::diagram`]), its two-point line,
//! the exact two-point tilt ([`super::geometry`]) and the wedging angles
//! ([`super::wedging`]), each differentiated with respect to the peg radius
//! r, the clearance ratio c = (D − d)/D, the friction coefficient μ and the
//! insertion depth l.
//!
//! The derivatives are generated symbolically: the generated model
//! `jamming_design` (declared in `equations/src/models/jamming_design.rs`)
//! writes the same quantities as expression trees of p = (r, c, μ, l),
//!
//! ```text
//! Whitney:  P₁ = (1/μ, 1 + 2λ),  Q = (1/μ, 1),  λ = l/(2rμ)
//! exact:    θ = atan2(l, d) − atan2(√(ρ² − D²), D),  ρ = √(l² + d²),  d = 2r,  D = d/(1 − c)
//!           P₁ = (k1/k2, (l + μr)/(r k2)),  P₂ = (−1/μ, −k2/μ),
//!           s = (P₁ᵧ − P₂ᵧ)/(P₁ₓ − P₂ₓ),  Q = (P₁ₓ, −P₁ᵧ + 2 s P₁ₓ)
//! wedging:  θ_c = atan μ − acos(D/(d √(1 + μ²))),  c/μ + (1 + 2μ²)c²/(2μ³),  c/μ
//! ```
//!
//! and the generator emits their parameter Jacobians (`<function>_p`).
//! The parallelogram's other corners are −P₁ and −Q, so their derivatives
//! are the negatives of those of P₁ and Q.
//!
//! ```
//! use pegdyn::jamming::{PegHole, sensitivities::sensitivities};
//! let p = PegHole::try_new(0.0125, 0.01, 0.25).unwrap();
//! let s = sensitivities(&p, 0.01).unwrap();
//! // Whitney's edge corner (1/μ, 1 + l/(rμ)): ∂P₁ᵧ/∂l = 1/(rμ) = 320 per m.
//! assert!((s.whitney.edge_corner.moment_ratio.l - 320.0).abs() < 1e-9);
//! assert!((s.whitney.edge_corner.force_ratio.mu + 16.0).abs() < 1e-12);
//! ```

use super::error::ParamError;
use super::geometry::min_two_point_depth;
use super::params::PegHole;
use crate::generated::jamming_design as generated;
use nalgebra::{SMatrix, SVector};

/// Derivatives of one scalar design quantity q with respect to the design's
/// inputs: `∂q/∂r` (per m), `∂q/∂c`, `∂q/∂μ`, `∂q/∂l` (per m), the others
/// held fixed (with r and c fixed, the hole diameter D = 2r/(1 − c) moves
/// with r).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Gradient {
    /// `∂q/∂r`, the peg radius (per m).
    pub r: f64,
    /// `∂q/∂c`, the clearance ratio.
    pub c: f64,
    /// `∂q/∂μ`, the friction coefficient.
    pub mu: f64,
    /// `∂q/∂l`, the insertion depth (per m).
    pub l: f64,
}

impl Gradient {
    /// From a row of a generated Jacobian, its columns taken by name
    /// through the generated model's parameters.
    fn from_params(g: generated::Params<f64>) -> Gradient {
        Gradient {
            r: g.r,
            c: g.c,
            mu: g.mu,
            l: g.l,
        }
    }

    /// The entries in the order `(r, c, mu, l)` of [`Gradient::NAMES`].
    pub fn to_array(&self) -> [f64; 4] {
        [self.r, self.c, self.mu, self.l]
    }

    /// The inputs' names, in the order of [`Gradient::to_array`].
    pub const NAMES: [&'static str; 4] = ["r", "c", "mu", "l"];
}

/// Derivatives of one point of the diagram, (F_x/F_z, M/(r F_z)).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RatioGradient {
    /// Of the force ratio F_x/F_z.
    pub force_ratio: Gradient,
    /// Of the moment ratio M/(r F_z) (moment about the tip).
    pub moment_ratio: Gradient,
}

impl RatioGradient {
    fn from_matrix(m: &SMatrix<f64, 2, 4>) -> RatioGradient {
        let row = |i: usize| gradient(&m.row(i).transpose());
        RatioGradient {
            force_ratio: row(0),
            moment_ratio: row(1),
        }
    }
}

/// Derivatives of a jamming parallelogram
/// ([`super::diagram::Parallelogram`], corners `[−P₁, Q, P₁, −Q]`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ParallelogramSensitivity {
    /// Of the edge-only corner P₁ (`corners[2]`; `corners[0]` = −P₁).
    pub edge_corner: RatioGradient,
    /// Of the corner Q (`corners[1]`; `corners[3]` = −Q), where the
    /// mirrored two-point line meets the edge cone limit through P₁.
    pub mirrored_corner: RatioGradient,
    /// Of the reference two-point line's slope
    /// ([`super::diagram::Parallelogram::two_point_line`]).
    pub slope: Gradient,
    /// Of that line's intercept.
    pub intercept: Gradient,
    /// Of the exact two-point tilt θ (rad) the corners are computed at
    /// (zero for Whitney's, computed at θ = 0).
    pub tilt: Gradient,
}

/// Derivatives of the wedging angles ([`super::wedging`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WedgingSensitivity {
    /// Of the exact critical tilt θ_c ([`super::wedging::wedging_angle`]);
    /// `None` where it does not exist or its derivative is unbounded
    /// (D ≥ d √(1 + μ²)).
    pub exact: Option<Gradient>,
    /// Of the two-term series ([`super::wedging::wedging_angle_series`]).
    pub series: Gradient,
    /// Of Whitney's c/μ ([`super::wedging::wedging_angle_whitney`]).
    pub whitney: Gradient,
}

/// The derivatives of every quasi-static design quantity at one design and
/// depth.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DesignSensitivities {
    /// Of Whitney's small-angle parallelogram
    /// ([`super::diagram::whitney_parallelogram`]).
    pub whitney: ParallelogramSensitivity,
    /// Of the exact parallelogram
    /// ([`super::diagram::exact_parallelogram`]); `None` where two-point
    /// contact is impossible or its tilt's derivative is unbounded
    /// (l ≤ √(D² − d²)).
    pub exact: Option<ParallelogramSensitivity>,
    /// Of the wedging angles (independent of l).
    pub wedging: WedgingSensitivity,
}

fn gradient(v: &SVector<f64, 4>) -> Gradient {
    Gradient::from_params(generated::Params::from(v))
}

/// The derivatives of the design quantities of `p` at depth `l` (m).
///
/// # Errors
/// [`ParamError`] naming `l` when the depth is not finite and positive.
pub fn sensitivities(p: &PegHole, l: f64) -> Result<DesignSensitivities, ParamError> {
    let l = PegHole::check_depth(l)?;
    let pv: SVector<f64, 4> = generated::Params {
        r: p.r(),
        c: p.c(),
        mu: p.mu(),
        l,
    }
    .into();
    let w = generated::whitney_diagram_p(&pv);
    let whitney = ParallelogramSensitivity {
        edge_corner: RatioGradient::from_matrix(&w.dedge_corner_dp),
        mirrored_corner: RatioGradient::from_matrix(&w.dmirrored_corner_dp),
        slope: gradient(&w.dslope_dp),
        intercept: gradient(&w.dintercept_dp),
        tilt: Gradient::default(),
    };
    let exact = (l > min_two_point_depth(p)).then(|| {
        let e = generated::exact_diagram_p(&pv);
        ParallelogramSensitivity {
            edge_corner: RatioGradient::from_matrix(&e.dedge_corner_dp),
            mirrored_corner: RatioGradient::from_matrix(&e.dmirrored_corner_dp),
            slope: gradient(&e.dslope_dp),
            intercept: gradient(&e.dintercept_dp),
            tilt: gradient(&e.dtilt_dp),
        }
    });
    let x = p.hole_diameter() / (p.peg_diameter() * p.mu().hypot(1.0));
    let wd = generated::wedging_p(&pv);
    let wedging = WedgingSensitivity {
        exact: (x < 1.0).then(|| gradient(&wd.dexact_dp)),
        series: gradient(&wd.dseries_dp),
        whitney: gradient(&wd.dwhitney_dp),
    };
    Ok(DesignSensitivities {
        whitney,
        exact,
        wedging,
    })
}
