//! Forward dynamics of the rigid three-point peg: state
//! x = (γ, ψ, γ̇, ψ̇) (rad, rad, 1/s, 1/s), given loads, as an
//! [`OdeSystem`] for the project's integrators.
//!
//! Every evaluation of the accelerations and reactions goes through one
//! private function, `accelerations`, which calls the generated model
//! ([`super::generated_model::forward`]) in the smallest variant that
//! represents the state.
//!
//! Friction ([`FrictionLaw`]): exact Coulomb, t_i = −v_i/|v_i| (sliding
//! only; rest is handled by the stop event and [`super::stick`]), or
//! regularized, t_i = −v_i/√(|v_i|² + v_s²).
//!
//! Outside three-point contact (an RK stage probing γ ≤ γ0 or γ ≥ π/2) the
//! right-hand side is evaluated at γ clamped to
//! [γ0 (1 + [`GAMMA_MARGIN`]), π/2 − [`GAMMA_MARGIN`]]: finite and
//! continuous, so that the step is accepted and the `γ − γ0` event, located
//! on the step's dense output, stops the run (`docs/rigid-peg.md`).

use nalgebra::{Vector2, Vector3, Vector4};

use crate::rigid_peg::dynamics::{forward_system, regularized_opposing};
use crate::rigid_peg::generated_model::{self, Variant};
use crate::rigid_peg::kinematics::Pose;
use crate::rigid_peg::{Loads, PegParams, RigidError};
use crate::system::OdeSystem;

/// Relative margin of the γ clamp of probing stages (dimensionless): γ is
/// evaluated no closer than γ0·1e-10 to γ0 (b ≈ D·1e-5 there for the
/// Fig. 9 peg) and 1e-10 rad to π/2.
pub const GAMMA_MARGIN: f64 = 1e-10;

/// Default stop speed `v_stop` (m/s) of the RMS contact sliding speed below
/// which the peg is taken to be at rest (see [`ForwardModel::speed`]).
pub const DEFAULT_V_STOP: f64 = 1e-6;

/// How friction forces are directed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrictionLaw {
    /// Exact Coulomb: |F_i| = f N_i against the sliding velocity.
    Coulomb,
    /// Regularized: F_i = −f N_i v_i/√(|v_i|² + v_s²), with the velocity
    /// scale `v_s` (m/s, > 0); defined at rest, so no stick logic.
    Regularized {
        /// Velocity scale v_s (m/s).
        v_s: f64,
    },
}

pub use crate::rigid_peg::generated_model::Accelerations;

/// The one place where the integrator obtains accelerations and reactions
/// from the model: the generated code (`pegdyn::generated::rigid_peg*`)
/// through [`generated_model::forward`], in the smallest variant that
/// represents the state — planar when ψ̇ = 0 and the loads and friction
/// directions lie in the symmetry plane (then ψ̈ = 0 by symmetry),
/// frictionless when f = 0 — and the 2-DOF variant otherwise.
fn accelerations(
    p: &PegParams,
    loads: &Loads,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
    t: &[Vector3<f64>; 3],
) -> Result<Accelerations, RigidError> {
    // Friction directions out of the plane (a sliding start searched over
    // the circle) rule out the planar variant with friction.
    let in_plane = qdot[1] == 0.0 && (p.friction == 0.0 || generated_model::planar_directions(t));
    let variant = Variant::smallest_at(p, loads, q[1], in_plane);
    generated_model::forward(variant, p, loads, q, qdot, t)
}

/// The peg, its loads and the friction law of a forward simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForwardModel {
    /// Dimensions, mass, friction coefficient.
    pub params: PegParams,
    /// Constant applied loads.
    pub loads: Loads,
    /// Friction law.
    pub friction: FrictionLaw,
    /// Stop speed v_stop (m/s) of the exact Coulomb law: when the RMS
    /// contact sliding speed falls to it, the peg is taken to be at rest and
    /// the stick/slip decision is made ([`super::stick`]).
    pub v_stop: f64,
}

impl ForwardModel {
    /// A model with exact Coulomb friction and [`DEFAULT_V_STOP`].
    ///
    /// # Errors
    /// [`RigidError::Param`] when the parameters or loads are invalid.
    pub fn new(params: PegParams, loads: Loads) -> Result<ForwardModel, RigidError> {
        params.validate()?;
        let named = [
            ("m_gamma", loads.m_gamma),
            ("m_psi", loads.m_psi),
            ("force_x", loads.force[0]),
            ("force_y", loads.force[1]),
            ("force_z", loads.force[2]),
        ];
        if let Some(&(field, value)) = named.iter().find(|(_, v)| !v.is_finite()) {
            return Err(RigidError::Param {
                field,
                value,
                reason: "must be finite",
            });
        }
        Ok(ForwardModel {
            params,
            loads,
            friction: FrictionLaw::Coulomb,
            v_stop: DEFAULT_V_STOP,
        })
    }

    /// The same model with another friction law.
    ///
    /// # Errors
    /// [`RigidError::Param`] for a regularization scale that is not
    /// finite and positive.
    pub fn with_friction(mut self, law: FrictionLaw) -> Result<ForwardModel, RigidError> {
        if let FrictionLaw::Regularized { v_s } = law
            && !(v_s.is_finite() && v_s > 0.0)
        {
            return Err(RigidError::Param {
                field: "v_s",
                value: v_s,
                reason: "must be finite and > 0",
            });
        }
        self.friction = law;
        Ok(self)
    }

    /// The same model with another stop speed.
    ///
    /// # Errors
    /// [`RigidError::Param`] unless `v_stop` is finite and positive.
    pub fn with_v_stop(mut self, v_stop: f64) -> Result<ForwardModel, RigidError> {
        if !(v_stop.is_finite() && v_stop > 0.0) {
            return Err(RigidError::Param {
                field: "v_stop",
                value: v_stop,
                reason: "must be finite and > 0",
            });
        }
        self.v_stop = v_stop;
        Ok(self)
    }

    /// γ clamped into the three-point range (see [`GAMMA_MARGIN`]).
    pub fn clamp_gamma(&self, gamma: f64) -> f64 {
        let g0 = self.params.gamma0();
        gamma
            .min(std::f64::consts::FRAC_PI_2 - GAMMA_MARGIN)
            .max(g0 * (1.0 + GAMMA_MARGIN))
    }

    /// Friction directions at (q, q̇) (unit for Coulomb, |t| < 1 when
    /// regularized), frame components (η, n, z). At a contact that does not
    /// slide, exact Coulomb uses the direction of the sliding start
    /// `start` (a direction of q̇, from [`super::stick`]).
    ///
    /// # Errors
    /// [`RigidError::NotThreePoint`] outside the range,
    /// [`RigidError::NoSliding`] when a Coulomb contact does not slide and
    /// no start direction is given.
    pub fn friction_directions(
        &self,
        q: Vector2<f64>,
        qdot: Vector2<f64>,
        start: Option<Vector2<f64>>,
    ) -> Result<[Vector3<f64>; 3], RigidError> {
        let pose = Pose::try_new(&self.params, q[0], q[1])?;
        self.directions_at(&pose, qdot, start)
    }

    /// [`ForwardModel::friction_directions`] at an already built pose.
    fn directions_at(
        &self,
        pose: &Pose,
        qdot: Vector2<f64>,
        start: Option<Vector2<f64>>,
    ) -> Result<[Vector3<f64>; 3], RigidError> {
        let j = pose.jacobians_local();
        let v = [0, 1, 2].map(|i| j.contacts[i] * qdot);
        if let FrictionLaw::Regularized { v_s } = self.friction {
            return Ok(regularized_opposing(&v, v_s));
        }
        let mut t = [Vector3::zeros(); 3];
        for (i, (ti, v)) in t.iter_mut().zip(v).enumerate() {
            let s = v.norm();
            *ti = if s > 0.0 && s.is_finite() {
                -v / s
            } else {
                let u = start.map(|u| j.contacts[i] * u).filter(|u| u.norm() > 0.0);
                match u {
                    Some(u) => -u / u.norm(),
                    None => {
                        return Err(RigidError::NoSliding {
                            contact: crate::rigid_peg::dynamics::CONTACTS[i],
                        });
                    }
                }
            };
        }
        Ok(t)
    }

    /// Accelerations and reactions at the state `x = (γ, ψ, γ̇, ψ̇)`
    /// (no clamping), with the sliding start `start` used where nothing
    /// slides.
    ///
    /// # Errors
    /// As [`ForwardModel::friction_directions`], and
    /// [`RigidError::Singular`] when the contact system is singular.
    pub fn evaluate(
        &self,
        x: &Vector4<f64>,
        start: Option<Vector2<f64>>,
    ) -> Result<Accelerations, RigidError> {
        let (q, qdot) = split(x);
        let t = self.friction_directions(q, qdot, start)?;
        accelerations(&self.params, &self.loads, q, qdot, &t)
    }

    /// Accelerations at rest at `q` for a sliding start in the direction
    /// `u` of q̇ (friction at each contact against J_i u).
    ///
    /// # Errors
    /// As [`ForwardModel::evaluate`].
    pub fn evaluate_start(
        &self,
        q: Vector2<f64>,
        u: Vector2<f64>,
    ) -> Result<Accelerations, RigidError> {
        let coulomb = ForwardModel {
            friction: FrictionLaw::Coulomb,
            ..*self
        };
        let t = coulomb.friction_directions(q, Vector2::zeros(), Some(u))?;
        accelerations(&self.params, &self.loads, q, Vector2::zeros(), &t)
    }

    /// Evaluation for the integrator: γ clamped (see [`GAMMA_MARGIN`]).
    pub fn evaluate_clamped(
        &self,
        x: &Vector4<f64>,
        start: Option<Vector2<f64>>,
    ) -> Result<Accelerations, RigidError> {
        let mut xc = *x;
        xc[0] = self.clamp_gamma(x[0]);
        self.evaluate(&xc, start)
    }

    /// RMS sliding speed of the three contacts,
    /// √((|v_K|² + |v_B1|² + |v_B2|²)/3) (m/s), at γ clamped; zero iff
    /// q̇ = 0 (each contact Jacobian has full column rank).
    pub fn speed(&self, x: &Vector4<f64>) -> f64 {
        let (q, qdot) = split(x);
        match Pose::try_new(&self.params, self.clamp_gamma(q[0]), q[1]) {
            Ok(pose) => {
                let v = pose.kinematics(qdot).v_contacts_local;
                ((v[0].norm_squared() + v[1].norm_squared() + v[2].norm_squared()) / 3.0).sqrt()
            }
            Err(_) => f64::NAN,
        }
    }

    /// Kinetic plus potential energy T + V (J) at x (γ not clamped).
    ///
    /// # Errors
    /// [`RigidError::NotThreePoint`] outside the range.
    pub fn energy(&self, x: &Vector4<f64>) -> Result<f64, RigidError> {
        use crate::rigid_peg::dynamics::{kinetic_energy, potential_energy};
        let (q, qdot) = split(x);
        let pose = Pose::try_new(&self.params, q[0], q[1])?;
        Ok(kinetic_energy(&self.params, &pose, &pose.kinematics(qdot))
            + potential_energy(&self.params, &pose))
    }
}

/// (q, q̇) of a state x = (γ, ψ, γ̇, ψ̇).
pub fn split(x: &Vector4<f64>) -> (Vector2<f64>, Vector2<f64>) {
    (Vector2::new(x[0], x[1]), Vector2::new(x[2], x[3]))
}

/// The forward model as an [`OdeSystem`] on x = (γ, ψ, γ̇, ψ̇), with the
/// sliding start direction used while nothing slides.
#[derive(Clone, Copy, Debug)]
pub struct PegSystem<'m> {
    /// The model.
    pub model: &'m ForwardModel,
    /// Direction of q̇ at a start from rest (exact Coulomb only).
    pub start: Option<Vector2<f64>>,
}

impl OdeSystem<4> for PegSystem<'_> {
    /// ẋ = (γ̇, ψ̇, γ̈, ψ̈); NaN when the contact system is singular (the
    /// driver then shrinks the step and stops with `NonFinite`).
    fn rhs(&self, _t: f64, x: &Vector4<f64>) -> Vector4<f64> {
        match self.model.evaluate_clamped(x, self.start) {
            Ok(a) => Vector4::new(x[2], x[3], a.qdd[0], a.qdd[1]),
            Err(_) => Vector4::repeat(f64::NAN),
        }
    }

    fn state_names(&self) -> &'static [&'static str] {
        &crate::generated::rigid_peg::X_NAMES
    }

    fn time_derivative(&self, _t: f64, _x: &Vector4<f64>) -> Vector4<f64> {
        Vector4::zeros()
    }
}

impl ForwardModel {
    /// Normalized determinant det A / Π_j |A_j| (Hadamard ratio, in
    /// [−1, 1]) of the hand-derived forward system at x (γ clamped): zero
    /// where the three-point problem is singular (Painlevé). NaN where the
    /// friction directions are undefined.
    pub fn contact_determinant(&self, x: &Vector4<f64>, start: Option<Vector2<f64>>) -> f64 {
        let (q, qdot) = split(x);
        let gamma = self.clamp_gamma(q[0]);
        let Ok(pose) = Pose::try_new(&self.params, gamma, q[1]) else {
            return f64::NAN;
        };
        let Ok(t) = self.directions_at(&pose, qdot, start) else {
            return f64::NAN;
        };
        let (a, _) = forward_system(&self.params, &self.loads, &pose, qdot, &t);
        let norms: f64 = a.column_iter().map(|c| c.norm()).product();
        a.determinant() / norms
    }
}
