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

/// Checks the parameters, the state's finiteness and the three-point range; returns γ0 = arccos(d/D), computed
/// once per call and handed to [`args`].
fn check_state(p: &PegParams, q: Vector2<f64>, qdot: Vector2<f64>) -> Result<f64, RigidError> {
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
    let (gamma, gamma0) = (q[0], p.gamma0());
    if !(gamma > gamma0 && gamma < std::f64::consts::FRAC_PI_2) {
        return Err(RigidError::NotThreePoint { gamma, gamma0 });
    }
    Ok(gamma0)
}

/// Inputs in the generated functions' order.
struct Args {
    x2: SVector<f64, 4>,
    x1: SVector<f64, 2>,
    p: SVector<f64, 7>,
    loads2: SVector<f64, 5>,
    loads1: SVector<f64, 3>,
    t2: SVector<f64, 9>,
    t1: SVector<f64, 4>,
}

fn args(
    p: &PegParams,
    gamma0: f64,
    loads: &Loads,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
    t: &[Vector3<f64>; 3],
) -> Args {
    let (s, c) = q[1].sin_cos();
    let [fx, fy, fz] = loads.force;
    let in_plane = fx * c + fy * s;
    Args {
        x2: SVector::<f64, 4>::new(q[0], q[1], qdot[0], qdot[1]),
        x1: SVector::<f64, 2>::new(q[0], qdot[0]),
        p: p.to_vector_with_gamma0(gamma0),
        loads2: loads.to_vector(),
        loads1: SVector::<f64, 3>::new(loads.m_gamma, in_plane, fz),
        t2: SVector::<f64, 9>::from_iterator(t.iter().flat_map(|v| v.iter().copied())),
        t1: SVector::<f64, 4>::new(t[0].x, t[0].z, t[1].x, t[1].z),
    }
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
    let gamma0 = check_state(p, q, qdot)?;
    variant.check(p, loads, q[1], qdot[1], t)?;
    let a = args(p, gamma0, loads, q, qdot, t);
    let gamma = q[0];
    let two = |s: rigid_peg::LinearSystem<f64>| solve::<5>(&s.a, &s.b, gamma);
    let one = |s: rigid_peg_planar::LinearSystem<f64>| solve::<3>(&s.a, &s.b, gamma);
    let (qdd, normal) = match variant {
        Variant::Full => split5(two(rigid_peg::forward(&a.x2, &a.p, &a.loads2, &a.t2))?),
        Variant::Frictionless => split5(two(rigid_peg_frictionless::forward(
            &a.x2, &a.p, &a.loads2,
        ))?),
        Variant::Planar => split3(one(rigid_peg_planar::forward(
            &a.x1, &a.p, &a.loads1, &a.t1,
        ))?),
        Variant::PlanarFrictionless => split3(one(rigid_peg_planar_frictionless::forward(
            &a.x1, &a.p, &a.loads1,
        ))?),
    };
    Ok(Accelerations { qdd, normal })
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
    let gamma0 = check_state(p, q, qdot)?;
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
    let a = args(p, gamma0, &loads, q, qdot, t);
    let (qdd2, qdd1) = (qdd, SVector::<f64, 1>::new(qdd[0]));
    let gamma = q[0];
    let two = |s: rigid_peg::LinearSystem<f64>| solve::<5>(&s.a, &s.b, gamma);
    let one = |s: rigid_peg_planar::LinearSystem<f64>| solve::<3>(&s.a, &s.b, gamma);
    let (moments, normal) = match variant {
        Variant::Full => split5(two(rigid_peg::prescribed(
            &a.x2, &qdd2, &a.p, &a.loads2, &a.t2,
        ))?),
        Variant::Frictionless => split5(two(rigid_peg_frictionless::prescribed(
            &a.x2, &qdd2, &a.p, &a.loads2,
        ))?),
        Variant::Planar => split3(one(rigid_peg_planar::prescribed(
            &a.x1, &qdd1, &a.p, &a.loads1, &a.t1,
        ))?),
        Variant::PlanarFrictionless => split3(one(rigid_peg_planar_frictionless::prescribed(
            &a.x1, &qdd1, &a.p, &a.loads1,
        ))?),
    };
    Ok(Reactions {
        m_gamma: moments[0],
        m_psi: moments[1],
        normal,
    })
}

/// [q̈ or M (2); N (3)] from the 2-DOF unknowns.
fn split5(x: SVector<f64, 5>) -> (Vector2<f64>, [f64; 3]) {
    (Vector2::new(x[0], x[1]), [x[2], x[3], x[4]])
}

/// [q̈ or M (2, the ψ part 0); N (3, N_B1 = N_B2 = N_B)] from the planar
/// unknowns.
fn split3(x: SVector<f64, 3>) -> (Vector2<f64>, [f64; 3]) {
    (Vector2::new(x[0], 0.0), [x[1], x[2], x[2]])
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
    let gamma0 = check_state(p, q, qdot)?;
    let a = args(
        p,
        gamma0,
        &Loads::default(),
        q,
        qdot,
        &[Vector3::zeros(); 3],
    );
    let v = match variant {
        Variant::Full => rigid_peg::contact_velocities(&a.x2, &a.p),
        Variant::Frictionless => rigid_peg_frictionless::contact_velocities(&a.x2, &a.p),
        _ if qdot[1] != 0.0 => return Err(variant.refuse("psidot is not zero")),
        Variant::Planar => rigid_peg_planar::contact_velocities(&a.x1, &a.p),
        Variant::PlanarFrictionless => {
            rigid_peg_planar_frictionless::contact_velocities(&a.x1, &a.p)
        }
    };
    Ok([0, 1, 2].map(|i| v.row(i).transpose()))
}

/// Friction directions t_i = −v_i/|v_i| from the contact velocities (the
/// hand-derived model's [`directions_opposing`](crate::rigid_peg::dynamics::directions_opposing)).
pub use crate::rigid_peg::dynamics::directions_opposing as friction_directions;
