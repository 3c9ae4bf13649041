//! Contact modes of the sliding peg: which of K, B1, B2 stay in contact
//! (the Painlevé check).
//!
//! The three-point model has 2 DOF (γ, ψ; spin locked). With a contact
//! allowed to separate, the peg has the coordinates p = (r_C, γ, ψ): centre
//! of mass free (fixed-frame components, written along (e_η, e_n, e_z) at
//! the instant), spin still locked. Newton–Euler in these coordinates:
//!
//! ```text
//! diag(m, m, m, I_ε, I_ε sin²γ + I_ζ cos²γ) p̈ = Q0 + Σ_i N_i B_i
//! Q0 = (F + m g, M_γ + (I_ε − I_ζ) sγ cγ ψ̇², M_ψ − 2 (I_ε − I_ζ) sγ cγ γ̇ ψ̇)
//! B_i = (f_i, −e_n·(ρ_i × f_i), e_z·(ρ_i × f_i)),  f_i = n_i + f t_i
//! ```
//!
//! with ρ_i = P_i − C. The normal acceleration of contact i is
//! g̈_i = G_i p̈ − n_i·a_C⁰, G_i = (n_i, −e_n·(ρ_i × n_i), e_z·(ρ_i × n_i)),
//! where a_C⁰ = J̇_C q̇ is the centre's acceleration of the three-point motion
//! with q̈ = 0: the velocity lies on the three-point manifold, so the
//! curvature terms of the gaps equal −G_i (a_C⁰, 0, 0) (no curvature formula
//! needed). A mode S ⊆ {K, B1, B2} is consistent when g̈_S = 0, N_S ≥ 0,
//! and g̈_j ≥ 0, N_j = 0 off S. S = all reproduces the forward problem
//! (`tests/rigid_peg/forward.rs`). Friction directions are fixed by the sliding
//! velocities, so each mode is a linear solve (8 modes).

use nalgebra::{Matrix3, SMatrix, SVector, Vector2, Vector3};

use crate::rigid_peg::dynamics::com_bias;
use crate::rigid_peg::forward::ForwardModel;
use crate::rigid_peg::kinematics::Pose;
use crate::rigid_peg::{PegParams, RigidError};

type Vector5 = SVector<f64, 5>;

/// One consistent contact mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mode {
    /// Which of `[K, B1, B2]` stay in contact.
    pub in_contact: [bool; 3],
    /// Normal reactions (N), zero off the mode.
    pub normal: [f64; 3],
    /// Normal accelerations g̈ (m/s², ≥ 0 = separating), zero on the mode.
    pub separation: [f64; 3],
}

impl Mode {
    /// True for the three-point mode.
    pub fn is_three_point(&self) -> bool {
        self.in_contact.iter().all(|&c| c)
    }
}

/// The contact LCP of one state: W N + w = g̈ (3×3, m/s²/N and m/s²).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactProblem {
    /// Delassus-type matrix W_ij = G_i M⁻¹ B_j (non-symmetric with friction).
    pub w_matrix: Matrix3<f64>,
    /// Free normal accelerations w (all N = 0).
    pub w_free: Vector3<f64>,
}

fn cross_terms(rho: &Vector3<f64>, f: &Vector3<f64>) -> (f64, f64) {
    let m = rho.cross(f);
    (-m[1], m[2])
}

/// The contact problem at (q, q̇) with the friction directions of `model`
/// (sliding state).
///
/// # Errors
/// As [`ForwardModel::friction_directions`].
pub fn contact_problem(
    model: &ForwardModel,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
) -> Result<ContactProblem, RigidError> {
    let p: &PegParams = &model.params;
    let pose = Pose::try_new(p, q[0], q[1])?;
    let t = model.friction_directions(q, qdot, None)?;
    let (s, c) = q[0].sin_cos();
    let (it, ia) = (p.inertia_transverse(), p.inertia_axial());
    let minv = Vector5::new(
        1.0 / p.mass,
        1.0 / p.mass,
        1.0 / p.mass,
        1.0 / it,
        1.0 / (it * s * s + ia * c * c),
    );
    let ld = &model.loads;
    let force = pose.frame.matrix().transpose() * Vector3::from(ld.force);
    let (gd, pd) = (qdot[0], qdot[1]);
    let k = (it - ia) * s * c;
    let q0 = Vector5::new(
        force[0],
        force[1],
        force[2] - p.mass * p.gravity,
        ld.m_gamma + k * pd * pd,
        ld.m_psi - 2.0 * k * gd * pd,
    );
    let bias = com_bias(&pose, qdot);
    let mut g = SMatrix::<f64, 3, 5>::zeros();
    let mut b = SMatrix::<f64, 5, 3>::zeros();
    let mut bias_n = Vector3::zeros();
    for i in 0..3 {
        let rho = pose.local.contacts[i] - pose.local.c;
        let n = pose.local.normals[i];
        let f = n + t[i] * p.friction;
        let (gn, pn) = cross_terms(&rho, &n);
        let (gf, pf) = cross_terms(&rho, &f);
        g.set_row(i, &SMatrix::<f64, 1, 5>::from([n[0], n[1], n[2], gn, pn]));
        b.set_column(i, &Vector5::new(f[0], f[1], f[2], gf, pf));
        bias_n[i] = n.dot(&bias);
    }
    let minv_b = SMatrix::<f64, 5, 3>::from_fn(|r, col| minv[r] * b[(r, col)]);
    Ok(ContactProblem {
        w_matrix: g * minv_b,
        w_free: g * minv.component_mul(&q0) - bias_n,
    })
}

impl ContactProblem {
    /// Every consistent mode (tolerance 1e-9 on N and g̈ relative to the
    /// problem's scale).
    pub fn consistent_modes(&self) -> Vec<Mode> {
        let scale_g = self.w_free.amax().max(1e-300);
        let mut out = Vec::new();
        for bits in 0u8..8 {
            let on = [bits & 1 != 0, bits & 2 != 0, bits & 4 != 0];
            let idx: Vec<usize> = (0..3).filter(|&i| on[i]).collect();
            let mut normal = Vector3::zeros();
            if !idx.is_empty() {
                let n = idx.len();
                let sub = nalgebra::DMatrix::from_fn(n, n, |r, c| self.w_matrix[(idx[r], idx[c])]);
                let rhs = nalgebra::DVector::from_fn(n, |r, _| -self.w_free[idx[r]]);
                let Some(sol) = sub.lu().solve(&rhs) else {
                    continue;
                };
                for (r, &i) in idx.iter().enumerate() {
                    normal[i] = sol[r];
                }
            }
            let sep = self.w_matrix * normal + self.w_free;
            let scale_n = normal
                .amax()
                .max(scale_g / self.w_matrix.amax().max(1e-300));
            let ok = (0..3).all(|i| {
                if on[i] {
                    normal[i] >= -1e-9 * scale_n
                } else {
                    sep[i] >= -1e-9 * scale_g.max(self.w_matrix.amax() * scale_n)
                }
            });
            if ok && normal.iter().all(|v| v.is_finite()) {
                out.push(Mode {
                    in_contact: on,
                    normal: [normal[0], normal[1], normal[2]],
                    separation: [
                        if on[0] { 0.0 } else { sep[0] },
                        if on[1] { 0.0 } else { sep[1] },
                        if on[2] { 0.0 } else { sep[2] },
                    ],
                });
            }
        }
        out
    }
}

/// What the rigid model says about a sliding state.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// The three-point mode is the only consistent one.
    ThreePoint,
    /// The three-point mode needs a pulling contact; exactly one mode with
    /// fewer contacts is consistent: those contacts lift off.
    LiftOff(Mode),
    /// No mode is consistent (Painlevé inconsistency).
    Inconsistent,
    /// Several modes are consistent (Painlevé indeterminacy).
    Indeterminate(Vec<Mode>),
}

/// Classifies the sliding state (q, q̇).
///
/// # Errors
/// As [`contact_problem`].
pub fn classify(
    model: &ForwardModel,
    q: Vector2<f64>,
    qdot: Vector2<f64>,
) -> Result<Verdict, RigidError> {
    let modes = contact_problem(model, q, qdot)?.consistent_modes();
    Ok(match modes.as_slice() {
        [] => Verdict::Inconsistent,
        [m] if m.is_three_point() => Verdict::ThreePoint,
        [m] => Verdict::LiftOff(*m),
        _ => Verdict::Indeterminate(modes),
    })
}
