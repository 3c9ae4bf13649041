//! The contact law of the compliant 3-D peg, written once for any scalar
//! ([`Real`]): the right-hand side evaluates it at `f64`, the exact
//! Jacobian at dual numbers of the state ([`super::jacobian`]), and its
//! coefficients, stiffnesses and geometry are scalars too, so that a dual
//! number can carry a parameter's derivative through it.
//!
//! At a point contact with penetration `δ`, force direction `n` on the
//! peg, point `x_c` and material-point velocity `v_c = v + ω × (x_c − p)`
//! (spin included; `ω = R ω_body` in the hole frame):
//!
//! ```text
//! δ̇   = −n·v_c
//! Q_e = s k δ^{3/2}                     (Hertz; s the hand-over weight of a plane pair's point, else 1)
//! Q   = max(0, Q_e (1 + α δ̇))           (Hunt–Crossley damping α, s/m)
//! v_t = v_c − (n·v_c) n,   F_t = −μ Q v_t / √(|v_t|² + v_s²)      (regularized Coulomb)
//! V   = (2/5) s k δ^{5/2} − (2/5) s k_c δ_c^{5/2}
//! F   = Q n + F_t − s k_c δ_c^{3/2} n_c + s F_k
//! T   = (x_c − p) × (Q n + F_t) + (x_col − p) × (−s k_c δ_c^{3/2} n_c) + s T_k
//! Ṡ   = (Q − Q_e) δ̇ − F_t·v_t ≥ 0
//! ```
//!
//! with, for a point whose overlap with the next point of its pair is
//! connected ([`super::merge`]), the elastic force `−s k_c δ_c^{3/2} n_c`
//! of the subtracted col at the col point (no damping, no friction), and,
//! with the stiffness from the curvatures, the force and moment
//! `(F_k, T_k) = −(2/5) δ^{5/2} ∂k/∂(p, φ)` of the stiffness's variation
//! with the pose, less the col's ([`super::stiffness`]).
//!
//! The distributed ring of the peg's bottom on a flat ([`super::face`])
//! has `Q_e = (1 − s) P` and `V = (1 − s) V_ring`, along `e_z` at its
//! centre of pressure, with damping and friction as above, and adds the
//! hand-over's pure moment `M = 2 a_z s′(u) (V_point − V_ring) (a × e_z)`.
//!
//! The operations keep the order of the right-hand side's `f64` form
//! ([`super::frame`]), so the right-hand side is the same to the last bit.

use super::contact::Geometry;
use super::face::{self, Ring};
use super::frame::{Motion, V3, add, cross, dot, scale, sub};
use super::params::Peg3dParams;
use crate::scalar::Real;

/// The coefficients of the contact law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LawParams<T> {
    /// Coulomb friction coefficient `μ`.
    pub friction: T,
    /// Velocity scale `v_s` of the regularized sign (m/s).
    pub slip_scale: T,
    /// Hunt–Crossley damping `α` (s/m).
    pub damping: T,
}

impl<T: Real> LawParams<T> {
    /// The coefficients of `prm`, as constants of `T`.
    pub fn of(prm: &Peg3dParams) -> LawParams<T> {
        LawParams {
            friction: T::from_f64(prm.friction),
            slip_scale: T::from_f64(prm.slip_scale),
            damping: T::from_f64(prm.damping),
        }
    }
}

/// A point contact as the law sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point<T> {
    /// Where and how deep.
    pub at: Geometry<T>,
    /// Hertz stiffness `k` (N/m^{3/2}), unweighted.
    pub stiffness: T,
    /// Hand-over weight `s` (1 except for a plane pair's point at small
    /// tilt, [`super::face::blend`]).
    pub weight: T,
    /// The subtracted col, if any.
    pub col: Option<Col<T>>,
    /// `(F_k, T_k)` of the curvature stiffness less the col's, unweighted
    /// (N, N·m); `None` with a fixed stiffness.
    pub term: Option<[V3<T>; 2]>,
}

/// The col of a [`Point`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Col<T> {
    /// Where and how deep the col is.
    pub at: Geometry<T>,
    /// Its Hertz stiffness `k_c` (N/m^{3/2}), unweighted.
    pub stiffness: T,
}

/// What the law gives at one contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Load<T> {
    /// Normal force `Q` (N).
    pub normal_force: T,
    /// Friction force `F_t` on the peg (N).
    pub friction: V3<T>,
    /// Stiffness used: `s k` of a point (N/m^{3/2}), `k_ℓ` of a ring
    /// (N/m²).
    pub stiffness: T,
    /// Elastic normal force `Q_e` (N).
    pub elastic: T,
    /// Elastic energy `V` (J).
    pub potential: T,
    /// The col's elastic force `s k_c δ_c^{3/2}` (N); 0 without a col.
    pub col_force: T,
    /// Pure moment `M` (N·m): the ring's hand-over moment, else 0.
    pub torque: V3<T>,
    /// `s F_k` (N); 0 with a fixed stiffness.
    pub stiffness_force: V3<T>,
    /// `s T_k` (N·m); 0 with a fixed stiffness.
    pub stiffness_torque: V3<T>,
}

/// `max(x, 0)`, 0 for NaN (as `f64::max(x, 0.0)`).
fn positive_part<T: Real>(x: T) -> T {
    if x.to_f64() > 0.0 {
        x
    } else {
        T::from_f64(0.0)
    }
}

/// The normal force `Q = max(0, Q_e (1 − α n·v_c))` and the regularized
/// friction `F_t = −μ Q v_t / √(|v_t|² + v_s²)`, `v_t = v_c − (n·v_c) n`,
/// of elastic force `qe` at force direction `n` and material-point
/// velocity `vc`.
pub fn normal_and_friction<T: Real>(
    law: &LawParams<T>,
    n: &V3<T>,
    qe: T,
    vc: &V3<T>,
) -> (T, V3<T>) {
    let vn = dot(n, vc);
    let q = positive_part(qe * (T::from_f64(1.0) - law.damping * vn));
    let vt = sub(vc, &scale(n, vn));
    let ft = scale(
        &vt,
        -law.friction * q / (dot(&vt, &vt) + law.slip_scale * law.slip_scale).sqrt(),
    );
    (q, ft)
}

/// The [`Load`] of a point contact at the peg's motion `m`.
pub fn point_load<T: Real>(law: &LawParams<T>, m: &Motion<T>, pt: &Point<T>) -> Load<T> {
    let c = T::from_f64;
    let (s, k, d) = (pt.weight, pt.stiffness, pt.at.penetration);
    let (col_force, col_potential) = match &pt.col {
        Some(col) => {
            let kc = s * col.stiffness;
            let dc = col.at.penetration;
            (kc * dc * dc.sqrt(), c(0.4) * kc * dc * dc * dc.sqrt())
        }
        None => (c(0.0), c(0.0)),
    };
    let potential = c(0.4) * s * k * d * d * d.sqrt() - col_potential;
    let stiffness = s * k;
    let elastic = s * k * d * d.sqrt();
    let vc = m.point_velocity(&pt.at.point);
    let (normal_force, friction) = normal_and_friction(law, &pt.at.normal, elastic, &vc);
    let zero = [c(0.0); 3];
    let [stiffness_force, stiffness_torque] = match &pt.term {
        Some([f, t]) => [scale(f, s), scale(t, s)],
        None => [zero, zero],
    };
    Load {
        normal_force,
        friction,
        stiffness,
        elastic,
        potential,
        col_force,
        torque: zero,
        stiffness_force,
        stiffness_torque,
    }
}

/// The [`Load`] of the ring `ring` on the plane `z0` (m) at the peg's
/// motion `m`, and its point (the centre of pressure, m): `s` the plane
/// pair's point weight, `v_point` the pair's unweighted point potential
/// (J), `kl` the line stiffness (N/m²).
pub fn ring_load<T: Real>(
    law: &LawParams<T>,
    m: &Motion<T>,
    ring: &Ring<T>,
    z0: f64,
    s: T,
    v_point: T,
    kl: T,
) -> (Load<T>, V3<T>) {
    let c = T::from_f64;
    let point = face::centre_of_pressure(&m.pose, ring, z0);
    let elastic = (c(1.0) - s) * ring.force;
    let potential = (c(1.0) - s) * ring.potential;
    let vc = m.point_velocity(&point);
    let ez = [c(0.0), c(0.0), c(1.0)];
    let (normal_force, friction) = normal_and_friction(law, &ez, elastic, &vc);
    let zero = [c(0.0); 3];
    let load = Load {
        normal_force,
        friction,
        stiffness: kl,
        elastic,
        potential,
        col_force: c(0.0),
        torque: face::blend_moment(&ring.axis, ring.u, v_point, ring.potential),
        stiffness_force: zero,
        stiffness_torque: zero,
    };
    (load, point)
}

/// Adds a contact's wrench `(F, T about the centre of mass, Ṡ)` of the
/// module documentation to `w`: the load `load` at `at` (force direction
/// and point) and, with a col, the col's elastic force at `col`.
pub fn add_to_wrench<T: Real>(
    w: &mut [T; 7],
    m: &Motion<T>,
    at: &Geometry<T>,
    load: &Load<T>,
    col: Option<&Geometry<T>>,
) {
    let n = &at.normal;
    let force = add(&scale(n, load.normal_force), &load.friction);
    let arm = sub(&at.point, &m.centre);
    let torque = cross(&arm, &force);
    let vc = add(&m.velocity, &cross(&m.omega, &arm));
    let ddot = -dot(n, &vc);
    let vt = sub(&vc, &scale(n, dot(n, &vc)));
    for k in 0..3 {
        w[k] = w[k] + force[k];
        w[3 + k] = w[3 + k] + (torque[k] + load.torque[k]);
    }
    if let Some(col) = col {
        // The subtracted col: −s k_c δ_c^{3/2} n_c at the col point.
        let back = scale(&col.normal.map(|v| -v), load.col_force);
        let t = cross(&sub(&col.point, &m.centre), &back);
        for k in 0..3 {
            w[k] = w[k] + back[k];
            w[3 + k] = w[3 + k] + t[k];
        }
    }
    let (sf, st) = (&load.stiffness_force, &load.stiffness_torque);
    if sf.iter().chain(st).any(|v| v.to_f64() != 0.0) {
        // −(2/5) δ^{5/2} ∂k/∂(pose) of the curvature stiffness.
        for k in 0..3 {
            w[k] = w[k] + sf[k];
            w[3 + k] = w[3 + k] + st[k];
        }
    }
    w[6] = w[6] + ((load.normal_force - load.elastic) * ddot - dot(&load.friction, &vt));
}
