//! Peg/hole parameters of Whitney's two-dimensional peg-in-hole problem.

use super::error::{ParamError, check};

/// A round peg of radius `r` in a round hole, with clearance ratio
/// `c = (D − d)/D` (d = 2r peg diameter, D hole diameter) and Coulomb
/// friction coefficient `mu` at every contact.
///
/// Built only through [`PegHole::try_new`], so every value is finite and in
/// range: `r > 0` (m), `0 < c < 1`, `mu > 0` (a frictionless peg never jams:
/// the diagram's one-point sides sit at `F_x/F_z = ±1/μ`).
///
/// ```
/// use pegdyn::jamming::PegHole;
/// let p = PegHole::try_new(0.0125, 0.01, 0.3).unwrap();
/// assert!((p.hole_diameter() - 0.025 / 0.99).abs() < 1e-15);
/// assert_eq!(PegHole::try_new(0.0125, 1.5, 0.3).unwrap_err().field, "c");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PegHole {
    r: f64,
    c: f64,
    mu: f64,
}

impl PegHole {
    /// Check and build; the error names the first refused field.
    pub fn try_new(r: f64, c: f64, mu: f64) -> Result<Self, ParamError> {
        let r = check("r", r, |v| v > 0.0, "peg radius must be positive (m)")?;
        let c = check(
            "c",
            c,
            |v| v > 0.0 && v < 1.0,
            "clearance ratio (D - d)/D must lie in (0, 1)",
        )?;
        let mu = check(
            "mu",
            mu,
            |v| v > 0.0,
            "friction coefficient must be positive",
        )?;
        Ok(Self { r, c, mu })
    }

    /// Peg radius r (m).
    pub fn r(&self) -> f64 {
        self.r
    }
    /// Clearance ratio c = (D − d)/D.
    pub fn c(&self) -> f64 {
        self.c
    }
    /// Friction coefficient μ.
    pub fn mu(&self) -> f64 {
        self.mu
    }
    /// Peg diameter d = 2r (m).
    pub fn peg_diameter(&self) -> f64 {
        2.0 * self.r
    }
    /// Hole diameter D = d/(1 − c) (m).
    pub fn hole_diameter(&self) -> f64 {
        self.peg_diameter() / (1.0 - self.c)
    }
    /// Whitney's dimensionless depth λ = l/(2rμ) for insertion depth `l` (m).
    pub fn lambda(&self, l: f64) -> f64 {
        l / (2.0 * self.r * self.mu)
    }
    /// Check an insertion depth `l` (m): finite and positive.
    pub fn check_depth(l: f64) -> Result<f64, ParamError> {
        check("l", l, |v| v > 0.0, "insertion depth must be positive (m)")
    }
}
