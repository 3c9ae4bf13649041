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
//! F_k = −(2/5) δ^{5/2} ∂k/∂p,  T_k = −(2/5) δ^{5/2} ∂k/∂φ   (k from the curvatures)
//! Q   = max(0, Q_e (1 + α δ̇))              (Hunt–Crossley damping α, s/m)
//! v_t = v_c − (n·v_c) n,   F_t = −μ Q v_t / √(|v_t|² + v_s²)
//! F   = Q n + F_t,   T = (x_c − p) × F     (about the centre of mass)
//! and, for a point with a subtracted col (`super::merge`), the elastic
//! force `−k_c δ_c^{3/2} n_c` at the col point.
//! Ṡ   = (Q − Q_e) δ̇ − F_t·v_t ≥ 0          (damping and friction)
//! ```
//!
//! On a flat at small tilt the peg's bottom is the distributed ring of
//! [`super::face`]: `Q_e` is its load `P` weighted by `1 − s`, applied
//! along `e_z` at its centre of pressure, the plane pair's points are
//! weighted by `s`, and the hand-over moment is added as a pure moment
//! ([`ContactForce::torque`]).
//!
//! With the stiffness from the curvatures, each point adds the force and
//! moment `−(2/5) δ^{5/2} ∂k/∂(pose)` ([`super::stiffness`]). Then
//! `T + m g z + Σ V − W + S` is constant (each force is `−∂V/∂x`: a
//! point's at its minimizing angle, the ring's in closed form). Further
//! generalized forces (a wrist spring–damper, a prescribed frame) add to
//! the same wrench.

use super::face;
use super::jacobian;
use super::params::{HertzMode, Peg3dParams};
use super::prune;
use super::search::{ContactPoint, Pair, Search};
use super::stiffness;
use crate::generated::compliant_peg_3d as generated;
use crate::hertz::HertzError;
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
    /// Elastic part `Q_e` of the normal force (N), before damping: the
    /// (weighted) `k δ^{3/2}` of a point, the weighted ring load `P` of
    /// [`super::face`].
    pub elastic: f64,
    /// A pure moment (N·m, hole frame) added to the contact's wrench: the
    /// hand-over moment of [`super::face::blend_moment`] on a ring; zero
    /// otherwise.
    pub torque: Vector3<f64>,
    /// With [`HertzMode::Curvature`], the force `−(2/5) δ^{5/2} ∂k/∂p`
    /// (N, hole frame, through the centre of mass) of the stiffness's
    /// variation with the pose ([`super::stiffness`]), weighted like the
    /// point and less its col's; zero otherwise. Not part of
    /// [`ContactForce::normal_force`].
    pub stiffness_force: Vector3<f64>,
    /// The matching moment `−(2/5) δ^{5/2} ∂k/∂φ` (N·m, hole frame, `φ` a
    /// rotation about the centre of mass); zero with a fixed stiffness.
    pub stiffness_torque: Vector3<f64>,
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

    /// Every contact point of the state, pair by pair: the point contacts
    /// of each pair's search, then, for the block's top face and the bore
    /// bottom at small tilt, the distributed ring of [`super::face`] (the
    /// point search is skipped where the ring carries the flat alone).
    pub fn contacts(&self, y: &SVector<f64, 15>) -> Vec<ContactPoint> {
        let x = Self::pose(y);
        let mut out = Vec::new();
        let mut s = self.searches.borrow_mut();
        for (k, pair) in Pair::ALL.iter().enumerate() {
            let ring = prune::ring_applies(*pair, &self.params, &x);
            let weight = if ring { self.point_weight(&x) } else { 1.0 };
            if weight > 0.0 && prune::can_touch(*pair, &self.params, &x) {
                s[k].find(*pair, &self.params, &x, &self.p, &mut out);
            } else {
                s[k] = Search::default();
            }
            if ring && weight < 1.0 {
                out.extend(self.ring_contact(*pair, &x));
            }
        }
        out
    }

    /// The hand-over weight `s` of the plane pairs' point contacts at pose
    /// `x` (where their ring applies).
    fn point_weight(&self, x: &SVector<f64, 7>) -> f64 {
        let a = axis_of(x);
        face::blend(a.x * a.x + a.y * a.y).0
    }

    /// The ring of a plane pair at pose `x`, as a contact point.
    fn ring_contact(&self, pair: Pair, x: &SVector<f64, 7>) -> Option<ContactPoint> {
        let z0 = face::plane(pair, &self.params)?;
        let xs: [f64; 7] = (*x).into();
        let r = face::ring(&self.params, z0, face::line_stiffness(&self.params), &xs)?;
        let cop = face::centre_of_pressure(&xs, &r, z0);
        Some(ContactPoint {
            pair,
            angle: r.angle,
            penetration: r.depth,
            gradient: pair.eval(x, r.angle, &self.p).grad,
            normal: Vector3::z(),
            point: Vector3::new(cop[0], cop[1], cop[2]),
            saddle: None,
            ring: true,
        })
    }

    /// The stiffness `k` at a contact and, with [`HertzMode::Curvature`],
    /// `−(2/5) δ^{5/2} (∂k/∂p, ∂k/∂φ)` ([`stiffness::with_term`]; zero with
    /// a fixed stiffness), `c` a point contact or its col.
    fn stiffness_and_term(
        &self,
        c: &ContactPoint,
        x: &SVector<f64, 7>,
    ) -> Result<(f64, Vector3<f64>, Vector3<f64>), HertzError> {
        match self.params.hertz {
            HertzMode::Fixed(k) => Ok((k, Vector3::zeros(), Vector3::zeros())),
            HertzMode::Curvature => stiffness::with_term(&self.params, &self.p, c, x),
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
        let contacts = self.contacts(y);
        let weight = self.point_weight(&x);
        let mut out = Vec::with_capacity(contacts.len());
        // Unweighted point potential of each plane pair, for the hand-over
        // moment of its ring.
        let mut v_point = [0.0; Pair::ALL.len()];
        let mut rings = Vec::new();
        for c in contacts {
            if c.ring {
                rings.push(c);
                continue;
            }
            let blended = face::plane(c.pair, prm).is_some()
                && prune::ring_applies(c.pair, prm, &x)
                && weight < 1.0;
            let s = if blended { weight } else { 1.0 };
            let (k, mut kf, mut kt) = self.stiffness_and_term(&c, &x)?;
            let d = c.penetration;
            let vc = v + om.cross(&(c.point - centre));
            let (col_force, col_potential) = match &c.saddle {
                Some(sd) => {
                    let at_col = ContactPoint {
                        angle: sd.angle,
                        penetration: sd.penetration,
                        gradient: sd.gradient,
                        normal: sd.normal,
                        point: sd.point,
                        saddle: None,
                        ..c
                    };
                    let (kc1, cf, ct) = self.stiffness_and_term(&at_col, &x)?;
                    let kc = s * kc1;
                    let dc = sd.penetration;
                    kf -= cf;
                    kt -= ct;
                    (kc * dc * dc.sqrt(), 0.4 * kc * dc * dc * dc.sqrt())
                }
                None => (0.0, 0.0),
            };
            let potential = 0.4 * s * k * d * d * d.sqrt() - col_potential;
            if blended {
                v_point[Pair::ALL.iter().position(|p| *p == c.pair).unwrap_or(0)] += potential / s;
            }
            let mut f =
                self.contact_force(c, s * k, s * k * d * d.sqrt(), vc, potential, col_force);
            if self.params.hertz == HertzMode::Curvature {
                f.stiffness_force = kf * s;
                f.stiffness_torque = kt * s;
            }
            out.push(f);
        }
        for c in rings {
            let Some(z0) = face::plane(c.pair, prm) else {
                continue;
            };
            let xs: [f64; 7] = x.into();
            let kl = face::line_stiffness(prm);
            let Some(r) = face::ring(prm, z0, kl, &xs) else {
                continue;
            };
            let vc = v + om.cross(&(c.point - centre));
            let idx = Pair::ALL.iter().position(|p| *p == c.pair).unwrap_or(0);
            let mut f = self.contact_force(
                c,
                kl,
                (1.0 - weight) * r.force,
                vc,
                (1.0 - weight) * r.potential,
                0.0,
            );
            f.torque = face::blend_moment(&r.axis, r.u, v_point[idx], r.potential);
            out.push(f);
        }
        Ok(out)
    }

    /// A contact's forces from its elastic normal force `qe` (N):
    /// Hunt–Crossley damping with the material point's velocity `vc` and
    /// regularized Coulomb friction.
    fn contact_force(
        &self,
        c: ContactPoint,
        stiffness: f64,
        qe: f64,
        vc: Vector3<f64>,
        potential: f64,
        col_force: f64,
    ) -> ContactForce {
        let prm = &self.params;
        let vn = c.normal.dot(&vc);
        let qn = (qe * (1.0 - prm.damping * vn)).max(0.0);
        let vt = vc - c.normal * vn;
        let ft = vt
            * (-prm.friction * qn / (vt.norm_squared() + prm.slip_scale * prm.slip_scale).sqrt());
        ContactForce {
            contact: c,
            normal_force: qn,
            friction: ft,
            stiffness,
            potential,
            col_force,
            elastic: qe,
            torque: Vector3::zeros(),
            stiffness_force: Vector3::zeros(),
            stiffness_torque: Vector3::zeros(),
        }
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
            let qe = f.elastic;
            let vt = vc - c.normal * c.normal.dot(&vc);
            for k in 0..3 {
                w[k] += force[k];
                w[3 + k] += torque[k] + f.torque[k];
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
            if f.stiffness_force != Vector3::zeros() || f.stiffness_torque != Vector3::zeros() {
                // −(2/5) δ^{5/2} ∂k/∂(pose) of the curvature stiffness.
                for k in 0..3 {
                    w[k] += f.stiffness_force[k];
                    w[3 + k] += f.stiffness_torque[k];
                }
            }
            w[6] += (f.normal_force - qe) * ddot - f.friction.dot(&vt);
        }
        w
    }

    /// `T + m g z + Σ (2/5) k δ^{5/2} − W + S` at state `y` (J): constant
    /// along solutions.
    ///
    /// # Errors
    /// As [`Peg3d::forces`].
    pub fn energy_balance(&self, y: &SVector<f64, 15>) -> Result<f64, HertzError> {
        let e = generated::energy(y, &self.p);
        let pot: f64 = self.forces(y)?.iter().map(|f| f.potential).sum();
        Ok(e.kinetic + e.gravity + pot - y[13] + y[14])
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

    fn state_names(&self) -> &'static [&'static str] {
        &generated::Y_NAMES
    }
}
