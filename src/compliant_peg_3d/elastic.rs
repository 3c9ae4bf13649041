//! The compliant 3-D peg with the elastic friction law ([`super::mindlin`])
//! as an ODE system: the 15 states of [`Peg3d`] followed by a tangential
//! displacement `ξ` (3 components, hole frame, m) per slot.
//!
//! **Why a wrapper with extra components.** The displacements must be
//! integrated with the motion (the integrators' error control, dense output
//! and events see them), but the 15-state system, its generated
//! Newton–Euler right-hand side, its exact Jacobian and every driver built
//! on it stay as they are: [`ElasticPeg3d`] holds a [`Peg3d`], evaluates
//! its contacts and normal law unchanged, replaces the regularized friction
//! of the tracked contacts by the spring's, and appends the displacements'
//! rates. Its state length `N = 15 + 3 S` is a type parameter (`S` slots),
//! its Jacobian a forward difference with steps scaled to the contact
//! ([`jacobian_scale`]; the spring is not in the exact Jacobian), and it
//! declares no kinematic split (the displacements' columns are not zero).
//!
//! **Slots.** A slot is keyed by a contact's pair, whether it is the pair's
//! ring, and its index among the pair's point contacts in the order the
//! search finds them ([`SlotKey`]): the key is a function of the contacts
//! of the state, so trial states of a step see the same assignment and no
//! bookkeeping outside the state is needed. A slot's displacement is zero
//! until its contact first touches (it starts at zero and relaxes to zero
//! while not touching), follows the contact while it touches, and is
//! dropped at separation (the cap brings it to zero as the load vanishes,
//! then it relaxes, [`super::mindlin::DROP_TIME`]). A touching contact
//! without a slot keeps the regularized law. The index key assumes a
//! pair's points keep their order while they touch (a point appearing
//! before another of the same pair takes over its slot).

use super::contact::Pair;
use super::forces::{self, Setups};
use super::frame::{Motion, V3, cross, dot, scale, sub};
use super::law::{self, LawParams, Load};
use super::mindlin::{self, Mindlin, Spring, Touch};
use super::params::{FrictionLaw, Peg3dParams};
use super::system::Peg3d;
use crate::generated::compliant_peg_3d as generated;
use crate::hertz::HertzError;
use crate::system::{ModelError, OdeSystem};
use nalgebra::{SMatrix, SVector};

/// The scale `s_j` of state component `j` in the finite-difference
/// Jacobian's step: 10 µm for the position, 10⁻³ for the quaternion,
/// 1 mm/s, 0.1 rad/s, 1 J for the work integrals, 0.1 nm for a
/// displacement.
pub fn jacobian_scale(j: usize) -> f64 {
    match j {
        0..=2 => 1e-5,
        3..=6 => 1e-3,
        7..=9 => 1e-3,
        10..=12 => 1e-1,
        13 | 14 => 1.0,
        _ => 1e-10,
    }
}

/// Which contact a slot tracks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SlotKey {
    /// The contact's pair.
    pub pair: Pair,
    /// True for the pair's distributed ring ([`super::face`]).
    pub ring: bool,
    /// Index among the pair's point contacts in the order found (0 for a
    /// ring).
    pub index: usize,
}

impl SlotKey {
    /// The ring of a plane pair.
    pub fn ring(pair: Pair) -> SlotKey {
        SlotKey {
            pair,
            ring: true,
            index: 0,
        }
    }

    /// The `index`-th point contact of `pair`.
    pub fn point(pair: Pair, index: usize) -> SlotKey {
        SlotKey {
            pair,
            ring: false,
            index,
        }
    }
}

/// Why an [`ElasticPeg3d`] cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ElasticError {
    /// The parameters select another friction law.
    #[error("friction_law: the elastic system needs friction_law = \"elastic\"")]
    FrictionLaw,
    /// The friction coefficient is not positive and finite.
    #[error("friction: must be > 0 with the elastic friction law, got {0}")]
    Friction(f64),
    /// The tangential damping time is negative or not finite.
    #[error("tangential_damping: must be finite and >= 0, got {0}")]
    TangentialDamping(f64),
    /// More slots than [`MAX_SLOTS`].
    #[error("slots: at most {MAX_SLOTS} tracked contacts, not {0}")]
    TooManySlots(usize),
    /// The state length is not 15 + 3 per slot.
    #[error("slots: {slots} slots need a state of {} components, not {state}", 15 + 3 * slots)]
    Slots {
        /// Slots asked for.
        slots: usize,
        /// The system's state length `N`.
        state: usize,
    },
}

/// The most tracked contacts of an [`ElasticPeg3d`]: every point contact
/// the search can return ([`super::MAX_CONTACTS`]).
pub const MAX_SLOTS: usize = super::contact::MAX_CONTACTS;

/// Every slot's [`SlotForce`], in a fixed-capacity array (the right-hand
/// side allocates nothing).
pub type SlotForces = arrayvec::ArrayVec<SlotForce, MAX_SLOTS>;

/// One tracked contact's tangential law at a state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlotForce {
    /// The slot's key.
    pub key: SlotKey,
    /// Whether its contact touches.
    pub touching: bool,
    /// Normal force `Q` of the contact law (N; 0 when not touching).
    pub normal_force: f64,
    /// Elastic normal force `Q_e` (N).
    pub elastic: f64,
    /// The spring ([`super::mindlin::spring`]).
    pub spring: Spring,
}

/// The compliant 3-D peg with `(N − 15)/3` tracked tangential
/// displacements.
pub struct ElasticPeg3d<const N: usize> {
    peg: Peg3d,
    law: Mindlin,
    slots: Vec<SlotKey>,
}

impl<const N: usize> ElasticPeg3d<N> {
    /// The system of `params` tracking the contacts `slots`.
    ///
    /// # Errors
    /// `params.friction_law` not [`FrictionLaw::Elastic`], a friction
    /// coefficient not `> 0`, a negative tangential damping time, more
    /// than [`MAX_SLOTS`] slots, or `N ≠ 15 + 3 slots.len()`.
    pub fn try_new(params: Peg3dParams, slots: &[SlotKey]) -> Result<Self, ElasticError> {
        if params.friction_law != FrictionLaw::Elastic {
            return Err(ElasticError::FrictionLaw);
        }
        if !(params.friction > 0.0 && params.friction.is_finite()) {
            return Err(ElasticError::Friction(params.friction));
        }
        let tau = params.tangential_damping;
        if !(tau >= 0.0 && tau.is_finite()) {
            return Err(ElasticError::TangentialDamping(tau));
        }
        if slots.len() > MAX_SLOTS {
            return Err(ElasticError::TooManySlots(slots.len()));
        }
        if N != 15 + 3 * slots.len() {
            return Err(ElasticError::Slots {
                slots: slots.len(),
                state: N,
            });
        }
        Ok(ElasticPeg3d {
            law: Mindlin::of(&params),
            peg: Peg3d::new(params),
            slots: slots.to_vec(),
        })
    }

    /// The 15-state system it wraps.
    pub fn peg(&self) -> &Peg3d {
        &self.peg
    }

    /// The tracked contacts, slot by slot.
    pub fn slots(&self) -> &[SlotKey] {
        &self.slots
    }

    /// The 15 states of the peg.
    pub fn peg_state(y: &SVector<f64, N>) -> SVector<f64, 15> {
        SVector::from_fn(|i, _| y[i])
    }

    /// The state of the peg's state `y` with every displacement zero.
    pub fn state(y: &SVector<f64, 15>) -> SVector<f64, N> {
        SVector::from_fn(|i, _| if i < 15 { y[i] } else { 0.0 })
    }

    /// The displacement `ξ` of slot `k` (m).
    pub fn displacement(y: &SVector<f64, N>, k: usize) -> V3<f64> {
        [y[15 + 3 * k], y[16 + 3 * k], y[17 + 3 * k]]
    }

    /// The slot of the `index`-th point (or the ring) of `pair`.
    fn slot_of(&self, pair: Pair, ring: bool, index: usize) -> Option<usize> {
        self.slots
            .iter()
            .position(|k| k.pair == pair && k.ring == ring && k.index == index)
    }

    /// Evaluates the contact law of `setups` at `y`: the wrench
    /// `(F, T about the centre of mass, Ṡ)` with each tracked contact's
    /// spring in place of its regularized friction, and every slot's
    /// [`SlotForce`] (not touching: dropped).
    fn evaluate(&self, y: &SVector<f64, N>, setups: &Setups) -> ([f64; 7], SlotForces) {
        let prm = &self.peg.params;
        let m = Motion::of_state(y.as_slice());
        let lp = LawParams::of(prm);
        let mut w = [0.0; 7];
        // At most MAX_SLOTS slots (`try_new`): the array holds them all.
        let mut out: SlotForces = (0..self.slots.len())
            .map(|k| SlotForce {
                key: self.slots[k],
                touching: false,
                normal_force: 0.0,
                elastic: 0.0,
                spring: mindlin::dropped(&Self::displacement(y, k)),
            })
            .collect();
        let mut seen = [0usize; Pair::ALL.len()];
        let weight = forces::point_weight(&m.pose);
        let ring_radius = prm.peg_radius() - prm.rim_fillet;
        forces::evaluate(
            prm,
            &lp,
            &m,
            setups,
            |_, _, at| *at,
            |st, at, load, col| {
                let cp = &st.contact;
                let index = if cp.ring {
                    0
                } else {
                    let i = seen[cp.pair.index()];
                    seen[cp.pair.index()] += 1;
                    i
                };
                let Some(k) = self.slot_of(cp.pair, cp.ring, index) else {
                    law::add_to_wrench(&mut w, &m, at, load, col);
                    return;
                };
                let s = if st.weighted { weight } else { 1.0 };
                let (normal_stiffness, exponent) = if cp.ring {
                    (
                        (1.0 - weight) * 2.0 * std::f64::consts::PI * ring_radius * st.stiffness,
                        0.0,
                    )
                } else {
                    (1.5 * s * st.stiffness * at.penetration.sqrt(), 0.5)
                };
                let touch = Touch {
                    normal: at.normal,
                    velocity: m.point_velocity(&at.point),
                    elastic: load.elastic,
                    normal_stiffness,
                    exponent,
                    penetration: at.penetration,
                };
                let spring = mindlin::spring(&self.law, &touch, &Self::displacement(y, k));
                let replaced = Load {
                    friction: spring.force,
                    ..*load
                };
                law::add_to_wrench(&mut w, &m, at, &replaced, col);
                // The spring's own dissipation instead of −F_t·v_t.
                let vc = touch.velocity;
                let vt = sub(&vc, &scale(&at.normal, dot(&at.normal, &vc)));
                w[6] += spring.dissipation + dot(&spring.force, &vt);
                // The stored energy's normal force P n at the contact point.
                let pn = scale(&at.normal, spring.normal);
                let t = cross(&sub(&at.point, &m.centre), &pn);
                for j in 0..3 {
                    w[j] += pn[j];
                    w[3 + j] += t[j];
                }
                out[k] = SlotForce {
                    key: self.slots[k],
                    touching: true,
                    normal_force: load.normal_force,
                    elastic: load.elastic,
                    spring,
                };
            },
        );
        (w, out)
    }

    /// Every slot's tangential law at state `y`.
    ///
    /// # Errors
    /// A contact whose Hertz setup fails (relative curvature not positive).
    pub fn slot_forces(&self, y: &SVector<f64, N>) -> Result<Vec<SlotForce>, HertzError> {
        let setups = self.peg.setups(&Self::peg_state(y))?;
        Ok(self.evaluate(y, &setups).1.to_vec())
    }

    /// `T + m g z + Σ V + Σ E_t − W + S` at state `y` (J): constant along
    /// solutions where the law is conservative ([`super::mindlin`]).
    ///
    /// # Errors
    /// As [`ElasticPeg3d::slot_forces`].
    pub fn energy_balance(&self, y: &SVector<f64, N>) -> Result<f64, HertzError> {
        let stored: f64 = self.slot_forces(y)?.iter().map(|s| s.spring.energy).sum();
        Ok(self.peg.energy_balance(&Self::peg_state(y))? + stored)
    }
}

impl<const N: usize> OdeSystem<N> for ElasticPeg3d<N> {
    /// [`OdeSystem::try_rhs`], NaN after a Hertz setup error.
    fn rhs(&self, t: f64, y: &SVector<f64, N>) -> SVector<f64, N> {
        self.try_rhs(t, y)
            .unwrap_or_else(|_| SVector::repeat(f64::NAN))
    }

    /// The peg's generated right-hand side with the wrench of the tracked
    /// contacts' springs, then the displacements' rates.
    fn try_rhs(&self, _t: f64, y: &SVector<f64, N>) -> Result<SVector<f64, N>, ModelError> {
        let y15 = Self::peg_state(y);
        let setups = self.peg.setups(&y15)?;
        let (w, slots) = self.evaluate(y, &setups);
        let f = generated::rhs(&y15, &SVector::from(w), self.peg.param_vector());
        let mut out = SVector::<f64, N>::zeros();
        out.fixed_rows_mut::<15>(0).copy_from(&f);
        for (k, s) in slots.iter().enumerate() {
            for j in 0..3 {
                out[15 + 3 * k + j] = s.spring.rate[j];
            }
        }
        Ok(out)
    }

    /// [`OdeSystem::try_jacobian`], NaN after a Hertz setup error.
    fn jacobian(&self, t: f64, y: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        self.try_jacobian(t, y)
            .unwrap_or_else(|_| SMatrix::repeat(f64::NAN))
    }

    /// A forward finite difference with steps scaled to the contact:
    /// column `j` is `(f(y + h_j e_j) − f(y))/h_j`, `h_j = 10⁻⁷ max(|y_j|,
    /// s_j)` with the scales `s_j` of [`jacobian_scale`] (the default's
    /// `√ε max(|y_j|, 1)` would move the peg by more than its penetration
    /// and a displacement by more than its slip limit).
    fn try_jacobian(&self, t: f64, y: &SVector<f64, N>) -> Result<SMatrix<f64, N, N>, ModelError> {
        let f0 = self.try_rhs(t, y)?;
        let mut jac = SMatrix::<f64, N, N>::zeros();
        let mut yp = *y;
        for j in 0..N {
            let stepped = y[j] + 1e-7 * y[j].abs().max(jacobian_scale(j));
            let h = stepped - y[j];
            yp[j] = stepped;
            let f = self.try_rhs(t, &yp)?;
            jac.set_column(j, &((f - f0) / h));
            yp[j] = y[j];
        }
        Ok(jac)
    }

    fn time_derivative(&self, _t: f64, _y: &SVector<f64, N>) -> SVector<f64, N> {
        SVector::zeros()
    }
}
