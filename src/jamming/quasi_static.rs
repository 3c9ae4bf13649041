//! The paper's contact-force solution, Eqs. 51–54, in the paper's own frame:
//! a hand-written reference for the generated model `quasi_static`.
//!
//! Paper frame (Fig. 5): x lateral, y (printed z in Eqs. 50–54) along the
//! hole axis into the hole, θ positive clockwise; contact A is the hole-mouth
//! edge on the peg side (normal perpendicular to the peg axis), contact B the
//! peg's tip corner on the wall x = D. The input force has components f₁
//! along and f₂ across the peg axis; M is the input moment about the centre
//! of mass C, which lies l_c above the tip face. Moment arms (Eqs. 22–26):
//!
//! ```text
//! S_AX = r,  S_AY = l_c − l,  S_BX = l_c sinθ + r cosθ,  S_BY = l_c cosθ − r sinθ
//! ```
//!
//! Equations 51 (D'Alembert, sliding friction, A and B both touching):
//!
//! ```text
//! m ẍ = f₁ sinθ + f₂ cosθ + k1 f_A − f_B
//! m ÿ = f₁ cosθ − f₂ sinθ − k2 f_A − μ f_B
//! J θ̈ = M + (S_AY − μ S_AX) f_A − (S_BY − μ S_BX) f_B
//! ```
//!
//! solved for (f_A, f_B, M) in Eq. 52. One-point contact (Eqs. 53, 54) drops
//! the other force; the normal force is then the projection of the force
//! balance on the contact normal, and the tangential balance is a constraint
//! on the accelerations. Eq. 53 as printed has sign errors (see
//! `docs/formula-departures.md`); here it is Eq. 51 with f_B = 0.

use super::error::SlidingIndeterminate;
use super::forces::{checked_k_factors, k_factors};

/// Geometry, friction and inertia of the paper's planar peg (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperPeg {
    /// Tilt θ (rad), clockwise positive.
    pub theta: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// Peg radius r (m).
    pub r: f64,
    /// Insertion depth l (m).
    pub l: f64,
    /// Distance l_c from the tip face to the centre of mass (m).
    pub l_c: f64,
    /// Mass m (kg).
    pub m: f64,
    /// Moment of inertia J about C (kg m²).
    pub j: f64,
}

/// Input force components (N): f₁ along the peg axis, f₂ across it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PegLoad {
    /// Axial component f₁ (N).
    pub f1: f64,
    /// Radial component f₂ (N).
    pub f2: f64,
}

/// Accelerations ẍ, ÿ (m/s²) of C and θ̈ (rad/s²).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PegAcc {
    /// ẍ (m/s²).
    pub xdd: f64,
    /// ÿ (m/s², printed z̈), into the hole.
    pub ydd: f64,
    /// θ̈ (rad/s²).
    pub thdd: f64,
}

/// Result of the quasi-static solution: contact forces (N) and the input
/// moment about C (N·m) consistent with the given motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperSolution {
    /// Edge contact force f_A (N).
    pub f_a: f64,
    /// Tip contact force f_B (N).
    pub f_b: f64,
    /// Input moment M about C (N·m).
    pub m: f64,
}

impl PaperPeg {
    /// Moment arms (S_AX, S_AY, S_BX, S_BY) of Eqs. 22–26 (m).
    pub fn arms(&self) -> (f64, f64, f64, f64) {
        let (s, c) = self.theta.sin_cos();
        (
            self.r,
            self.l_c - self.l,
            self.l_c * s + self.r * c,
            self.l_c * c - self.r * s,
        )
    }

    /// Two-point contact, Eq. 52: f_A = a₁f₁ + a₂f₂ + a₃, f_B = b₁f₁ + b₂f₂
    /// + b₃, M = c₁f₁ + c₂f₂ + c₃ + Jθ̈.
    ///
    /// Unchecked: ±∞ or NaN where k3 = 0 (as the generated
    /// `pegdyn::generated::quasi_static::two_point`, which has no runtime
    /// caller: tests and benches only); [`PaperPeg::try_two_point`] checks.
    pub fn two_point(&self, u: PegLoad, acc: PegAcc) -> PaperSolution {
        self.two_point_with(k_factors(self.mu, self.theta), u, acc)
    }

    /// [`PaperPeg::two_point`], or why it is not determined.
    ///
    /// # Errors
    /// [`SlidingIndeterminate`] when k3 is zero to rounding (see
    /// [`checked_k_factors`]).
    pub fn try_two_point(
        &self,
        u: PegLoad,
        acc: PegAcc,
    ) -> Result<PaperSolution, SlidingIndeterminate> {
        Ok(self.two_point_with(checked_k_factors(self.mu, self.theta)?, u, acc))
    }

    fn two_point_with(
        &self,
        (k1, k2, k3): (f64, f64, f64),
        u: PegLoad,
        acc: PegAcc,
    ) -> PaperSolution {
        let (mu, m) = (self.mu, self.m);
        let f_a = (k1 * u.f1 - k2 * u.f2 + mu * m * acc.xdd - m * acc.ydd) / k3;
        let f_b = (u.f1 + mu * u.f2 - k1 * m * acc.ydd - k2 * m * acc.xdd) / k3;
        let (sax, say, sbx, sby) = self.arms();
        PaperSolution {
            f_a,
            f_b,
            m: (mu * sax - say) * f_a + (sby - mu * sbx) * f_b + self.j * acc.thdd,
        }
    }

    /// One-point contact at the edge A (Eq. 53, corrected): f_A from the
    /// normal balance, M from the moment balance; f_B = 0.
    pub fn edge_only(&self, u: PegLoad, acc: PegAcc) -> PaperSolution {
        let (s, c) = self.theta.sin_cos();
        let f_a = self.m * (acc.xdd * c - acc.ydd * s) - u.f2;
        let (sax, say, _, _) = self.arms();
        PaperSolution {
            f_a,
            f_b: 0.0,
            m: (self.mu * sax - say) * f_a + self.j * acc.thdd,
        }
    }

    /// One-point contact at the tip B (Eq. 54): f_B from the x balance, M
    /// from the moment balance; f_A = 0.
    pub fn tip_only(&self, u: PegLoad, acc: PegAcc) -> PaperSolution {
        let (s, c) = self.theta.sin_cos();
        let f_b = u.f1 * s + u.f2 * c - self.m * acc.xdd;
        let (_, _, sbx, sby) = self.arms();
        PaperSolution {
            f_a: 0.0,
            f_b,
            m: (sby - self.mu * sbx) * f_b + self.j * acc.thdd,
        }
    }
}
