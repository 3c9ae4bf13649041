//! The no-jam margin of a peg in the bore at any scalar ([`Real`]): the
//! load on the peg reduced to its tip, in the tilt plane, against
//! Whitney's parallelogram at the tip's depth.
//!
//! With `a` the peg's axis, `X = (a_x, a_y, 0)/|(a_x, a_y)|` the horizontal
//! direction of its lean and `Z = −e_z` into the hole, a load `(F, M)`
//! (force, moment about the centre of mass) gives
//!
//! ```text
//! M_tip = M + (L/2) a × F,   F_Z = F·Z,   τ = M_tip·(X × Z) = M_tip·(−X_y, X_x, 0)
//! q = (F·X / F_Z,  τ / (r F_Z))
//! margin = least signed distance of q to the edges of Whitney's parallelogram
//!          at depth l ([`whitney_corners`]; positive inside: the peg slides in)
//! ```
//!
//! `None` for a load that does not push the peg in (`F_Z ≤ 0`) or a peg
//! that does not lean (`|(a_x, a_y)| < 10⁻⁹`): there the ratio has no
//! plane.
//!
//! Two loads are read ([`MarginLoad`]): the load applied to the peg (the
//! wrist's force and moment plus gravity), which the scenes report, and
//! the contacts' resultant reversed, `(−F_c, −M_c)`, which equals it less
//! the peg's inertia `(m a, dL/dt)`. An insertion's margin with its
//! gradients in the state and the design parameters is
//! [`Insertion::no_jam_margin_gradient`]: the formula above at dual
//! numbers of the state ([`D`]) and of the design ([`Q`]).
//!
//! Why two: where the peg slides steadily on one contact, the applied
//! load's ratio is set by that contact's friction, so its derivatives
//! along the geometry vanish, but as `F_y s + F_q` they are sums of terms
//! of the wrist's stiffness times the sensitivities (10⁴ per unit) that
//! cancel; the contacts' resultant gives the same ratio from the contact's
//! normal and slip alone (its normal force cancels in the ratio), with
//! derivatives of order one.

use nalgebra::SVector;

use super::design::{Design, N_DESIGN, Q, slots};
use super::forces::contact_wrench;
use super::frame::{Motion, V3, axis, cross, dot, scale};
use super::held::TIME_STEP;
use super::insertion::{Insertion, N_STATE, peg_state};
use super::jacobian::{self, D};
use super::wrist::{Kinematics, load_with};
use crate::hertz::HertzError;
use crate::jamming::diagram::{edge_distances, nearest, whitney_corners};
use crate::scalar::Real;

/// Below this lean `|(a_x, a_y)|` the tilt plane is not defined.
pub const MIN_LEAN: f64 = 1e-9;

/// The load ratio `q = (F_X/F_Z, M_tip/(r F_Z))` of the load `(force,
/// moment about the centre)` on a peg of axis `axis`, half length
/// `half_length` and radius `radius`; `None` where it has no plane (the
/// module documentation).
pub fn load_ratio<T: Real>(
    axis: &V3<T>,
    half_length: T,
    force: &V3<T>,
    moment: &V3<T>,
    radius: T,
) -> Option<[T; 2]> {
    let lean = axis[0].hypot(axis[1]);
    if lean.to_f64() < MIN_LEAN {
        return None;
    }
    let zero = T::from_f64(0.0);
    let x = [axis[0] / lean, axis[1] / lean, zero];
    let fz = -force[2];
    if fz.to_f64() <= 0.0 {
        return None;
    }
    let arm = scale(axis, half_length);
    let c = cross(&arm, force);
    let tip = [moment[0] + c[0], moment[1] + c[1], moment[2] + c[2]];
    let tau = dot(&tip, &[-x[1], x[0], zero]);
    Some([dot(force, &x) / fz, tau / (radius * fz)])
}

/// The signed distance of the load ratio `q` to Whitney's parallelogram
/// of friction `friction`, peg radius `radius` (m) at depth `depth` (m)
/// (positive inside), and the index of the nearest edge.
pub fn margin<T: Real>(q: [T; 2], friction: T, radius: T, depth: T) -> (T, usize) {
    let e = edge_distances(&whitney_corners(friction, radius, depth), q);
    let k = nearest(&e);
    (e[k], k)
}

/// The distance (in ratio units) between the nearest and the next nearest
/// edge of [`margin`]: where it is zero the margin has a corner.
pub fn edge_gap(q: [f64; 2], friction: f64, radius: f64, depth: f64) -> f64 {
    let mut e = edge_distances(&whitney_corners(friction, radius, depth), q);
    e.sort_by(f64::total_cmp);
    e[1] - e[0]
}

/// A margin at `f64` and the gap to its next edge ([`edge_gap`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Margin {
    /// The signed distance to the nearest edge (positive inside).
    pub value: f64,
    /// How much farther the next nearest edge is.
    pub edge_gap: f64,
}

/// The load the no-jam margin reads (module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MarginLoad {
    /// The wrist's force and moment plus gravity: the load applied to the
    /// peg.
    Applied,
    /// The contacts' resultant reversed: the applied load less the peg's
    /// inertia.
    Contacts,
}

/// A margin with its gradients: the value, `∂/∂y` (16, the work
/// integrals' entries zero), `∂/∂q` and the partial rate in time `∂/∂t`
/// (the robot frame's motion moves the applied load; zero for the
/// contacts').
pub type MarginGradients = (f64, SVector<f64, N_STATE>, SVector<f64, N_DESIGN>, f64);

/// The margin of a load at any scalar: the peg state's pose `pose`, half
/// length, radius, friction, the weight `m g` (added for the applied
/// load) and the load `(force, moment about the centre)`.
struct Peg<T> {
    pose: [T; 7],
    half: T,
    radius: T,
    friction: T,
    weight: T,
}

impl<T: Real> Peg<T> {
    /// The ratio and the depth of the load `(force, moment)`.
    fn ratio(&self, force: V3<T>, moment: V3<T>) -> Option<([T; 2], T)> {
        let a = axis(&self.pose);
        let q = load_ratio(&a, self.half, &force, &moment, self.radius)?;
        Some((q, -(self.pose[2] - self.half * a[2])))
    }

    fn margin(&self, force: V3<T>, moment: V3<T>) -> Option<T> {
        let (q, depth) = self.ratio(force, moment)?;
        Some(margin(q, self.friction, self.radius, depth).0)
    }
}

impl Peg<f64> {
    fn margin_f64(&self, force: V3<f64>, moment: V3<f64>) -> Option<Margin> {
        let (q, depth) = self.ratio(force, moment)?;
        Some(Margin {
            value: margin(q, self.friction, self.radius, depth).0,
            edge_gap: edge_gap(q, self.friction, self.radius, depth),
        })
    }
}

impl Insertion {
    /// The no-jam margin of the load `load` at `(t, y)` (module
    /// documentation); `None` where the ratio has no plane or the peg is
    /// not held.
    ///
    /// # Errors
    /// As [`super::Peg3d::setups`].
    pub fn no_jam_margin(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
        load: MarginLoad,
    ) -> Result<Option<Margin>, HertzError> {
        let ys = peg_state(y);
        let prm = &self.peg.params;
        let peg = Peg {
            pose: Motion::of_state(ys.as_slice()).pose,
            half: 0.5 * prm.length,
            radius: prm.peg_radius(),
            friction: prm.friction,
            weight: prm.mass * prm.gravity,
        };
        let Some(h) = self.held else { return Ok(None) };
        Ok(match load {
            MarginLoad::Applied => {
                let kin = Kinematics::of_state(ys.as_slice());
                let l = h.wrist.load_of(prm.length, &kin, &h.robot.frame(t));
                let f = [l.force[0], l.force[1], l.force[2] - peg.weight];
                peg.margin_f64(f, l.moment)
            }
            MarginLoad::Contacts => {
                let w = self.peg.with_setups(&ys, |setups| {
                    let m = Motion::of_state(ys.as_slice());
                    contact_wrench(
                        prm,
                        &super::law::LawParams::of(prm),
                        &m,
                        setups,
                        |_, _, at| *at,
                    )
                })?;
                peg.margin_f64([-w[0], -w[1], -w[2]], [-w[3], -w[4], -w[5]])
            }
        })
    }

    /// [`Insertion::no_jam_margin`] with its gradients in the state and in
    /// the design parameters `d` and its partial rate in time (the applied
    /// load's: central differences with the steps [`TIME_STEP`] and half
    /// of it, Richardson-extrapolated), at the contacts the right-hand
    /// side found at `y`.
    ///
    /// # Errors
    /// As [`super::Peg3d::setups`].
    pub fn no_jam_margin_gradient(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
        d: &Design,
        load: MarginLoad,
    ) -> Result<Option<MarginGradients>, HertzError> {
        let Some(h) = self.held else { return Ok(None) };
        let ys = peg_state(y);
        let prm = &self.peg.params;
        let yd = jacobian::seeded(&ys);
        let md = Motion::of_state(&yd);
        let yq: [Q; 13] = std::array::from_fn(|k| Q::constant(y[k]));
        let mq = Motion::of_state(&yq);
        let pq = d.params();
        let c = D::from_f64;
        let peg_d = Peg {
            pose: md.pose,
            half: c(0.5 * prm.length),
            radius: c(prm.peg_radius()),
            friction: c(prm.friction),
            weight: c(prm.mass * prm.gravity),
        };
        let peg_q = Peg {
            pose: mq.pose,
            half: Q::from_f64(0.5) * pq.L,
            radius: pq.r,
            friction: d.law.friction,
            weight: pq.m * pq.g,
        };
        let (by_y, by_q, rate) = match load {
            MarginLoad::Applied => {
                let kd = Kinematics::of_state(&yd);
                let ld = h.wrist.load_of(prm.length, &kd, &h.robot.frame(t));
                let kq = Kinematics::of_state(&yq);
                let lq = load_with(&d.wrist, pq.L, &kq, &h.robot.terms_of(t, &d.robot));
                let at = |t: f64| {
                    self.no_jam_margin(t, y, load)
                        .ok()
                        .flatten()
                        .map(|m| m.value)
                };
                let central = |h: f64| match (at(t + h), at(t - h)) {
                    (Some(up), Some(down)) => Some((up - down) / (2.0 * h)),
                    _ => None,
                };
                let rate = match (central(0.5 * TIME_STEP), central(TIME_STEP)) {
                    (Some(half), Some(full)) => (4.0 * half - full) / 3.0,
                    _ => return Ok(None),
                };
                let lift = |f: V3<D>, w: D| [f[0], f[1], f[2] - w];
                let lift_q = |f: V3<Q>, w: Q| [f[0], f[1], f[2] - w];
                (
                    peg_d.margin(lift(ld.force, peg_d.weight), ld.moment),
                    peg_q.margin(lift_q(lq.force, peg_q.weight), lq.moment),
                    rate,
                )
            }
            MarginLoad::Contacts => self.peg.with_setups(&ys, |setups| {
                let wd = jacobian::wrench_dual(prm, self.peg.param_vector(), &yd, setups);
                let x = SVector::<Q, 7>::from(mq.pose);
                let wq = contact_wrench(prm, &d.law, &mq, setups, |pair, angle, _| {
                    pair.at_stationary(&x, angle, &d.p)
                });
                let neg = |w: &[D; 7]| ([-w[0], -w[1], -w[2]], [-w[3], -w[4], -w[5]]);
                let neg_q = |w: &[Q; 7]| ([-w[0], -w[1], -w[2]], [-w[3], -w[4], -w[5]]);
                let (fd, md_) = neg(&wd);
                let (fq, mq_) = neg_q(&wq);
                (peg_d.margin(fd, md_), peg_q.margin(fq, mq_), 0.0)
            })?,
        };
        let (Some(by_y), Some(by_q)) = (by_y, by_q) else {
            return Ok(None);
        };
        let g_y = SVector::from_fn(|i, _| if i < 13 { by_y.d[i] } else { 0.0 });
        Ok(Some((by_y.v, g_y, slots(&by_q), rate)))
    }
}
