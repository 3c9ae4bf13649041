//! The relative curvature of two bodies at a point of contact.
//!
//! Each body's surface near the contact is `zᵢ = ½ κᵢ₁ x² + ½ κᵢ₂ y²` in its
//! own principal axes (the paper's (6), written with curvatures `κ = 1/ρ`;
//! convex surfaces have positive, concave negative curvature). With the
//! angle `ω` between the principal plane of `κ₁₁` and that of `κ₂₁`, the gap
//! is `h = A x'² + B y'²` in the axes of the contact ellipse, where
//!
//! ```text
//! A + B = ½ Σρ,   Σρ = κ₁₁ + κ₁₂ + κ₂₁ + κ₂₂                       (7)
//! B − A = ½ √((κ₁₁ − κ₁₂)² + (κ₂₁ − κ₂₂)² + 2(κ₁₁ − κ₁₂)(κ₂₁ − κ₂₂) cos 2ω)
//! ```
//!
//! (Johnson, *Contact Mechanics*, §4.1). The paper's (7) calls `Σρ` a sum of
//! "curvature radii"; it is a sum of curvatures (see
//! `docs/formula-departures.md`).

/// The principal curvatures of two bodies and the angle between their
/// principal planes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curvatures {
    /// Principal curvatures `[κ₁₁, κ₁₂]` of body 1 (1/m; concave < 0).
    pub body1: [f64; 2],
    /// Principal curvatures `[κ₂₁, κ₂₂]` of body 2 (1/m; concave < 0).
    pub body2: [f64; 2],
    /// Angle `ω` (rad) between the plane of `κ₁₁` and the plane of `κ₂₁`.
    pub angle: f64,
}

impl Curvatures {
    /// Two bodies whose principal planes coincide (`ω = 0`).
    pub fn aligned(body1: [f64; 2], body2: [f64; 2]) -> Curvatures {
        Curvatures {
            body1,
            body2,
            angle: 0.0,
        }
    }

    /// A body of curvature `[κ₁, κ₂]` on a flat.
    pub fn on_flat(body: [f64; 2]) -> Curvatures {
        Curvatures::aligned(body, [0.0, 0.0])
    }

    /// `Σρ` of the paper's (7): the sum of the four principal curvatures (1/m).
    pub fn sum(&self) -> f64 {
        self.body1[0] + self.body1[1] + self.body2[0] + self.body2[1]
    }

    /// The relative curvatures `(A, B)`, `A ≤ B`, `A + B = Σρ/2` (1/m).
    ///
    /// When the principal planes are aligned or crossed at a right angle
    /// (`cos 2ω = ±1` to rounding), the directional sums are formed directly,
    /// so that a nearly conforming direction (a convex radius against a
    /// slightly larger concave one) keeps its digits.
    ///
    /// ```
    /// use pegdyn::hertz::Curvatures;
    /// // Crossed cylinders of radius 2 m and 3 m: A = 1/6, B = 1/4.
    /// let c = Curvatures { body1: [0.5, 0.0], body2: [1.0 / 3.0, 0.0], angle: std::f64::consts::FRAC_PI_2 };
    /// let (a, b) = c.relative();
    /// assert!((a - 1.0 / 6.0).abs() < 1e-15 && (b - 0.25).abs() < 1e-15);
    /// ```
    pub fn relative(&self) -> (f64, f64) {
        let [k11, k12] = self.body1;
        let [k21, k22] = self.body2;
        let c2 = (2.0 * self.angle).cos();
        let (p, q) = if (c2 - 1.0).abs() < 1e-15 {
            (0.5 * (k11 + k21), 0.5 * (k12 + k22))
        } else if (c2 + 1.0).abs() < 1e-15 {
            (0.5 * (k11 + k22), 0.5 * (k12 + k21))
        } else {
            let (d1, d2) = (k11 - k12, k21 - k22);
            let half_sum = 0.25 * self.sum();
            let half_diff = 0.25 * (d1 * d1 + d2 * d2 + 2.0 * d1 * d2 * c2).max(0.0).sqrt();
            (half_sum - half_diff, half_sum + half_diff)
        };
        (p.min(q), p.max(q))
    }
}
