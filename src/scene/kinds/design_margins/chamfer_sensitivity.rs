//! Derivatives of the chamfer's capture widths ([`Capture::width`],
//! [`Capture::frictionless_width`], [`Capture::aligned_tip_error`]) with
//! respect to the capture geometry and the friction, generated
//! symbolically (the generated model `chamfer_capture`, declared in
//! `equations/src/models/chamfer_capture.rs`, and its parameter Jacobian):
//!
//! ```text
//! W_0 = R + ρ_h,   W_μ = W_0 − (ρ_h + ρ_p) μ/√(1 + μ²),   e_max = W_μ − (r − ρ_p)
//! ∂W_μ/∂R = 1,  ∂W_μ/∂ρ_h = 1 − μ/√(1 + μ²),  ∂W_μ/∂ρ_p = −μ/√(1 + μ²),
//! ∂W_μ/∂μ = −(ρ_h + ρ_p)/(1 + μ²)^{3/2}
//! ```
//!
//! The height of the compliance centre does not enter the widths (it moves
//! the tip's error, not the band an aligned peg is captured in).

use super::chamfer::Capture;
use crate::generated::chamfer_capture as generated;
use nalgebra::SVector;

/// Derivatives of one capture width with respect to the fields of
/// [`Capture`] (each per unit of that field; the others held fixed).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CaptureGradient {
    /// With respect to the peg radius `r` (m).
    pub peg_radius: f64,
    /// With respect to the bore radius `R` (m).
    pub bore_radius: f64,
    /// With respect to the rim fillet `ρ_p` (m).
    pub rim_fillet: f64,
    /// With respect to the mouth fillet `ρ_h` (m).
    pub mouth_fillet: f64,
    /// With respect to the friction coefficient `μ` (m per unit μ).
    pub friction: f64,
}

impl CaptureGradient {
    /// From a generated row, its columns taken by name through the
    /// generated model's parameters.
    fn from_vector(v: &SVector<f64, 5>) -> CaptureGradient {
        let g = generated::Params::from(v);
        CaptureGradient {
            peg_radius: g.r_peg,
            bore_radius: g.r_bore,
            rim_fillet: g.rho_p,
            mouth_fillet: g.rho_h,
            friction: g.mu,
        }
    }
}

/// The derivatives of the three capture widths.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CaptureSensitivity {
    /// Of `W_0 = R + ρ_h` ([`Capture::frictionless_width`]).
    pub frictionless_width: CaptureGradient,
    /// Of `W_μ` ([`Capture::width`]).
    pub width: CaptureGradient,
    /// Of the largest aligned tip error `W_μ − (r − ρ_p)`
    /// ([`Capture::aligned_tip_error`]).
    pub aligned_tip_error: CaptureGradient,
}

impl Capture {
    /// The derivatives of the capture widths at this geometry.
    ///
    /// ```
    /// use pegdyn::scene::kinds::design_margins::chamfer::Capture;
    /// let c = Capture {
    ///     peg_radius: 0.0124, bore_radius: 0.0125, rim_fillet: 3e-4,
    ///     mouth_fillet: 5e-4, friction: 0.2, centre_height: 0.025,
    /// };
    /// let s = c.sensitivities();
    /// // ∂W_μ/∂ρ_h = 1 − μ/√(1 + μ²)
    /// assert!((s.width.mouth_fillet - (1.0 - 0.2 / 1.04f64.sqrt())).abs() < 1e-15);
    /// assert_eq!(s.aligned_tip_error.peg_radius, -1.0);
    /// ```
    pub fn sensitivities(&self) -> CaptureSensitivity {
        let p: SVector<f64, 5> = generated::Params {
            r_peg: self.peg_radius,
            r_bore: self.bore_radius,
            rho_p: self.rim_fillet,
            rho_h: self.mouth_fillet,
            mu: self.friction,
        }
        .into();
        let d = generated::widths_p(&p);
        CaptureSensitivity {
            frictionless_width: CaptureGradient::from_vector(&d.dfrictionless_width_dp),
            width: CaptureGradient::from_vector(&d.dwidth_dp),
            aligned_tip_error: CaptureGradient::from_vector(&d.daligned_tip_error_dp),
        }
    }
}
