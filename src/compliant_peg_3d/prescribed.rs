//! The compliant 3-D peg with a prescribed orientation and a free
//! translation: the compliant counterpart of the rigid three-point peg's
//! prescribed motion (nutation γ(t), precession ψ(t), spin held).
//!
//! Orientation (the rigid three-point peg's Euler angles; `e_η`, `e_n` the
//! symmetry-plane frame at ψ):
//!
//! ```text
//! R(t) = R_z(ψ) R_y(−γ),   axis a = R e_z = −sin γ e_η + cos γ e_z
//! ω    = ψ̇ e_z − γ̇ e_n     (hole frame),   ω_body = Rᵀ ω
//! γ(t) = γ_s + γ̇ t,   ψ(t) = ψ_s + ψ̇ t
//! ```
//!
//! The state is `y = (p, v, S)` (centre of mass in m, its velocity in m/s,
//! dissipated energy in J); the moment that drives the orientation is
//! whatever it has to be, and the translation obeys
//!
//! ```text
//! ṗ = v,   m v̇ = F + F_a − m g e_z,   Ṡ = Σ ((Q − Q_e) δ̇ − F_t·v_t)
//! ```
//!
//! with `F` and `Ṡ` the force and dissipation rate of [`Peg3d::wrench`]
//! over every contact of [`Peg3d::forces`] (every pair, the rim torus
//! against the mouth torus included, each col's elastic force of a merging
//! pair included, the stiffness fixed or from the curvatures as
//! [`HertzMode`] says). The rigid three-point peg's bottom edge rests on
//! the hole edge at B1 and B2: here the pair [`Pair::RimEdge`].
//!
//! The exact Jacobian is the contact wrench's in dual numbers of the full
//! state ([`Peg3d::contact_wrench_dual`], at the contacts the right-hand
//! side just found), its columns of `p` and `v`; the time derivative
//! follows the prescribed pose through the chain rule,
//!
//! ```text
//! ∂w/∂t = ∂w/∂q · q̇ + ∂w/∂ω_body · ω̇_body,
//! q̇ = ½ q ⊗ (0, ω_body),   ω̇_body = Rᵀ γ̇ ψ̇ (cos ψ, sin ψ, 0)
//! ```
//!
//! (`d(Rᵀ ω)/dt = Rᵀ ω̇`: the term `−ω_body × ω_body` vanishes).

#[cfg(doc)]
use super::contact::Pair;
use super::forces::ContactForce;
use super::jacobian::D;
use super::params::{HertzMode, Peg3dParams};
use super::system::{Peg3d, pose_state};
use crate::hertz::HertzError;
use crate::system::{ModelError, OdeSystem};
use nalgebra::{SMatrix, SVector, UnitQuaternion, Vector3};
use std::cell::RefCell;

/// Steady rates of nutation and precession from a start orientation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// γ at `t = 0` (rad).
    pub gamma: f64,
    /// γ̇ (1/s); negative aligns the peg.
    pub gammadot: f64,
    /// ψ at `t = 0` (rad).
    pub psi: f64,
    /// ψ̇ (1/s); positive is counter-clockwise seen from above.
    pub psidot: f64,
}

impl Motion {
    /// `(γ(t), ψ(t))` (rad).
    pub fn angles(&self, t: f64) -> (f64, f64) {
        (self.gamma + self.gammadot * t, self.psi + self.psidot * t)
    }

    /// `R(t) = R_z(ψ) R_y(−γ)`: the axis tilts by γ towards `−e_η`.
    pub fn orientation(&self, t: f64) -> UnitQuaternion<f64> {
        let (gamma, psi) = self.angles(t);
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), psi)
            * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -gamma)
    }

    /// `ω_body = Rᵀ (ψ̇ e_z − γ̇ e_n)` (1/s), `e_n = (−sin ψ, cos ψ, 0)`.
    pub fn omega_body(&self, t: f64) -> Vector3<f64> {
        let (_, psi) = self.angles(t);
        let e_n = Vector3::new(-psi.sin(), psi.cos(), 0.0);
        let omega = Vector3::z() * self.psidot - e_n * self.gammadot;
        self.orientation(t).inverse() * omega
    }

    /// `ω̇_body = Rᵀ γ̇ ψ̇ (cos ψ, sin ψ, 0)` (1/s²).
    pub fn omega_body_rate(&self, t: f64) -> Vector3<f64> {
        let (_, psi) = self.angles(t);
        let rate = Vector3::new(psi.cos(), psi.sin(), 0.0) * (self.gammadot * self.psidot);
        self.orientation(t).inverse() * rate
    }
}

/// The time derivative of the last Jacobian, at the `(t, y)` bits it was
/// evaluated at: a Rosenbrock step asks for both at one state.
type Memo = ([u64; 8], SVector<f64, 7>);

/// The compliant 3-D peg whose orientation follows [`Motion`].
pub struct PrescribedPeg {
    /// The peg.
    pub peg: Peg3d,
    /// The prescribed orientation.
    pub motion: Motion,
    rate_memo: RefCell<Option<Memo>>,
}

impl PrescribedPeg {
    /// The system of `params` driven along `motion`.
    ///
    /// # Errors
    /// [`HertzError::Invalid`] (field `hertz`) for a
    /// [`HertzMode::Fixed`] stiffness that is not finite and positive.
    pub fn try_new(params: Peg3dParams, motion: Motion) -> Result<PrescribedPeg, HertzError> {
        match params.hertz {
            HertzMode::Fixed(k) if !(k.is_finite() && k > 0.0) => Err(HertzError::Invalid {
                field: "hertz".to_owned(),
                value: k,
                reason: "the fixed stiffness must be finite and > 0",
            }),
            _ => Ok(PrescribedPeg {
                peg: Peg3d::new(params),
                motion,
                rate_memo: RefCell::new(None),
            }),
        }
    }

    /// The 15-state `(p, q(t), v, ω_body(t), 0, S)` of the full model.
    pub fn full_state(&self, t: f64, y: &SVector<f64, 7>) -> SVector<f64, 15> {
        let mut full = pose_state(
            Vector3::new(y[0], y[1], y[2]),
            self.motion.orientation(t),
            Vector3::new(y[3], y[4], y[5]),
            self.motion.omega_body(t),
        );
        full[14] = y[6];
        full
    }

    /// Every contact force at time `t`, state `y`: [`Peg3d::forces`] of
    /// [`PrescribedPeg::full_state`].
    ///
    /// # Errors
    /// As [`Peg3d::forces`].
    pub fn forces(&self, t: f64, y: &SVector<f64, 7>) -> Result<Vec<ContactForce>, HertzError> {
        self.peg.forces(&self.full_state(t, y))
    }
}

impl PrescribedPeg {
    /// The exact Jacobian (7 × 7) and time derivative at `(t, y)` of the
    /// module documentation.
    ///
    /// # Errors
    /// As [`Peg3d::setups`] when the contacts have to be searched.
    pub fn linearization(
        &self,
        t: f64,
        y: &SVector<f64, 7>,
    ) -> Result<(SMatrix<f64, 7, 7>, SVector<f64, 7>), HertzError> {
        let full = self.full_state(t, y);
        let w: [D; 7] = self.peg.contact_wrench_dual(&full)?;
        let inv_m = 1.0 / self.peg.params.mass;
        let mut j = SMatrix::<f64, 7, 7>::zeros();
        for k in 0..3 {
            j[(k, 3 + k)] = 1.0;
        }
        // State slots: p 0–2, v 7–9 of the full state; rows F (0–2), Ṡ (6).
        for (r, scale) in [(0, inv_m), (1, inv_m), (2, inv_m), (6, 1.0)] {
            let row = if r == 6 { 6 } else { 3 + r };
            for c in 0..3 {
                j[(row, c)] = w[r].d[c] * scale;
                j[(row, 3 + c)] = w[r].d[7 + c] * scale;
            }
        }
        // ∂w/∂t through q(t) and ω_body(t).
        let q = [full[3], full[4], full[5], full[6]];
        let om = [full[10], full[11], full[12]];
        let q_dot = [
            -0.5 * (q[1] * om[0] + q[2] * om[1] + q[3] * om[2]),
            0.5 * (q[0] * om[0] + q[2] * om[2] - q[3] * om[1]),
            0.5 * (q[0] * om[1] + q[3] * om[0] - q[1] * om[2]),
            0.5 * (q[0] * om[2] + q[1] * om[1] - q[2] * om[0]),
        ];
        let om_dot = self.motion.omega_body_rate(t);
        let dt = |r: usize| {
            let d = &w[r].d;
            (0..4).map(|k| d[3 + k] * q_dot[k]).sum::<f64>()
                + (0..3).map(|k| d[10 + k] * om_dot[k]).sum::<f64>()
        };
        let rate = SVector::<f64, 7>::from_column_slice(&[
            0.0,
            0.0,
            0.0,
            dt(0) * inv_m,
            dt(1) * inv_m,
            dt(2) * inv_m,
            dt(6),
        ]);
        Ok((j, rate))
    }
}

/// The bits of `(t, y)`.
fn key(t: f64, y: &SVector<f64, 7>) -> [u64; 8] {
    std::array::from_fn(|k| {
        if k == 0 {
            t.to_bits()
        } else {
            y[k - 1].to_bits()
        }
    })
}

impl OdeSystem<7> for PrescribedPeg {
    /// [`OdeSystem::try_rhs`], NaN when [`PrescribedPeg::forces`] fails.
    fn rhs(&self, t: f64, y: &SVector<f64, 7>) -> SVector<f64, 7> {
        self.try_rhs(t, y)
            .unwrap_or_else(|_| SVector::repeat(f64::NAN))
    }

    /// `(v, (F + F_a)/m − g e_z, Ṡ)` with `(F, Ṡ)` of
    /// [`Peg3d::contact_wrench`].
    fn try_rhs(&self, t: f64, y: &SVector<f64, 7>) -> Result<SVector<f64, 7>, ModelError> {
        let w = self.peg.contact_wrench(&self.full_state(t, y))?;
        let prm = &self.peg.params;
        let f =
            Vector3::new(w[0], w[1], w[2]) + prm.force - Vector3::z() * (prm.mass * prm.gravity);
        let a = f / prm.mass;
        Ok(SVector::<f64, 7>::from_column_slice(&[
            y[3], y[4], y[5], a.x, a.y, a.z, w[6],
        ]))
    }

    /// [`PrescribedPeg::linearization`]'s Jacobian, NaN after a Hertz
    /// setup error.
    fn jacobian(&self, t: f64, y: &SVector<f64, 7>) -> SMatrix<f64, 7, 7> {
        self.try_jacobian(t, y)
            .unwrap_or_else(|_| SMatrix::repeat(f64::NAN))
    }

    /// [`PrescribedPeg::linearization`]'s Jacobian; its time derivative is
    /// kept for [`OdeSystem::time_derivative`] at the same `(t, y)`.
    fn try_jacobian(&self, t: f64, y: &SVector<f64, 7>) -> Result<SMatrix<f64, 7, 7>, ModelError> {
        let (j, rate) = self.linearization(t, y)?;
        *self.rate_memo.borrow_mut() = Some((key(t, y), rate));
        Ok(j)
    }

    /// [`PrescribedPeg::linearization`]'s time derivative (NaN after a
    /// Hertz setup error).
    fn time_derivative(&self, t: f64, y: &SVector<f64, 7>) -> SVector<f64, 7> {
        if let Some((k, rate)) = &*self.rate_memo.borrow()
            && *k == key(t, y)
        {
            return *rate;
        }
        self.linearization(t, y)
            .map_or_else(|_| SVector::repeat(f64::NAN), |(_, rate)| rate)
    }

    fn state_names(&self) -> &'static [&'static str] {
        &["px", "py", "pz", "vx", "vy", "vz", "dissipation"]
    }
}
