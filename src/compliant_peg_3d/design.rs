//! The insertion's derivatives in design parameters: `∂f/∂q` of
//! [`Insertion`]'s right-hand side and the gradients of the quantities a
//! sensitivity run reads (depth, a contact's normal force, the wrist's
//! force, a pair's gap), in dual numbers of up to [`N_DESIGN`] design
//! parameters `q`.
//!
//! The model's quantities that the parameters move ([`Design`]: the
//! generated functions' parameter vector, the contact law's coefficients,
//! the wrist, the robot motion's start, tilt and descent) are given as
//! dual numbers ([`Q`]) whose slot `k` carries `∂/∂q_k`; the right-hand
//! side is then evaluated once at those dual numbers, through the same
//! code as at `f64`:
//!
//! ```text
//! ẏ = (f(y, w_c(y, q) + w_h(t, y, q), p(q)), Ẇ_r(t, y, q))
//! ∂ẏ/∂q = (∂f/∂p p_q + ∂f/∂w (∂w_c/∂q + ∂w_h/∂q), ∂Ẇ_r/∂q)
//! ```
//!
//! The generated Newton–Euler right-hand side `f` and the contact law
//! ([`super::forces::contact_wrench`]) are generic over the scalar; each
//! point and col is followed through its stationary angle by the
//! implicit-function theorem ([`Pair::at_stationary`], the angle in the
//! last slot, [`ANGLE_SLOT`]): a geometry parameter (the fillets, the peg's
//! radius) moves the contact point along the edge circle, and the gap's
//! derivative is the envelope theorem's. The wrist's load is
//! [`super::wrist::load_with`] at the robot frame's terms in dual numbers
//! ([`super::robot::RobotMotion::terms_of`]).
//!
//! The contacts and their Hertz setups are those the right-hand side found
//! at the state (the active set is held, as in the state Jacobian); the
//! Hertz stiffness `k` is held at its value: exact for a fixed stiffness
//! ([`HertzMode::Fixed`](super::HertzMode::Fixed)); with the curvature
//! stiffness its variation with the geometry parameters is left out. The
//! distributed ring of the peg's bottom on a flat ([`super::face`]) is
//! evaluated at the parameters' values without their derivatives.

use nalgebra::{SMatrix, SVector};

use super::contact::Pair;
use super::forces::{self, Setup, contact_wrench};
use super::frame::{Motion, axis};
use super::held::time_partial;
use super::insertion::{Insertion, N_STATE, peg_state};
use super::jacobian::{self, D};
use super::law::LawParams;
use super::robot::MotionOf;
use super::wrist::{Kinematics, WristOf, load_with};
use crate::generated::compliant_peg_3d as generated;
use crate::hertz::HertzError;
use crate::scalar::{Dual, Real};
use crate::sensitivity::ParameterJacobian;
use crate::system::{KinematicSplit, ModelError, OdeSystem};

/// The most design parameters carried at once.
pub const N_DESIGN: usize = 8;

/// The slot of the edge angle in [`Q`] (eliminated by the implicit-function
/// theorem, zero in every result).
pub const ANGLE_SLOT: usize = N_DESIGN;

/// Dual numbers of the design parameters (slots `0..N_DESIGN`) and of a
/// pair function's edge angle (slot [`ANGLE_SLOT`]).
pub type Q = Dual<{ N_DESIGN + 1 }>;

/// The model's quantities in dual numbers of the design parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Design {
    /// The generated functions' parameter vector
    /// ([`super::Peg3dParams::vector`]).
    pub p: SVector<Q, 16>,
    /// The contact law's coefficients.
    pub law: LawParams<Q>,
    /// The wrist.
    pub wrist: WristOf<Q>,
    /// The robot motion's start, tilt and descent.
    pub robot: MotionOf<Q>,
}

impl Design {
    /// The generated functions' parameters by name (`L`, `m`, `g`, …).
    pub fn params(&self) -> generated::Params<Q> {
        generated::Params::from(&self.p)
    }

    /// The quantities of `system` as constants (every derivative zero).
    /// `None` for a peg that is not held.
    pub fn constant(system: &Insertion) -> Option<Design> {
        let h = system.held?;
        Some(Design {
            p: system.peg.param_vector().map(Q::constant),
            law: LawParams::of(&system.peg.params),
            wrist: h.wrist.of(),
            robot: h.robot.of(),
        })
    }
}

/// A value with its gradients in the state and in the design parameters.
pub type Gradients = (f64, SVector<f64, N_STATE>, SVector<f64, N_DESIGN>);

/// The derivatives of a dual number in the design slots.
pub fn slots(x: &Q) -> SVector<f64, N_DESIGN> {
    SVector::from_fn(|k, _| x.d[k])
}

/// The peg state's first 13 components as constants of `T`.
fn constant_state<T: Real>(y: &SVector<f64, N_STATE>) -> [T; 13] {
    std::array::from_fn(|k| T::from_f64(y[k]))
}

impl Insertion {
    /// `∂ẏ/∂q` (16 × [`N_DESIGN`]) at `(t, y)` for the quantities `d` (in
    /// dual numbers of the design parameters), at the contacts the
    /// right-hand side finds at `y` (the memo of the last search: no second
    /// search after `f(y)`). The quantities' values must be this system's.
    ///
    /// # Errors
    /// As [`super::Peg3d::setups`] when the contacts have to be searched.
    pub fn parameter_rate(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
        d: &Design,
    ) -> Result<SMatrix<f64, N_STATE, N_DESIGN>, HertzError> {
        self.rate_along(t, y, d, None)
    }

    /// `J s + ∂ẏ/∂q` (16 × [`N_DESIGN`], column `k`: `J s_k + ∂ẏ/∂q_k`)
    /// at `(t, y)` in one pass: the right-hand side at the state seeded
    /// with the sensitivities' columns and the quantities `d`, so that
    /// slot `k` of every dual number carries the directional derivative
    /// along `(s_k, e_k)`: the variational equations' right-hand side
    /// without forming `J` (one evaluation of the law in dual numbers
    /// where `J` and `∂ẏ/∂q` take two). Same contacts and errors as
    /// [`Self::parameter_rate`].
    ///
    /// # Errors
    /// As [`super::Peg3d::setups`] when the contacts have to be searched.
    pub fn sensitivity_rate(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
        s: &SMatrix<f64, N_STATE, N_DESIGN>,
        d: &Design,
    ) -> Result<SMatrix<f64, N_STATE, N_DESIGN>, HertzError> {
        self.rate_along(t, y, d, Some(s))
    }

    /// `ẏ`'s derivatives in the design slots at the state `y`, constant
    /// (`s = None`) or moving along the columns of `s`.
    fn rate_along(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
        d: &Design,
        s: Option<&SMatrix<f64, N_STATE, N_DESIGN>>,
    ) -> Result<SMatrix<f64, N_STATE, N_DESIGN>, HertzError> {
        let ys = peg_state(y);
        let along = |i: usize| {
            let mut v = Q::constant(y[i]);
            if let Some(s) = s {
                for k in 0..N_DESIGN {
                    v.d[k] = s[(i, k)];
                }
            }
            v
        };
        let yq: [Q; 13] = std::array::from_fn(along);
        let m = Motion::of_state(&yq);
        let x = SVector::<Q, 7>::from(m.pose);
        let prm = &self.peg.params;
        let mut w = self.peg.with_setups(&ys, |setups| {
            contact_wrench(prm, &d.law, &m, setups, |pair, angle, _| {
                pair.at_stationary(&x, angle, &d.p)
            })
        })?;
        let kin = Kinematics::of_state(&yq);
        let frame = self.held.map(|h| h.robot.terms_of(t, &d.robot));
        let power = self.add_held_with(
            &kin,
            frame.as_ref().map(|f| (&d.wrist, f)),
            d.params().L,
            &mut w,
        );
        let yq15 = SVector::<Q, 15>::from_fn(|i, _| along(i));
        let rate = generated::rhs(&yq15, &SVector::from(w), &d.p);
        Ok(SMatrix::from_fn(|r, k| {
            if r < 15 { rate[r].d[k] } else { power.d[k] }
        }))
    }

    /// The tip's depth `−(p_z − (L/2) a_z)` at `y` (m) with its gradients
    /// in the state (16) and in the design parameters.
    pub fn depth_gradient(
        &self,
        y: &SVector<f64, N_STATE>,
        d: &Design,
    ) -> (f64, SVector<f64, N_STATE>, SVector<f64, N_DESIGN>) {
        let ys = peg_state(y);
        let depth = |x: [D; 7], half: D| -(x[2] - half * axis(&x)[2]);
        let half = D::from_f64(0.5 * self.peg.params.length);
        let x = Motion::of_state(&jacobian::seeded(&ys)).pose;
        let dy = depth(x, half);
        let xq = Motion::of_state(&constant_state::<Q>(y)).pose;
        let dq = -(xq[2] - Q::from_f64(0.5) * d.params().L * axis(&xq)[2]);
        (dy.v, state_gradient(&dy), slots(&dq))
    }

    /// The normal force `Q` (N) of the contact at `index` among the setups
    /// of `y` ([`super::Peg3d::setups`] order) with its gradients in the
    /// state and in the design parameters; `None` without that contact.
    ///
    /// # Errors
    /// As [`super::Peg3d::setups`].
    pub fn normal_force_gradient(
        &self,
        y: &SVector<f64, N_STATE>,
        index: usize,
        d: &Design,
    ) -> Result<Option<Gradients>, HertzError> {
        let ys = peg_state(y);
        let prm = &self.peg.params;
        let pv = self.peg.param_vector();
        self.peg.with_setups(&ys, |setups| {
            if index >= setups.len() {
                return None;
            }
            let state = jacobian::normal_forces_dual(prm, pv, &jacobian::seeded(&ys), setups);
            let yq: [Q; 13] = constant_state(y);
            let m = Motion::of_state(&yq);
            let x = SVector::<Q, 7>::from(m.pose);
            let mut param = None;
            let mut k = 0;
            forces::evaluate(
                prm,
                &d.law,
                &m,
                setups,
                |pair, angle, _| pair.at_stationary(&x, angle, &d.p),
                |_: &Setup, _, load, _| {
                    if k == index {
                        param = Some(load.normal_force);
                    }
                    k += 1;
                },
            );
            let (s, p) = (state.get(index)?, param?);
            Some((s.v, state_gradient(s), slots(&p)))
        })
    }

    /// The largest contact normal force at `y` (N) and the index of its
    /// contact among the setups; `None` without contact.
    ///
    /// # Errors
    /// As [`super::Peg3d::forces`].
    pub fn peak_contact(
        &self,
        y: &SVector<f64, N_STATE>,
    ) -> Result<Option<(usize, f64)>, HertzError> {
        let f = self.peg.forces(&peg_state(y))?;
        Ok(f.iter()
            .enumerate()
            .map(|(i, f)| (i, f.normal_force))
            .filter(|(_, f)| *f > 0.0)
            .max_by(|a, b| a.1.total_cmp(&b.1)))
    }

    /// The magnitude of the wrist's force `|F|` (N) at `(t, y)` with its
    /// gradients in the state and in the design parameters, and its
    /// partial rate in time `∂|F|/∂t` (the robot frame's motion,
    /// [`time_partial`]). `None` for a peg that is not held.
    pub fn wrist_force_gradient(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
        d: &Design,
    ) -> Option<(f64, SVector<f64, N_STATE>, SVector<f64, N_DESIGN>, f64)> {
        let h = self.held?;
        let ys = peg_state(y);
        let length = self.peg.params.length;
        let norm = |f: [D; 3]| (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
        let kin = Kinematics::of_state(&jacobian::seeded(&ys));
        let fy = norm(h.wrist.load_of(length, &kin, &h.robot.frame(t)).force);
        let kq = Kinematics::of_state(&constant_state::<Q>(y));
        let fq = load_with(&d.wrist, d.params().L, &kq, &h.robot.terms_of(t, &d.robot)).force;
        let fq = (fq[0] * fq[0] + fq[1] * fq[1] + fq[2] * fq[2]).sqrt();
        let at = |t: f64| {
            let k = Kinematics::of_state(ys.as_slice());
            let f = h.wrist.load_of(length, &k, &h.robot.frame(t)).force;
            (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt()
        };
        // Richardson-extrapolated: a plain central difference's `h² F‴/6`
        // shows in a peak's derivative along the robot's speed, multiplied
        // by the seat time's.
        Some((fy.v, state_gradient(&fy), slots(&fq), time_partial(t, at)))
    }

    /// The gap `g` (m, negative when penetrating) of `pair` at its
    /// stationary angle near `angle` (Newton's method on `g′ = 0` from
    /// `angle`, to 10⁻¹⁴ rad) at `y`, and that angle; `None` when Newton's
    /// method does not settle on a minimum (`g″ ≤ 0`, or 30 steps).
    pub fn stationary_gap(
        &self,
        y: &SVector<f64, N_STATE>,
        pair: Pair,
        angle: f64,
    ) -> Option<(f64, f64)> {
        let x = super::system::Peg3d::pose(&peg_state(y));
        let pv = self.peg.param_vector();
        let mut a = angle;
        for _ in 0..30 {
            let o = pair.eval(&x, a, pv);
            if o.d2.is_nan() || o.d2 <= 0.0 {
                return None;
            }
            let step = o.d1 / o.d2;
            a -= step;
            if step.abs() < 1e-14 {
                return Some((pair.eval(&x, a, pv).gap, a));
            }
        }
        None
    }

    /// [`Insertion::stationary_gap`] with the gap's gradients in the state
    /// and in the design parameters (the envelope theorem: the angle's own
    /// change drops out of the gap's).
    pub fn gap_gradient(
        &self,
        y: &SVector<f64, N_STATE>,
        pair: Pair,
        angle: f64,
        d: &Design,
    ) -> Option<(f64, SVector<f64, N_STATE>, SVector<f64, N_DESIGN>)> {
        let (_, a) = self.stationary_gap(y, pair, angle)?;
        let ys = peg_state(y);
        let gy = jacobian::gap_dual(self.peg.param_vector(), &jacobian::seeded(&ys), pair, a);
        let xq = SVector::<Q, 7>::from(Motion::of_state(&constant_state::<Q>(y)).pose);
        let gq = -pair.at_stationary(&xq, a, &d.p).penetration;
        Some((gy.v, state_gradient(&gy), slots(&gq)))
    }
}

/// The state gradient (16, the work integrals' entries zero) of a dual
/// number of the 13 state components.
fn state_gradient(x: &D) -> SVector<f64, N_STATE> {
    SVector::from_fn(|i, _| if i < 13 { x.d[i] } else { 0.0 })
}

/// An [`Insertion`] with the design quantities along which its
/// sensitivities are integrated: the [`ParameterJacobian`] of the
/// insertion in [`N_DESIGN`] design parameters (slots whose derivatives
/// are all zero stay zero).
pub struct Directions<'a> {
    /// The system.
    pub system: &'a Insertion,
    /// The quantities in dual numbers of the design parameters.
    pub design: Design,
    /// The design parameters' values (the sensitivities' column scales).
    pub values: SVector<f64, N_DESIGN>,
}

impl OdeSystem<N_STATE> for Directions<'_> {
    fn rhs(&self, t: f64, y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        self.system.rhs(t, y)
    }

    fn try_rhs(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> Result<SVector<f64, N_STATE>, ModelError> {
        self.system.try_rhs(t, y)
    }

    fn jacobian(&self, t: f64, y: &SVector<f64, N_STATE>) -> SMatrix<f64, N_STATE, N_STATE> {
        self.system.jacobian(t, y)
    }

    fn try_jacobian(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> Result<SMatrix<f64, N_STATE, N_STATE>, ModelError> {
        self.system.try_jacobian(t, y)
    }

    fn time_derivative(&self, t: f64, y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        self.system.time_derivative(t, y)
    }

    fn kinematic_split(&self) -> Option<KinematicSplit> {
        self.system.kinematic_split()
    }

    fn state_names(&self) -> &'static [&'static str] {
        self.system.state_names()
    }
}

impl ParameterJacobian<N_STATE, N_DESIGN> for Directions<'_> {
    fn parameters(&self) -> SVector<f64, N_DESIGN> {
        self.values
    }

    /// [`Insertion::parameter_rate`], NaN after a Hertz setup error.
    fn parameter_jacobian(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> SMatrix<f64, N_STATE, N_DESIGN> {
        self.try_parameter_jacobian(t, y)
            .unwrap_or_else(|_| SMatrix::repeat(f64::NAN))
    }

    fn try_parameter_jacobian(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> Result<SMatrix<f64, N_STATE, N_DESIGN>, ModelError> {
        Ok(self.system.parameter_rate(t, y, &self.design)?)
    }

    /// [`Insertion::sensitivity_rate`]: `J s + ∂f/∂q` in one pass.
    fn try_sensitivity_rate(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
        s: &SMatrix<f64, N_STATE, N_DESIGN>,
    ) -> Option<Result<SMatrix<f64, N_STATE, N_DESIGN>, ModelError>> {
        Some(
            self.system
                .sensitivity_rate(t, y, s, &self.design)
                .map_err(ModelError::from),
        )
    }
}
