//! Derivatives of the rigid three-point peg's accelerations and reactions
//! with respect to its parameters, the geometry included: the hole
//! diameter D, the peg diameter d and the height H (which places the
//! centre of mass, at H/2 on the axis), the mass, gravity and friction.
//!
//! The generated model's forward system `A(x, p) u = b(x, p, loads, t)`,
//! `u = (γ̈, ψ̈, N_K, N_B1, N_B2)`, has the generated parameter Jacobian
//! `forward_p = ∂(b − A u)/∂p` at the solution (`docs/sensitivities.md`,
//! "Parameter Jacobians, generated"), so
//!
//! ```text
//! ∂u/∂p = A⁻¹ forward_p                          (one more solve with the same A)
//! ```
//!
//! with p = (D_hole, d_peg, H, m, g, f, γ0). γ0 = arccos(d/D) is a
//! parameter of its own there; the runtime's [`PegParams`] computes it
//! from D and d, so a change of D or d also moves γ0:
//!
//! ```text
//! du/dD = ∂u/∂D + ∂u/∂γ0 · d/(D √(D² − d²)),    du/dd = ∂u/∂d − ∂u/∂γ0 / √(D² − d²)
//! ```
//!
//! [`forward_sensitivity`] holds the state (γ, ψ, γ̇, ψ̇), the loads and
//! the friction directions `t` fixed. Where friction opposes sliding,
//! `t_i = −v_i/|v_i|` and the contact velocities `v_i` move with the
//! geometry (D, d, H and γ0 place the contacts), so
//! [`sliding_forward_sensitivity`] adds their term:
//!
//! ```text
//! du/dp = A⁻¹ (∂(b − A u)/∂p + ∂(b − A u)/∂t · dt/dp),
//! dt_i/dp = −(I − t_i t_iᵀ)/|v_i| · ∂v_i/∂p
//! ```
//!
//! evaluated in one pass of the generated `contact_velocities` and
//! `forward` at dual numbers seeded on the seven parameters (the same
//! generated code, at [`Dual`] instead of `f64`).

use nalgebra::{SMatrix, SVector, Vector2, Vector3};

use crate::generated::rigid_peg;
use crate::rigid_peg::dynamics::{CONTACTS, solve};
use crate::rigid_peg::generated_inputs::{directions, state};
use crate::rigid_peg::generated_model::checked;
use crate::rigid_peg::{Loads, PegParams, RigidError};
use crate::scalar::{Dual, Real};

/// Derivatives of the forward unknowns with respect to one parameter
/// (each per unit of that parameter).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ForwardDerivative {
    /// Of the nutation acceleration γ̈ (rad/s² per unit).
    pub gammaddot: f64,
    /// Of the precession acceleration ψ̈ (rad/s² per unit).
    pub psiddot: f64,
    /// Of the normal force N_K at K (N per unit).
    pub n_k: f64,
    /// Of the normal force N_B1 at B1 (N per unit).
    pub n_b1: f64,
    /// Of the normal force N_B2 at B2 (N per unit).
    pub n_b2: f64,
}

impl ForwardDerivative {
    /// From the five unknowns' derivatives, in the order of the generated
    /// model's unknowns `u` (`rigid_peg::U_NAMES`: γ̈, ψ̈, N_K, N_B1, N_B2).
    fn from_unknowns(v: [f64; 5]) -> ForwardDerivative {
        let [gammaddot, psiddot, n_k, n_b1, n_b2] = v;
        ForwardDerivative {
            gammaddot,
            psiddot,
            n_k,
            n_b1,
            n_b2,
        }
    }

    /// The entries in the order of the unknowns (γ̈, ψ̈, N_K, N_B1, N_B2).
    pub fn to_array(&self) -> [f64; 5] {
        [self.gammaddot, self.psiddot, self.n_k, self.n_b1, self.n_b2]
    }
}

/// Derivatives of (γ̈, ψ̈, N_K, N_B1, N_B2) with respect to each field of
/// [`PegParams`], γ0 = arccos(d/D) following D and d.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ForwardSensitivity {
    /// With respect to the hole diameter D (per m), through γ0 too.
    pub hole_diameter: ForwardDerivative,
    /// With respect to the peg diameter d (per m), through γ0 too.
    pub peg_diameter: ForwardDerivative,
    /// With respect to the height H (per m): the length and the centre of
    /// mass at H/2.
    pub height: ForwardDerivative,
    /// With respect to the mass m (per kg).
    pub mass: ForwardDerivative,
    /// With respect to gravity g (per m/s²).
    pub gravity: ForwardDerivative,
    /// With respect to the friction coefficient f.
    pub friction: ForwardDerivative,
    /// With respect to γ0 alone (per rad), D and d held fixed: the
    /// generated model's own parameter, for callers that vary γ0
    /// independently.
    pub gamma0: ForwardDerivative,
}

/// `(∂γ0/∂D, ∂γ0/∂d)` of γ0 = arccos(d/D) (per m), with √(D² − d²)
/// formed as √((D − d)(D + d)) for a small clearance.
pub fn gamma0_gradient(p: &PegParams) -> [f64; 2] {
    let (dh, dp) = (p.hole_diameter, p.peg_diameter);
    let root = ((dh - dp) * (dh + dp)).sqrt();
    [dp / (dh * root), -1.0 / root]
}

/// The derivatives of the forward dynamics' accelerations and normal
/// forces (the full generated variant, `rigid_peg`) at state (q, q̇) under
/// `loads` with friction directions `t` (K, B1, B2; rotating components,
/// force on the peg), held fixed.
///
/// # Errors
/// As [`crate::rigid_peg::generated_model::forward`]: invalid parameters
/// or a non-finite state, γ outside (γ0, π/2), a singular system.
pub fn forward_sensitivity(
    p: &PegParams,
    loads: &Loads,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
    t: &[Vector3<f64>; 3],
) -> Result<ForwardSensitivity, RigidError> {
    let pv = checked(p, q, qdot)?.into();
    let x = state(q, qdot).into();
    let l = rigid_peg::Loads::from(loads).into();
    let tv = directions(t).into();
    let sys = rigid_peg::forward(&x, &pv, &l, &tv);
    let u = solve::<5, 1>(&sys.a, &sys.b, q[0])?;
    let rp = rigid_peg::forward_p(&x, &u, &pv, &l, &tv);
    let du = solve(&sys.a, &rp, q[0])?;
    Ok(named(&du, p))
}

/// `∂u/∂p` (rows the unknowns, columns the generated parameters) as
/// derivatives per runtime parameter, D and d through γ0 too.
fn named(du: &SMatrix<f64, 5, 7>, p: &PegParams) -> ForwardSensitivity {
    // Row i of ∂u/∂p with its columns named by the generated parameters,
    // so each derivative below is taken by parameter name.
    let rows: [rigid_peg::Params<f64>; 5] =
        std::array::from_fn(|i| rigid_peg::Params::from(du.row(i).transpose()));
    let along = |field: fn(&rigid_peg::Params<f64>) -> f64| {
        ForwardDerivative::from_unknowns(std::array::from_fn(|i| field(&rows[i])))
    };
    let g0 = along(|r| r.gamma0);
    let [g0_dh, g0_dp] = gamma0_gradient(p);
    // D and d also move γ0 = arccos(d/D): ∂u/∂D + ∂u/∂γ0 ∂γ0/∂D.
    let chain = |direct: ForwardDerivative, dg0: f64| {
        let (a, b) = (direct.to_array(), g0.to_array());
        ForwardDerivative::from_unknowns(std::array::from_fn(|i| a[i] + b[i] * dg0))
    };
    ForwardSensitivity {
        hole_diameter: chain(along(|r| r.D_hole), g0_dh),
        peg_diameter: chain(along(|r| r.d_peg), g0_dp),
        height: along(|r| r.H),
        mass: along(|r| r.m),
        gravity: along(|r| r.g),
        friction: along(|r| r.f),
        gamma0: g0,
    }
}

/// Dual numbers seeded on the generated model's seven parameters
/// (D, d, H, m, g, f, γ0).
type D7 = Dual<7>;

/// As [`forward_sensitivity`], with the friction directions opposing the
/// sliding velocities at (q, q̇), `t_i = −v_i/|v_i|`, and so moving with
/// the geometry: the derivatives of the runtime's forward dynamics where
/// each contact slides (the Coulomb law of [`crate::rigid_peg::forward`]).
///
/// # Errors
/// As [`forward_sensitivity`], and [`RigidError::NoSliding`] naming a
/// contact whose sliding speed is zero (its direction, and so the
/// derivative, is not defined there).
pub fn sliding_forward_sensitivity(
    p: &PegParams,
    loads: &Loads,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
) -> Result<ForwardSensitivity, RigidError> {
    let pv: SVector<f64, 7> = checked(p, q, qdot)?.into();
    let x: SVector<f64, 4> = state(q, qdot).into();
    let l: SVector<f64, 5> = rigid_peg::Loads::from(loads).into();
    let pd: SVector<D7, 7> = SVector::from_fn(|k, _| D7::variable(pv[k], k));
    let xd = x.map(D7::constant);
    let ld = l.map(D7::constant);
    let v = rigid_peg::contact_velocities(&xd, &pd);
    let mut t = [[D7::constant(0.0); 3]; 3];
    for (i, ti) in t.iter_mut().enumerate() {
        let vi = [v[(i, 0)], v[(i, 1)], v[(i, 2)]];
        let speed = (vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]).sqrt();
        if speed.v == 0.0 || !speed.v.is_finite() {
            return Err(RigidError::NoSliding {
                contact: CONTACTS[i],
            });
        }
        *ti = vi.map(|c| -c / speed);
    }
    let [k, b1, b2] = t;
    let td: SVector<D7, 9> = rigid_peg::FrictionDirections {
        t_K_eta: k[0],
        t_K_n: k[1],
        t_K_z: k[2],
        t_B1_eta: b1[0],
        t_B1_n: b1[1],
        t_B1_z: b1[2],
        t_B2_eta: b2[0],
        t_B2_n: b2[1],
        t_B2_z: b2[2],
    }
    .into();
    let sys = rigid_peg::forward(&xd, &pd, &ld, &td);
    let a = sys.a.map(|e| e.v);
    let u = solve::<5, 1>(&a, &sys.b.map(|e| e.v), q[0])?;
    // d(b − A u)/dp_k at the solution, u held: the right-hand side of
    // A du/dp_k = d(b − A u)/dp_k.
    let rhs = SMatrix::<f64, 5, 7>::from_fn(|i, k| {
        let au: f64 = (0..5).map(|j| sys.a[(i, j)].d[k] * u[j]).sum();
        sys.b[i].d[k] - au
    });
    let du = solve(&a, &rhs, q[0])?;
    Ok(named(&du, p))
}
