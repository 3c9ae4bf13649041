//! The rigid three-point peg through the generated code
//! (`pegdyn::generated::rigid_peg*`, derived in
//! `equations/src/models/rigid_peg/`; `docs/rigid-model.md`).
//!
//! Four variants of one derivation; the runtime picks the smallest that
//! represents the state ([`Variant::smallest_at`]; [`Variant::smallest`] for
//! a scene posed at ψ = 0). Every entry point checks the
//! parameters, the three-point range γ0 < γ < π/2 and that the variant can
//! represent the request, solves the generated 5×5 (or 3×3 planar) system
//! with LU, and refuses a singular or non-finite solution.
//!
//! Friction directions `t` are unit vectors (or shorter, regularized) in
//! rotating components (e_η, e_n, e_z), force on the peg, one per contact
//! K, B1, B2; [`friction_directions`] makes them from
//! [`contact_velocities`].

use nalgebra::{SVector, Vector2, Vector3};

use crate::generated::{
    rigid_peg, rigid_peg_frictionless, rigid_peg_planar, rigid_peg_planar_frictionless,
};
use crate::rigid_peg::dynamics::solve;
use crate::rigid_peg::generated_inputs::{
    directions, planar_friction, planar_loads, planar_state, state,
};
use crate::rigid_peg::{Loads, PegParams, RigidError};

/// Which generated rigid-peg module to use: the generator's own definition
/// (one file, `equations/src/models/rigid_peg/variant.rs`, compiled into both
/// crates).
#[path = "../../equations/src/models/rigid_peg/variant.rs"]
mod variant;
pub use variant::Variant;

/// Forward-dynamics result: accelerations and normal forces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accelerations {
    /// (γ̈, ψ̈) (rad/s²).
    pub qdd: Vector2<f64>,
    /// Normal forces on the peg `[N_K, N_B1, N_B2]` (N); negative = the
    /// contact would have to pull.
    pub normal: [f64; 3],
}

/// Reactions and driving moments of a prescribed motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reactions {
    /// Moment conjugate to γ that drives the motion (N·m).
    pub m_gamma: f64,
    /// Moment about the hole axis that drives the motion (N·m).
    pub m_psi: f64,
    /// Normal reactions `[N_K, N_B1, N_B2]` (N); negative = the contact would
    /// have to pull.
    pub normal: [f64; 3],
}

impl Reactions {
    /// True when every contact pushes (N ≥ 0): the prescribed motion is
    /// possible with the peg on three points.
    pub fn feasible(&self) -> bool {
        self.normal.iter().all(|&n| n >= 0.0)
    }
}

/// Relative size below which a lateral component counts as zero in the
/// planar variants' checks (rounding of an exactly planar input).
const PLANAR_TOL: f64 = 1e-12;

impl Variant {
    /// The smallest variant for a scene posed at ψ = 0: planar when ψ̇ ≡ 0
    /// throughout, M_ψ = 0 and the lateral force `force[1]` is 0 (the fixed
    /// y axis is e_n at ψ = 0); frictionless when f = 0.
    pub fn smallest(p: &PegParams, loads: &Loads, psidot_is_zero_throughout: bool) -> Variant {
        Variant::smallest_at(p, loads, 0.0, psidot_is_zero_throughout)
    }

    /// As [`Variant::smallest`] for a scene whose constant precession angle
    /// is `psi`: the lateral force is −F_x sin ψ + F_y cos ψ.
    pub fn smallest_at(
        p: &PegParams,
        loads: &Loads,
        psi: f64,
        psidot_is_zero_throughout: bool,
    ) -> Variant {
        let planar = psidot_is_zero_throughout && loads.m_psi == 0.0 && lateral(loads, psi) == 0.0;
        match (planar, p.friction == 0.0) {
            (true, true) => Variant::PlanarFrictionless,
            (true, false) => Variant::Planar,
            (false, true) => Variant::Frictionless,
            (false, false) => Variant::Full,
        }
    }

    fn refuse(self, reason: &'static str) -> RigidError {
        RigidError::Unrepresentable {
            variant: self.module_name(),
            reason,
        }
    }

    /// Checks that this variant represents the request.
    fn check(
        self,
        p: &PegParams,
        loads: &Loads,
        psi: f64,
        psidot: f64,
        t: &[Vector3<f64>; 3],
    ) -> Result<(), RigidError> {
        if !self.has_friction() && p.friction != 0.0 {
            return Err(self.refuse("friction coefficient is not zero"));
        }
        if !self.is_planar() {
            return Ok(());
        }
        if psidot != 0.0 {
            return Err(self.refuse("psidot is not zero"));
        }
        if loads.m_psi != 0.0 {
            return Err(self.refuse("M_psi is not zero"));
        }
        let scale = Vector3::from(loads.force).norm();
        if lateral(loads, psi).abs() > PLANAR_TOL * scale {
            return Err(self.refuse("the force has a lateral (e_n) component"));
        }
        if self.has_friction() && !planar_directions(t) {
            return Err(
                self.refuse("friction directions are not planar (t_n = 0, t_B1 = t_B2 required)")
            );
        }
        Ok(())
    }
}

/// Whether the friction directions `t` (K, B1, B2) lie in the symmetry
/// plane, as the planar variants with friction require: no lateral (e_n)
/// component and t_B1 = t_B2, each up to [`PLANAR_TOL`] (absolute, `t` is
/// at most unit).
pub(crate) fn planar_directions(t: &[Vector3<f64>; 3]) -> bool {
    let lateral_t = t.iter().any(|ti| ti.y.abs() > PLANAR_TOL);
    let (b1, b2) = (t[1], t[2]);
    let unequal = (b1.x - b2.x).abs() > PLANAR_TOL || (b1.z - b2.z).abs() > PLANAR_TOL;
    !(lateral_t || unequal)
}

/// Lateral (e_n) component of the assembly force at precession angle ψ (N).
fn lateral(loads: &Loads, psi: f64) -> f64 {
    let (s, c) = psi.sin_cos();
    -loads.force[0] * s + loads.force[1] * c
}

/// Checks the parameters, the state's finiteness and the three-point range;
/// returns the generated model's parameters (γ0 computed once, here).
pub(super) fn checked(
    p: &PegParams,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
) -> Result<rigid_peg::Params<f64>, RigidError> {
    p.validate()?;
    let values = [
        ("q", q[0]),
        ("q", q[1]),
        ("qdot", qdot[0]),
        ("qdot", qdot[1]),
    ];
    for (field, value) in values {
        if !value.is_finite() {
            return Err(RigidError::Param {
                field,
                value,
                reason: "must be finite",
            });
        }
    }
    let params = rigid_peg::Params::from(p);
    let (gamma, gamma0) = (q[0], params.gamma0);
    if !(gamma > gamma0 && gamma < std::f64::consts::FRAC_PI_2) {
        return Err(RigidError::NotThreePoint { gamma, gamma0 });
    }
    Ok(params)
}

/// The unknowns of a solved system: q̈ (forward) or the moments
/// (prescribed), and the normal forces `[N_K, N_B1, N_B2]`.
struct Unknowns {
    head: Vector2<f64>,
    normal: [f64; 3],
}

/// Solves a 2-DOF variant's system A u = b at γ.
fn solve5(s: rigid_peg::LinearSystem<f64>, gamma: f64) -> Result<Unknowns, RigidError> {
    let x = solve::<5, 1>(&s.a, &s.b, gamma)?;
    Ok(Unknowns {
        head: Vector2::new(x[0], x[1]),
        normal: [x[2], x[3], x[4]],
    })
}

/// Solves a planar variant's system A u = b at γ: the ψ part is 0 and
/// N_B1 = N_B2 = N_B.
fn solve3(s: rigid_peg_planar::LinearSystem<f64>, gamma: f64) -> Result<Unknowns, RigidError> {
    let x = solve::<3, 1>(&s.a, &s.b, gamma)?;
    Ok(Unknowns {
        head: Vector2::new(x[0], 0.0),
        normal: [x[1], x[2], x[2]],
    })
}

/// Forward dynamics: (γ̈, ψ̈) and the normal forces at state (q, q̇) under
/// `loads`, with friction directions `t` (ignored by the frictionless
/// variants). Replaces the paper's (24)–(31).
///
/// # Errors
/// [`RigidError::Param`] for invalid parameters or a non-finite state,
/// [`RigidError::NotThreePoint`] outside γ0 < γ < π/2,
/// [`RigidError::Unrepresentable`] when `variant` cannot represent the
/// request (friction with a frictionless variant; ψ̇, M_ψ, a lateral force
/// or non-planar friction with a planar one), [`RigidError::Singular`].
pub fn forward(
    variant: Variant,
    p: &PegParams,
    loads: &Loads,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
    t: &[Vector3<f64>; 3],
) -> Result<Accelerations, RigidError> {
    let params = checked(p, q, qdot)?;
    variant.check(p, loads, q[1], qdot[1], t)?;
    let pv = params.into();
    let gamma = q[0];
    let u = match variant {
        Variant::Full => solve5(
            rigid_peg::forward(
                &state(q, qdot).into(),
                &pv,
                &rigid_peg::Loads::from(loads).into(),
                &directions(t).into(),
            ),
            gamma,
        )?,
        Variant::Frictionless => solve5(
            rigid_peg_frictionless::forward(
                &state(q, qdot).into(),
                &pv,
                &rigid_peg::Loads::from(loads).into(),
            ),
            gamma,
        )?,
        Variant::Planar => solve3(
            rigid_peg_planar::forward(
                &planar_state(q, qdot).into(),
                &pv,
                &planar_loads(loads, q[1]).into(),
                &planar_friction(t).into(),
            ),
            gamma,
        )?,
        Variant::PlanarFrictionless => solve3(
            rigid_peg_planar_frictionless::forward(
                &planar_state(q, qdot).into(),
                &pv,
                &planar_loads(loads, q[1]).into(),
            ),
            gamma,
        )?,
    };
    Ok(Accelerations {
        qdd: u.head,
        normal: u.normal,
    })
}

/// Prescribed motion: the moments (M_γ, M_ψ) that drive (q̈ given) and the
/// normal forces (paper (26)–(31), Fig. 9). `loads.m_gamma`, `loads.m_psi`
/// are ignored (they are the unknowns).
///
/// # Errors
/// As [`forward`]; a planar variant also refuses ψ̈ ≠ 0.
pub fn prescribed(
    variant: Variant,
    p: &PegParams,
    loads: &Loads,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
    qdd: Vector2<f64>,
    t: &[Vector3<f64>; 3],
) -> Result<Reactions, RigidError> {
    let params = checked(p, q, qdot)?;
    let loads = Loads {
        m_gamma: 0.0,
        m_psi: 0.0,
        ..*loads
    };
    variant.check(p, &loads, q[1], qdot[1], t)?;
    if variant.is_planar() && qdd[1] != 0.0 {
        return Err(variant.refuse("psiddot is not zero"));
    }
    if !(qdd[0].is_finite() && qdd[1].is_finite()) {
        return Err(RigidError::Param {
            field: "qdd",
            value: if qdd[0].is_finite() { qdd[1] } else { qdd[0] },
            reason: "must be finite",
        });
    }
    let pv = params.into();
    let (qdd2, qdd1) = (qdd, SVector::<f64, 1>::new(qdd[0]));
    let gamma = q[0];
    let u = match variant {
        Variant::Full => solve5(
            rigid_peg::prescribed(
                &state(q, qdot).into(),
                &qdd2,
                &pv,
                &rigid_peg::Loads::from(&loads).into(),
                &directions(t).into(),
            ),
            gamma,
        )?,
        Variant::Frictionless => solve5(
            rigid_peg_frictionless::prescribed(
                &state(q, qdot).into(),
                &qdd2,
                &pv,
                &rigid_peg::Loads::from(&loads).into(),
            ),
            gamma,
        )?,
        Variant::Planar => solve3(
            rigid_peg_planar::prescribed(
                &planar_state(q, qdot).into(),
                &qdd1,
                &pv,
                &planar_loads(&loads, q[1]).into(),
                &planar_friction(t).into(),
            ),
            gamma,
        )?,
        Variant::PlanarFrictionless => solve3(
            rigid_peg_planar_frictionless::prescribed(
                &planar_state(q, qdot).into(),
                &qdd1,
                &pv,
                &planar_loads(&loads, q[1]).into(),
            ),
            gamma,
        )?,
    };
    Ok(Reactions {
        m_gamma: u.head[0],
        m_psi: u.head[1],
        normal: u.normal,
    })
}

/// Material velocity of the peg at K, B1, B2 in rotating components (m/s)
/// (paper (10)–(13), corrected).
///
/// # Errors
/// As [`forward`] for the state checks; a planar variant refuses ψ̇ ≠ 0.
pub fn contact_velocities(
    variant: Variant,
    p: &PegParams,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
) -> Result<[Vector3<f64>; 3], RigidError> {
    let pv = checked(p, q, qdot)?.into();
    let (x2, x1) = (state(q, qdot).into(), planar_state(q, qdot).into());
    let v = match variant {
        Variant::Full => rigid_peg::contact_velocities(&x2, &pv),
        Variant::Frictionless => rigid_peg_frictionless::contact_velocities(&x2, &pv),
        _ if qdot[1] != 0.0 => return Err(variant.refuse("psidot is not zero")),
        Variant::Planar => rigid_peg_planar::contact_velocities(&x1, &pv),
        Variant::PlanarFrictionless => rigid_peg_planar_frictionless::contact_velocities(&x1, &pv),
    };
    Ok([0, 1, 2].map(|i| v.row(i).transpose()))
}

/// Friction directions t_i = −v_i/|v_i| from the contact velocities (the
/// hand-derived model's [`directions_opposing`](crate::rigid_peg::dynamics::directions_opposing)).
pub use crate::rigid_peg::dynamics::directions_opposing as friction_directions;
