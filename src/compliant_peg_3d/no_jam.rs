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
//! numbers of the state ([`jacobian::D`]) and of the design ([`Q`]).
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
use super::held::time_partial;
use super::insertion::{Insertion, N_STATE, peg_state};
use super::jacobian;
use super::params::Peg3dParams;
use super::wrist::{Kinematics, load_with};
use crate::hertz::HertzError;
use crate::jamming::diagram::{edge_distances, margin_of, whitney_corners};
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
    margin_of(&whitney_corners(friction, radius, depth), q)
}

/// A margin at `f64` and the gap to its next edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Margin {
    /// The signed distance to the nearest edge (positive inside).
    pub value: f64,
    /// How much farther the next nearest edge is (in ratio units): where
    /// it is zero the margin has a corner.
    pub edge_gap: f64,
}

impl Margin {
    /// The margin of the load ratio `q` as [`margin`], with its gap.
    pub fn of(q: [f64; 2], friction: f64, radius: f64, depth: f64) -> Margin {
        let mut e = edge_distances(&whitney_corners(friction, radius, depth), q);
        e.sort_by(f64::total_cmp);
        Margin {
            value: e[0],
            edge_gap: e[1] - e[0],
        }
    }
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

/// The force of a wrist load with the weight `m g` added (hole frame,
/// `z` up).
fn with_weight<T: Real>(f: &V3<T>, weight: T) -> V3<T> {
    [f[0], f[1], f[2] - weight]
}

/// The load `(−F_c, −M_c)` of a contact wrench `(F_c, M_c, Ṡ)`.
fn reversed<T: Real>(w: &[T; 7]) -> (V3<T>, V3<T>) {
    ([-w[0], -w[1], -w[2]], [-w[3], -w[4], -w[5]])
}

/// The peg's quantities the margin reads, at any scalar: its pose, half
/// length, radius, friction and weight `m g`.
struct Peg<T> {
    pose: [T; 7],
    half: T,
    radius: T,
    friction: T,
    weight: T,
}

impl<T: Real> Peg<T> {
    /// The pose `pose` with the parameters `prm` as constants.
    fn constants(pose: [T; 7], prm: &Peg3dParams) -> Peg<T> {
        let c = T::from_f64;
        Peg {
            pose,
            half: c(0.5 * prm.length),
            radius: c(prm.peg_radius()),
            friction: c(prm.friction),
            weight: c(prm.mass * prm.gravity),
        }
    }

    /// The ratio and the depth of the load `(force, moment)`.
    fn ratio(&self, force: &V3<T>, moment: &V3<T>) -> Option<([T; 2], T)> {
        let a = axis(&self.pose);
        let q = load_ratio(&a, self.half, force, moment, self.radius)?;
        Some((q, -(self.pose[2] - self.half * a[2])))
    }

    fn margin(&self, (force, moment): (V3<T>, V3<T>)) -> Option<T> {
        let (q, depth) = self.ratio(&force, &moment)?;
        Some(margin(q, self.friction, self.radius, depth).0)
    }
}

impl Peg<f64> {
    fn margin_f64(&self, (force, moment): (V3<f64>, V3<f64>)) -> Option<Margin> {
        let (q, depth) = self.ratio(&force, &moment)?;
        Some(Margin::of(q, self.friction, self.radius, depth))
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
        let Some(h) = self.held else { return Ok(None) };
        let ys = peg_state(y);
        let prm = &self.peg.params;
        let peg = Peg::constants(Motion::of_state(ys.as_slice()).pose, prm);
        Ok(peg.margin_f64(match load {
            MarginLoad::Applied => {
                let kin = Kinematics::of_state(ys.as_slice());
                let l = h.wrist.load_of(prm.length, &kin, &h.robot.frame(t));
                (with_weight(&l.force, peg.weight), l.moment)
            }
            MarginLoad::Contacts => reversed(&self.peg.contact_wrench(&ys)?.into()),
        }))
    }

    /// [`Insertion::no_jam_margin`] with its gradients in the state and in
    /// the design parameters `d` and its partial rate in time (the applied
    /// load's, [`time_partial`]), at the contacts the right-hand side
    /// found at `y`.
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
        let yq: [Q; 13] = std::array::from_fn(|k| Q::constant(y[k]));
        let mq = Motion::of_state(&yq);
        let pq = d.params();
        let peg_d = Peg::constants(Motion::of_state(&yd).pose, prm);
        let peg_q = Peg {
            pose: mq.pose,
            half: Q::from_f64(0.5) * pq.L,
            radius: pq.r,
            friction: d.law.friction,
            weight: pq.m * pq.g,
        };
        let (by_y, by_q, rate) = match load {
            MarginLoad::Applied => {
                let ld = h
                    .wrist
                    .load_of(prm.length, &Kinematics::of_state(&yd), &h.robot.frame(t));
                let kq = Kinematics::of_state(&yq);
                let lq = load_with(&d.wrist, pq.L, &kq, &h.robot.terms_of(t, &d.robot));
                let at = |t: f64| {
                    self.no_jam_margin(t, y, load)
                        .ok()
                        .flatten()
                        .map_or(f64::NAN, |m| m.value)
                };
                let rate = time_partial(t, at);
                if !rate.is_finite() {
                    return Ok(None);
                }
                (
                    peg_d.margin((with_weight(&ld.force, peg_d.weight), ld.moment)),
                    peg_q.margin((with_weight(&lq.force, peg_q.weight), lq.moment)),
                    rate,
                )
            }
            MarginLoad::Contacts => {
                let wd = self.peg.contact_wrench_dual(&ys)?;
                let x = SVector::<Q, 7>::from(mq.pose);
                let wq = self.peg.with_setups(&ys, |setups| {
                    contact_wrench(prm, &d.law, &mq, setups, |pair, angle, _| {
                        pair.at_stationary(&x, angle, &d.p)
                    })
                })?;
                (
                    peg_d.margin(reversed(&wd)),
                    peg_q.margin(reversed(&wq)),
                    0.0,
                )
            }
        };
        let (Some(by_y), Some(by_q)) = (by_y, by_q) else {
            return Ok(None);
        };
        let g_y = SVector::from_fn(|i, _| if i < 13 { by_y.d[i] } else { 0.0 });
        Ok(Some((by_y.v, g_y, slots(&by_q), rate)))
    }
}
