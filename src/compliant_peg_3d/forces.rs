//! The contacts of a state with their forces: each contact's Hertz setup
//! once per state ([`setups_into`]), then the contact law ([`super::law`])
//! evaluated over all of them at any scalar ([`evaluate`]): at `f64` for
//! the forces of the right-hand side ([`forces`], [`wrench`]), at dual
//! numbers for the exact Jacobian ([`super::jacobian`]), both from the
//! same setups.
//!
//! The contacts come in the order the law needs: the point contacts in
//! the order found, then the rings of the peg's bottom on a flat (a ring's
//! hand-over moment reads the unweighted potential of its pair's points).
//!
//! With the stiffness from the curvatures (`HertzMode::Curvature`), each
//! point adds the force and moment `−(2/5) δ^{5/2} ∂k/∂(pose)`
//! ([`super::stiffness`]). Then `T + m g z + Σ V − W + S` is constant (each
//! force is `−∂V/∂x`: a point's at its minimizing angle, the ring's in
//! closed form).

use super::contact::{ContactPoint, Contacts, Geometry, MAX_CONTACTS, Pair};
use super::face;
use super::frame::{Motion, axis};
use super::law::{self, Col, LawParams, Load, Point};
use super::params::{HertzMode, Peg3dParams};
use super::prune;
use super::stiffness;
use crate::hertz::HertzError;
use crate::scalar::Real;
use nalgebra::{SVector, Vector3};

/// One evaluated contact: the point and its forces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactForce {
    /// Where and how deep.
    pub contact: ContactPoint,
    /// Normal force `Q` (N).
    pub normal_force: f64,
    /// Friction force on the peg, hole frame (N).
    pub friction: Vector3<f64>,
    /// Hertz stiffness `k` used (N/m^{3/2}): weighted like the point's
    /// force; the line stiffness `k_ℓ` (N/m²) of a ring.
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

impl ContactForce {
    /// The contact `contact` with the law's `load` at `f64`.
    pub fn new(contact: ContactPoint, load: &Load<f64>) -> ContactForce {
        ContactForce {
            contact,
            normal_force: load.normal_force,
            friction: load.friction.into(),
            stiffness: load.stiffness,
            potential: load.potential,
            col_force: load.col_force,
            elastic: load.elastic,
            torque: load.torque.into(),
            stiffness_force: load.stiffness_force.into(),
            stiffness_torque: load.stiffness_torque.into(),
        }
    }

    /// The contact's load as the law gives it.
    pub fn load(&self) -> Load<f64> {
        Load {
            normal_force: self.normal_force,
            friction: self.friction.into(),
            stiffness: self.stiffness,
            elastic: self.elastic,
            potential: self.potential,
            col_force: self.col_force,
            torque: self.torque.into(),
            stiffness_force: self.stiffness_force.into(),
            stiffness_torque: self.stiffness_torque.into(),
        }
    }
}

/// A contact with the Hertz data the law needs at its state, set up once
/// per state: the forces ([`forces`]) and the exact Jacobian
/// ([`super::jacobian`]) evaluate the law from the same setups.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setup {
    /// The contact.
    pub contact: ContactPoint,
    /// Hertz stiffness `k` of a point, unweighted (N/m^{3/2}); the line
    /// stiffness `k_ℓ` of a ring (N/m²).
    pub stiffness: f64,
    /// Hertz stiffness `k_c` of the point's subtracted col, unweighted
    /// (N/m^{3/2}); 0 without a col.
    pub col_stiffness: f64,
    /// With [`HertzMode::Curvature`], `(F_k, T_k) = −(2/5) δ^{5/2}
    /// ∂k/∂(p, φ)` of the point less its col's, unweighted (N, N·m).
    pub term: Option<[Vector3<f64>; 2]>,
    /// True for a plane pair's point in the hand-over window of its ring:
    /// its force is weighted by `s` ([`super::face::blend`]).
    pub weighted: bool,
}

/// The setups of one state's contacts, in a fixed-capacity array (no
/// allocation in the right-hand side).
pub type Setups = arrayvec::ArrayVec<Setup, MAX_CONTACTS>;

/// The hand-over weight `s` of the plane pairs' point contacts at pose `x`
/// (where their ring applies).
pub fn point_weight<T: Real>(x: &[T; 7]) -> T {
    let a = axis(x);
    face::blend(a[0] * a[0] + a[1] * a[1]).0
}

/// The stiffness `k` at a contact and, with [`HertzMode::Curvature`],
/// `−(2/5) δ^{5/2} (∂k/∂p, ∂k/∂φ)` ([`stiffness::with_term`]; zero with a
/// fixed stiffness), `c` a point contact or its col.
fn stiffness_and_term(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    c: &ContactPoint,
    x: &SVector<f64, 7>,
) -> Result<(f64, Vector3<f64>, Vector3<f64>), HertzError> {
    match prm.hertz {
        HertzMode::Fixed(k) => Ok((k, Vector3::zeros(), Vector3::zeros())),
        HertzMode::Curvature => stiffness::with_term(prm, p, c, x),
    }
}

/// The setups of `contacts` found at pose `x` (unit quaternion), `p` the
/// generated functions' parameter vector, into `out` (cleared first, and
/// written in place: the array is a few kilobytes): the point contacts in
/// order, then the rings.
///
/// # Errors
/// The first contact (or col) whose Hertz setup fails (relative curvature
/// not positive); `out` then holds the setups before it.
pub fn setups_into(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    x: &SVector<f64, 7>,
    contacts: &Contacts,
    out: &mut Setups,
) -> Result<(), HertzError> {
    let weight = point_weight(&(*x).into());
    // One setup per contact: `out` has the capacity of `contacts`.
    out.clear();
    for c in contacts.iter().filter(|c| !c.ring) {
        let weighted = face::plane(c.pair, prm).is_some()
            && prune::ring_applies(c.pair, prm, x)
            && weight < 1.0;
        let (k, kf, kt) = stiffness_and_term(prm, p, c, x)?;
        let (col_stiffness, term) = match &c.saddle {
            Some(sd) => {
                let at_col = ContactPoint {
                    angle: sd.angle,
                    penetration: sd.penetration,
                    gradient: sd.gradient,
                    normal: sd.normal,
                    point: sd.point,
                    saddle: None,
                    ..*c
                };
                let (kc, cf, ct) = stiffness_and_term(prm, p, &at_col, x)?;
                (kc, [kf - cf, kt - ct])
            }
            None => (0.0, [kf, kt]),
        };
        let _ = out.try_push(Setup {
            contact: *c,
            stiffness: k,
            col_stiffness,
            term: (prm.hertz == HertzMode::Curvature).then_some(term),
            weighted,
        });
    }
    for c in contacts.iter().filter(|c| c.ring) {
        let _ = out.try_push(Setup {
            contact: *c,
            stiffness: face::line_stiffness(prm),
            col_stiffness: 0.0,
            term: None,
            weighted: false,
        });
    }
    Ok(())
}

/// Evaluates the contact law at every contact of `setups` (found at the
/// motion `m`'s pose) at scalar `T`: the geometry of each point and col
/// from `geometry(pair, angle, at)` (`at` its `f64` geometry as found),
/// each ring's from its closed form at `m`'s pose; calls
/// `each(setup, geometry, load, col geometry)` in order.
pub fn evaluate<T: Real>(
    prm: &Peg3dParams,
    law: &LawParams<T>,
    m: &Motion<T>,
    setups: &[Setup],
    geometry: impl Fn(Pair, f64, &Geometry<f64>) -> Geometry<T>,
    mut each: impl FnMut(&Setup, &Geometry<T>, &Load<T>, Option<&Geometry<T>>),
) {
    let c = T::from_f64;
    let weight = point_weight(&m.pose);
    // The unweighted point potential of each plane pair, for the hand-over
    // moment of its ring.
    let mut v_point = [c(0.0); Pair::ALL.len()];
    for st in setups {
        let cp = &st.contact;
        if cp.ring {
            let Some(z0) = face::plane(cp.pair, prm) else {
                continue;
            };
            let Some(r) = face::ring(prm, z0, st.stiffness, &m.pose) else {
                continue;
            };
            let v = v_point[cp.pair.index()];
            let (load, point) = law::ring_load(law, m, &r, z0, weight, v, c(st.stiffness));
            let at = Geometry {
                normal: [c(0.0), c(0.0), c(1.0)],
                point,
                penetration: c(r.depth),
            };
            each(st, &at, &load, None);
        } else {
            let s = if st.weighted { weight } else { c(1.0) };
            let point = Point {
                at: geometry(cp.pair, cp.angle, &cp.geometry()),
                stiffness: c(st.stiffness),
                weight: s,
                col: cp.saddle.map(|sd| Col {
                    at: geometry(cp.pair, sd.angle, &sd.geometry()),
                    stiffness: c(st.col_stiffness),
                }),
                term: st.term.map(|[f, t]| [f.map(c).into(), t.map(c).into()]),
            };
            let load = law::point_load(law, m, &point);
            if st.weighted {
                let k = cp.pair.index();
                v_point[k] = v_point[k] + load.potential / s;
            }
            each(st, &point.at, &load, point.col.as_ref().map(|col| &col.at));
        }
    }
}

/// The contact wrench `(F, T about the centre of mass, Ṡ)` of `setups`
/// (found at the motion `m`'s pose) at scalar `T`: the law of every contact
/// ([`evaluate`], each point's and col's geometry from `geometry`) summed
/// by [`law::add_to_wrench`].
pub fn contact_wrench<T: Real>(
    prm: &Peg3dParams,
    law: &LawParams<T>,
    m: &Motion<T>,
    setups: &[Setup],
    geometry: impl Fn(Pair, f64, &Geometry<f64>) -> Geometry<T>,
) -> [T; 7] {
    let mut w = [T::from_f64(0.0); 7];
    evaluate(prm, law, m, setups, geometry, |_, at, load, col| {
        law::add_to_wrench(&mut w, m, at, load, col)
    });
    w
}

/// Every contact of `setups` with its forces at state `y` (`f64`).
pub fn forces(prm: &Peg3dParams, y: &SVector<f64, 15>, setups: &[Setup]) -> Vec<ContactForce> {
    let m = Motion::of_state(y.as_slice());
    let mut out = Vec::with_capacity(setups.len());
    evaluate(
        prm,
        &LawParams::of(prm),
        &m,
        setups,
        |_, _, at| *at,
        |st, _, load, _| out.push(ContactForce::new(st.contact, load)),
    );
    out
}

/// The contact wrench `(F, T about the centre of mass, Ṡ)` of `forces` at
/// state `y` ([`law::add_to_wrench`] at `f64`): the same as
/// [`contact_wrench`] of their setups.
pub fn wrench(y: &SVector<f64, 15>, forces: &[ContactForce]) -> SVector<f64, 7> {
    let m = Motion::of_state(y.as_slice());
    let mut w = [0.0; 7];
    for f in forces {
        let col = f.contact.saddle.map(|s| s.geometry());
        law::add_to_wrench(&mut w, &m, &f.contact.geometry(), &f.load(), col.as_ref());
    }
    SVector::from(w)
}
