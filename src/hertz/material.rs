//! Elastic materials and the contact modulus of a pair.

use super::error::{HertzError, positive};

/// An isotropic linear-elastic material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Young's modulus `E` (Pa).
    pub youngs_modulus: f64,
    /// Poisson's ratio `ν` (dimensionless), in `(−1, 0.5)`.
    pub poisson_ratio: f64,
}

impl Material {
    /// Structural steel: `E = 210 GPa`, `ν = 0.3`.
    pub const STEEL: Material = Material {
        youngs_modulus: 210e9,
        poisson_ratio: 0.3,
    };

    /// A checked material: `E` finite and `> 0`, `ν` in the open interval
    /// `(−1, 0.5)`. Errors name the field (`youngs_modulus`,
    /// `poisson_ratio`).
    ///
    /// ```
    /// use pegdyn::hertz::Material;
    /// assert!(Material::try_new(210e9, 0.3).is_ok());
    /// let err = Material::try_new(-1.0, 0.3).unwrap_err();
    /// assert!(err.to_string().contains("youngs_modulus"));
    /// ```
    pub fn try_new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Material, HertzError> {
        positive("youngs_modulus", youngs_modulus)?;
        if !(poisson_ratio > -1.0 && poisson_ratio < 0.5) {
            return Err(HertzError::Invalid {
                field: "poisson_ratio".to_owned(),
                value: poisson_ratio,
                reason: "must lie in the open interval (-1, 0.5)",
            });
        }
        Ok(Material {
            youngs_modulus,
            poisson_ratio,
        })
    }

    /// The compliance `(1 − ν²)/E` (1/Pa) of the paper's (9), (10), (13).
    pub fn compliance(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
    }
}

/// The contact modulus `E* = [(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂]⁻¹` (Pa).
///
/// ```
/// use pegdyn::hertz::{Material, contact_modulus};
/// let e = contact_modulus(&Material::STEEL, &Material::STEEL);
/// assert!((e - 210e9 / (2.0 * 0.91)).abs() < 1.0);
/// ```
pub fn contact_modulus(body1: &Material, body2: &Material) -> f64 {
    1.0 / (body1.compliance() + body2.compliance())
}
