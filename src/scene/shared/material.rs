//! The material table of the compliant pegs (`insert_compliant`'s and the
//! compliant 3-D kinds' `peg_material` and `hole_material`).

use serde::Deserialize;

/// A material table.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus, Pa.
    pub youngs_modulus: f64,
    /// Poisson's ratio, in (−1, 0.5).
    pub poisson_ratio: f64,
}

/// Steel (E = 210 GPa, ν = 0.3), the default of every material table.
pub fn steel() -> MaterialSpec {
    MaterialSpec {
        youngs_modulus: 210e9,
        poisson_ratio: 0.3,
    }
}
