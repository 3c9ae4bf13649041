//! The compliant 3-D peg as an ODE system: contact forces at the points of
//! [`super::search`] summed into the wrench of the generated Newton–Euler
//! right-hand side (`pegdyn::generated::compliant_peg_3d::rhs`).
//!
//! At a contact with penetration `δ`, force direction `n` on the peg, point
//! `x_c` and material-point velocity `v_c = v + ω_w × (x_c − p)` (spin
//! included; `ω_w = R ω` in the hole frame):
//!
//! ```text
//! δ̇   = −n·v_c
//! Q_e = k δ^{3/2}                          (Hertz; k from the curvatures or fixed)
//! Q   = max(0, Q_e (1 + α δ̇))              (Hunt–Crossley damping α, s/m)
//! v_t = v_c − (n·v_c) n,   F_t = −μ Q v_t / √(|v_t|² + v_s²)
//! F   = Q n + F_t,   T = (x_c − p) × F     (about the centre of mass)
//! and, for a point with a subtracted col (`super::merge`), the elastic
//! force `−k_c δ_c^{3/2} n_c` at the col point.
//! Ṡ   = (Q − Q_e) δ̇ − F_t·v_t ≥ 0          (damping and friction)
//! ```
//!
//! With a fixed `k`, `T + m g z + Σ (2/5) k δ^{5/2} − W + S` is constant
//! (the force `Q_e n` is `−∂V/∂x` at the minimizing angle). Further
//! generalized forces (a wrist spring–damper, a prescribed frame) add to
//! the same wrench.

use super::curvature;
use super::jacobian;
use super::params::{HertzMode, Peg3dParams};
use super::prune;
use super::search::{ContactPoint, Pair, Search};
use crate::generated::compliant_peg_3d as generated;
use crate::hertz::{EllipticityMethod, HertzContact, HertzError};
use crate::system::OdeSystem;
use nalgebra::{SMatrix, SVector, UnitQuaternion, Vector3};
use std::cell::RefCell;

/// The peg's axis `a = R(q) e_z` of a pose `(p, q)`, `q = (w, i, j, k)`:
/// `a = (2(ik + wj), 2(jk − wi), 1 − 2(i² + j²))`, the third column of the
/// rotation matrix the generated pair functions use.
pub fn axis_of(x: &SVector<f64, 7>) -> Vector3<f64> {
    let (w, i, j, k) = (x[3], x[4], x[5], x[6]);
    Vector3::new(
        2.0 * (i * k + w * j),
        2.0 * (j * k - w * i),
        1.0 - 2.0 * (i * i + j * j),
    )
}

/// The state `(p, q, v, ω_body, W = 0, S = 0)` of a pose and velocities.
pub fn pose_state(
    p: Vector3<f64>,
    q: UnitQuaternion<f64>,
    v: Vector3<f64>,
    omega_body: Vector3<f64>,
) -> SVector<f64, 15> {
    let mut y = SVector::<f64, 15>::zeros();
    y.fixed_rows_mut::<3>(0).copy_from(&p);
    y[3] = q.w;
    y[4] = q.i;
    y[5] = q.j;
    y[6] = q.k;
    y.fixed_rows_mut::<3>(7).copy_from(&v);
    y.fixed_rows_mut::<3>(10).copy_from(&omega_body);
    y
}

/// One evaluated contact: the point and its forces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactForce {
    /// Where and how deep.
    pub contact: ContactPoint,
    /// Normal force `Q` (N).
    pub normal_force: f64,
    /// Friction force on the peg, hole frame (N).
    pub friction: Vector3<f64>,
    /// Hertz stiffness `k` used (N/m^{3/2}).
    pub stiffness: f64,
    /// Elastic energy `(2/5) k δ^{5/2} − (2/5) k_c δ_c^{5/2}` (J), the
    /// second term for the contact's subtracted col ([`super::merge`]).
    pub potential: f64,
    /// Elastic force `k_c δ_c^{3/2}` (N) of the contact's subtracted col,
    /// applied as `−k_c δ_c^{3/2} n_c` at the col point; 0 without a col.
    pub col_force: f64,
}

/// The compliant 3-D peg.
pub struct Peg3d {
    /// The parameters.
    pub params: Peg3dParams,
    p: SVector<f64, 16>,
    searches: RefCell<[Search; Pair::ALL.len()]>,
    error: RefCell<Option<HertzError>>,
}

impl Peg3d {
    /// The system with parameters `params`.
    pub fn new(params: Peg3dParams) -> Peg3d {
        Peg3d {
            p: params.vector(),
            params,
            searches: RefCell::new(Default::default()),
            error: RefCell::new(None),
        }
    }

    /// The generated functions' parameter vector.
    pub fn param_vector(&self) -> &SVector<f64, 16> {
        &self.p
    }

    /// The first Hertz setup error met by the right-hand side (a contact
    /// whose relative curvatures are not positive); the right-hand side
    /// returns NaN from then on, which stops the integrators.
    pub fn error(&self) -> Option<HertzError> {
        self.error.borrow().clone()
    }

    /// The pose `(p, q/|q|)` of a state.
    pub fn pose(y: &SVector<f64, 15>) -> SVector<f64, 7> {
        let mut x = SVector::<f64, 7>::zeros();
        x.fixed_rows_mut::<3>(0).copy_from(&y.fixed_rows::<3>(0));
        let qn = y.fixed_rows::<4>(3).norm();
        for k in 0..4 {
            x[3 + k] = y[3 + k] / qn;
        }
        x
    }

    /// Every contact point of the state, pair by pair.
    pub fn contacts(&self, y: &SVector<f64, 15>) -> Vec<ContactPoint> {
        let x = Self::pose(y);
        let mut out = Vec::new();
        let mut s = self.searches.borrow_mut();
        for (k, pair) in Pair::ALL.iter().enumerate() {
            if prune::can_touch(*pair, &self.params, &x) {
                s[k].find(*pair, &self.params, &x, &self.p, &mut out);
            } else {
                s[k] = Search::default();
            }
        }
        out
    }

    /// The Hertz stiffness at a contact.
    fn stiffness(&self, c: &ContactPoint, x: &SVector<f64, 7>) -> Result<f64, HertzError> {
        match self.params.hertz {
            HertzMode::Fixed(k) => Ok(k),
            HertzMode::Curvature => {
                let centre = Vector3::new(x[0], x[1], x[2]);
                let curv = curvature::at(&self.params, c, &centre, &axis_of(x));
                let (m1, m2) = match c.pair {
                    Pair::EdgeSide => (&self.params.hole_material, &self.params.peg_material),
                    _ => (&self.params.peg_material, &self.params.hole_material),
                };
                Ok(HertzContact::try_new(&curv, m1, m2, EllipticityMethod::Exact)?.stiffness())
            }
        }
    }

    /// Every contact with its forces at state `y`.
    ///
    /// # Errors
    /// A contact whose Hertz setup fails (relative curvature not positive).
    pub fn forces(&self, y: &SVector<f64, 15>) -> Result<Vec<ContactForce>, HertzError> {
        let x = Self::pose(y);
        let centre = Vector3::new(x[0], x[1], x[2]);
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(x[3], x[4], x[5], x[6]));
        let v = Vector3::new(y[7], y[8], y[9]);
        let om = q * Vector3::new(y[10], y[11], y[12]);
        let prm = &self.params;
        let mut out = Vec::new();
        for c in self.contacts(y) {
            let k = self.stiffness(&c, &x)?;
            let d = c.penetration;
            let qe = k * d * d.sqrt();
            let vc = v + om.cross(&(c.point - centre));
            let vn = c.normal.dot(&vc);
            let ddot = -vn;
            let (col_force, col_potential) = match &c.saddle {
                Some(s) => {
                    let at_col = ContactPoint {
                        angle: s.angle,
                        penetration: s.penetration,
                        gradient: s.gradient,
                        normal: s.normal,
                        point: s.point,
                        saddle: None,
                        ..c
                    };
                    let kc = self.stiffness(&at_col, &x)?;
                    let dc = s.penetration;
                    (kc * dc * dc.sqrt(), 0.4 * kc * dc * dc * dc.sqrt())
                }
                None => (0.0, 0.0),
            };
            let qn = (qe * (1.0 + prm.damping * ddot)).max(0.0);
            let vt = vc - c.normal * vn;
            let ft = vt
                * (-prm.friction * qn
                    / (vt.norm_squared() + prm.slip_scale * prm.slip_scale).sqrt());
            out.push(ContactForce {
                contact: c,
                normal_force: qn,
                friction: ft,
                stiffness: k,
                potential: 0.4 * k * d * d * d.sqrt() - col_potential,
                col_force,
            });
        }
        Ok(out)
    }

    /// The contact wrench `(F, T about the centre of mass, Ṡ)` of
    /// `forces` at state `y`.
    pub fn wrench(y: &SVector<f64, 15>, forces: &[ContactForce]) -> SVector<f64, 7> {
        let x = Self::pose(y);
        let centre = Vector3::new(x[0], x[1], x[2]);
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(x[3], x[4], x[5], x[6]));
        let v = Vector3::new(y[7], y[8], y[9]);
        let om = q * Vector3::new(y[10], y[11], y[12]);
        let mut w = SVector::<f64, 7>::zeros();
        for f in forces {
            let c = &f.contact;
            let force = c.normal * f.normal_force + f.friction;
            let arm = c.point - centre;
            let torque = arm.cross(&force);
            let vc = v + om.cross(&arm);
            let ddot = -c.normal.dot(&vc);
            let d = c.penetration;
            let qe = f.stiffness * d * d.sqrt();
            let vt = vc - c.normal * c.normal.dot(&vc);
            for k in 0..3 {
                w[k] += force[k];
                w[3 + k] += torque[k];
            }
            if let Some(s) = &c.saddle {
                // The subtracted col: −k_c δ_c^{3/2} n_c at the col point.
                let back = -s.normal * f.col_force;
                let t = (s.point - centre).cross(&back);
                for k in 0..3 {
                    w[k] += back[k];
                    w[3 + k] += t[k];
                }
            }
            w[6] += (f.normal_force - qe) * ddot - f.friction.dot(&vt);
        }
        w
    }

    /// `T + m g z + Σ (2/5) k δ^{5/2} − W + S` at state `y` (J): constant
    /// along solutions when the stiffness is fixed.
    ///
    /// # Errors
    /// As [`Peg3d::forces`].
    pub fn energy_balance(&self, y: &SVector<f64, 15>) -> Result<f64, HertzError> {
        let (kin, grav) = generated::energy(y, &self.p);
        let pot: f64 = self.forces(y)?.iter().map(|f| f.potential).sum();
        Ok(kin + grav + pot - y[13] + y[14])
    }
}

impl OdeSystem<15> for Peg3d {
    fn rhs(&self, _t: f64, y: &SVector<f64, 15>) -> SVector<f64, 15> {
        match self.forces(y) {
            Ok(f) => generated::rhs(y, &Self::wrench(y, &f), &self.p),
            Err(e) => {
                let mut slot = self.error.borrow_mut();
                if slot.is_none() {
                    *slot = Some(e);
                }
                SVector::repeat(f64::NAN)
            }
        }
    }

    /// The exact Jacobian ([`super::jacobian`]); NaN after a Hertz setup
    /// error, like the right-hand side.
    fn jacobian(&self, _t: f64, y: &SVector<f64, 15>) -> SMatrix<f64, 15, 15> {
        match self.forces(y) {
            Ok(f) => jacobian::of(self, y, &f),
            Err(_) => SMatrix::repeat(f64::NAN),
        }
    }

    fn time_derivative(&self, _t: f64, _y: &SVector<f64, 15>) -> SVector<f64, 15> {
        SVector::zeros()
    }
}
