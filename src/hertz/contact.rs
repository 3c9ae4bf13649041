//! Hertz's elliptical point contact: the paper's (8)–(13) and the
//! force–approach law `Q = k δ^{3/2}` used by the dynamics.
//!
//! With `E*` the contact modulus ([`super::contact_modulus`]), `Σρ` the
//! curvature sum and the coefficients of [`Coefficients`]:
//!
//! ```text
//! a  = m_a (3Q / (2 Σρ E*))^{1/3}                                  (9)
//! b  = m_b (3Q / (2 Σρ E*))^{1/3}                                  (10)
//! p₀ = 3Q / (2π a b)                                               (11)
//! δ  = δ* (⅛ (3/(2E*))² Q² Σρ)^{1/3}                               (13)
//! Q  = k δ^{3/2},  k = (2E*/3) √(8 / (δ*³ Σρ))        (13) inverted
//! ```
//!
//! `δ*` is what the paper calls `K` in (13). For a sphere of radius `R` on a
//! flat these reduce to `a = (3QR/(4E*))^{1/3}`, `δ = a²/R`,
//! `k = (4/3) E* √R`.

use super::curvature::Curvatures;
use super::ellipticity::{self, Coefficients, Ellipticity};
use super::error::HertzError;
use super::material::{Material, contact_modulus};
use std::f64::consts::PI;

/// How the ellipticity is obtained from the curvature ratio.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum EllipticityMethod {
    /// Solve `B/A = f(e)` with complete elliptic integrals (to rounding).
    #[default]
    Exact,
    /// The Hamrock–Brewe curve fits (a few per cent; see
    /// [`ellipticity::hamrock_brewe`]).
    HamrockBrewe,
}

/// The contact ellipse, pressure and approach at one load.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState {
    /// Semi-major axis `a` (m), along the direction of smaller relative curvature.
    pub a: f64,
    /// Semi-minor axis `b` (m).
    pub b: f64,
    /// Maximum pressure `p₀` (Pa).
    pub p0: f64,
    /// Approach `δ` of distant points of the two bodies (m).
    pub delta: f64,
}

/// A Hertz point contact between two bodies: everything that does not
/// depend on the load, computed once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HertzContact {
    /// `Σρ` (1/m).
    pub sum_curvature: f64,
    /// Relative curvatures `(A, B)`, `A ≤ B` (1/m).
    pub relative: (f64, f64),
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Ellipse shape and elliptic integrals.
    pub ellipticity: Ellipticity,
    /// Coefficients `m_a, m_b, δ*` (the paper's `K`), `A, B, C` of (12).
    pub coefficients: Coefficients,
}

impl HertzContact {
    /// Sets up the contact of two bodies of curvatures `curv` and materials
    /// `body1`, `body2`.
    ///
    /// Refuses non-finite curvatures (field `curvature`), contacts where
    /// a relative curvature is not positive ([`HertzError::NotPointContact`])
    /// and line contacts ([`HertzError::LineContact`], `B/A` above
    /// [`ellipticity::MAX_RATIO`]).
    ///
    /// ```
    /// use pegdyn::hertz::{Curvatures, EllipticityMethod, HertzContact, Material};
    /// // A steel ball of radius 10 mm on a steel flat under 100 N.
    /// let c = HertzContact::try_new(
    ///     &Curvatures::on_flat([100.0, 100.0]),
    ///     &Material::STEEL,
    ///     &Material::STEEL,
    ///     EllipticityMethod::Exact,
    /// )
    /// .unwrap();
    /// let s = c.state(100.0);
    /// let r = 0.01;
    /// let a = (3.0 * 100.0 * r / (4.0 * c.contact_modulus)).cbrt();
    /// assert!((s.a - a).abs() < 1e-12 * a && (s.delta - a * a / r).abs() < 1e-12 * s.delta);
    /// ```
    pub fn try_new(
        curv: &Curvatures,
        body1: &Material,
        body2: &Material,
        method: EllipticityMethod,
    ) -> Result<HertzContact, HertzError> {
        for (k, v) in curv
            .body1
            .iter()
            .chain(&curv.body2)
            .chain([&curv.angle])
            .enumerate()
        {
            if !v.is_finite() {
                let field = if k < 4 { "curvature" } else { "angle" };
                return Err(HertzError::Invalid {
                    field: field.to_owned(),
                    value: *v,
                    reason: "must be finite",
                });
            }
        }
        let (a, b) = curv.relative();
        if !(a > 0.0 && b > 0.0) {
            return Err(HertzError::NotPointContact { a, b });
        }
        if b / a > ellipticity::MAX_RATIO {
            return Err(HertzError::LineContact {
                ratio: b / a,
                limit: ellipticity::MAX_RATIO,
            });
        }
        let sum_curvature = 2.0 * (a + b);
        if !sum_curvature.is_finite() {
            return Err(HertzError::Invalid {
                field: "curvature".to_owned(),
                value: sum_curvature,
                reason: "the curvature sum overflows f64",
            });
        }
        let modulus = contact_modulus(body1, body2);
        if !(modulus.is_finite() && modulus > 0.0) {
            return Err(HertzError::Invalid {
                field: "youngs_modulus".to_owned(),
                value: modulus,
                reason: "the contact modulus E* must be finite and > 0",
            });
        }
        let ellipticity = match method {
            EllipticityMethod::Exact => ellipticity::try_solve(b / a)?,
            EllipticityMethod::HamrockBrewe => ellipticity::hamrock_brewe(b / a),
        };
        let contact = HertzContact {
            sum_curvature,
            relative: (a, b),
            contact_modulus: modulus,
            ellipticity,
            coefficients: Coefficients::of(&ellipticity),
        };
        let k = contact.stiffness();
        if !(k.is_finite() && k > 0.0) {
            return Err(HertzError::Invalid {
                field: "curvature".to_owned(),
                value: sum_curvature,
                reason: "the contact stiffness E* sqrt(8/sum of curvatures) leaves the f64 range",
            });
        }
        Ok(contact)
    }

    /// `(3Q / (2 Σρ E*))^{1/3}`, the length scale of (9)–(10) (m).
    fn length_scale(&self, q: f64) -> f64 {
        (3.0 * q / (2.0 * self.sum_curvature * self.contact_modulus)).cbrt()
    }

    /// Semi-axes `(a, b)` (m) at load `q ≥ 0` (N), (9)–(10).
    pub fn semi_axes(&self, q: f64) -> (f64, f64) {
        let s = self.length_scale(q.max(0.0));
        (self.coefficients.m_a * s, self.coefficients.m_b * s)
    }

    /// Maximum pressure `p₀` (Pa) at load `q` (N), (11); 0 without load.
    pub fn max_pressure(&self, q: f64) -> f64 {
        if q <= 0.0 {
            return 0.0;
        }
        let (a, b) = self.semi_axes(q);
        1.5 * q / (PI * a * b)
    }

    /// Approach `δ` (m) at load `q` (N), (13).
    pub fn approach(&self, q: f64) -> f64 {
        let c = 1.5 / self.contact_modulus;
        let q = q.max(0.0);
        self.coefficients.delta_star * (0.125 * c * c * q * q * self.sum_curvature).cbrt()
    }

    /// The stiffness `k` (N/m^{3/2}) of `Q = k δ^{3/2}`.
    pub fn stiffness(&self) -> f64 {
        let d = self.coefficients.delta_star;
        (2.0 * self.contact_modulus / 3.0) * (8.0 / (d * d * d * self.sum_curvature)).sqrt()
    }

    /// The load `Q = k max(δ, 0)^{3/2}` (N) at approach `delta` (m).
    pub fn load(&self, delta: f64) -> f64 {
        let d = delta.max(0.0);
        self.stiffness() * d * d.sqrt()
    }

    /// The elastic energy `∫₀^δ Q dξ = (2/5) k δ^{5/2}` (J), the paper's (62).
    pub fn potential(&self, delta: f64) -> f64 {
        let d = delta.max(0.0);
        0.4 * self.stiffness() * d * d * d.sqrt()
    }

    /// Ellipse, pressure and approach at load `q` (N).
    pub fn state(&self, q: f64) -> ContactState {
        let (a, b) = self.semi_axes(q);
        ContactState {
            a,
            b,
            p0: self.max_pressure(q),
            delta: self.approach(q),
        }
    }
}
