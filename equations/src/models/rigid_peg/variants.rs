//! The generated modules of the rigid three-point peg: four variants of one
//! derivation ([`super::derive`]), specialized by substitution
//! at generation time.
//!
//! | module | coordinates | unknowns (forward) | friction input |
//! |---|---|---|---|
//! | `rigid_peg` | γ, ψ | γ̈, ψ̈, N_K, N_B1, N_B2 | t (9) |
//! | `rigid_peg_frictionless` | γ, ψ | γ̈, ψ̈, N_K, N_B1, N_B2 | — (f = 0) |
//! | `rigid_peg_planar` | γ (ψ ≡ 0) | γ̈, N_K, N_B (= N_B1 = N_B2) | t (4) |
//! | `rigid_peg_planar_frictionless` | γ (ψ ≡ 0) | γ̈, N_K, N_B | — |
//!
//! Planar: ψ = ψ̇ = ψ̈ = 0, M_ψ = 0, no lateral force (F_y = 0 at ψ = 0),
//! N_B1 = N_B2 = N_B, and friction in the symmetry plane with B1 and B2
//! sliding alike (t_B1 = t_B2 = t_B, no e_n components; the planar motion
//! gives v_B1 = v_B2 exactly). The builder then checks that the ψ Lagrange
//! row and the lateral centre-of-mass row have become the constant 0 — the
//! planar motion is a solution of the 2-DOF equations — and drops them.
//!
//! Each variant's systems are derivatives of the residual R (linear in its
//! unknowns u): A = ∂R/∂u, b = −R|_{u=0}. For the Lagrange rows this is
//! A = [M | −∂f/∂N], b = f|_{N=0}. Each variant is declared as a model in
//! [`super::declare`].

use super::Derivation;
use crate::expr::Expr;
use crate::graph::Graph;
use crate::subst::Substitution;

pub use super::variant::Variant;

/// A variant's symbols and specialized expressions.
pub struct Specialized<'g> {
    /// The state x.
    pub state: Vec<Expr<'g>>,
    /// The accelerations q̈.
    pub accel: Vec<Expr<'g>>,
    /// The loads input.
    pub loads: Vec<Expr<'g>>,
    /// The friction-direction input (empty without friction).
    pub friction_dir: Vec<Expr<'g>>,
    /// The normal-force unknowns.
    pub normal: Vec<Expr<'g>>,
    /// The generalized moments M (unknowns of the prescribed problem).
    pub moments: Vec<Expr<'g>>,
    /// The retained residual rows.
    pub rows: Vec<Expr<'g>>,
    /// The rows the specialization made vanish identically (dropped).
    pub vanished: Vec<Expr<'g>>,
    /// Contact velocities, rows K, B1, B2.
    pub contact_velocities: Vec<Vec<Expr<'g>>>,
    /// T + V.
    pub energy: Expr<'g>,
    /// T.
    pub kinetic: Expr<'g>,
}

/// Specializes the derivation `d` to `variant`.
pub fn specialize<'g>(g: &'g Graph, d: &Derivation<'g>, variant: Variant) -> Specialized<'g> {
    let zero = g.constant(0.0);
    let [gamma, psi, gd, pd] = d.state;
    let [gdd, pdd] = d.accel;
    let [m_gamma, m_psi, fx, fy, fz] = d.loads;
    let [n_k, n_b1, n_b2] = d.normal;
    let t = d.friction_dir;
    let mut pairs = Vec::new();
    if !variant.has_friction() {
        pairs.push((d.p.friction, zero));
    }
    let (state, accel, loads, normal, moments, keep, drop);
    let mut friction_dir: Vec<Expr<'g>> = Vec::new();
    if variant.is_planar() {
        let n_b = g.param("N_B");
        let (tb_eta, tb_z) = (g.param("t_B_eta"), g.param("t_B_z"));
        pairs.extend([
            (psi, zero),
            (pd, zero),
            (pdd, zero),
            (m_psi, zero),
            (fy, zero),
        ]);
        pairs.extend([(n_b1, n_b), (n_b2, n_b)]);
        pairs.extend(t.iter().map(|ti| (ti[1], zero)));
        pairs.extend([(t[1][0], tb_eta), (t[2][0], tb_eta)]);
        pairs.extend([(t[1][2], tb_z), (t[2][2], tb_z)]);
        state = vec![gamma, gd];
        accel = vec![gdd];
        loads = vec![m_gamma, fx, fz];
        normal = vec![n_k, n_b];
        moments = vec![m_gamma];
        friction_dir.extend([t[0][0], t[0][2], tb_eta, tb_z]);
        (keep, drop) = (vec![0, 2, 4], vec![1, 3]);
    } else {
        state = d.state.to_vec();
        accel = d.accel.to_vec();
        loads = d.loads.to_vec();
        normal = vec![n_k, n_b1, n_b2];
        moments = vec![m_gamma, m_psi];
        friction_dir.extend(t.iter().flatten());
        (keep, drop) = (vec![0, 1, 2, 3, 4], vec![]);
    }
    if !variant.has_friction() {
        friction_dir.clear();
    }
    let mut s = Substitution::new(&pairs);
    let rows = keep.iter().map(|&i| s.apply(d.residual[i])).collect();
    let vanished = drop.iter().map(|&i| s.apply(d.residual[i])).collect();
    let contact_velocities = d
        .contact_velocities
        .iter()
        .map(|v| v.iter().map(|&c| s.apply(c)).collect())
        .collect();
    Specialized {
        state,
        accel,
        loads,
        friction_dir,
        normal,
        moments,
        rows,
        vanished,
        contact_velocities,
        energy: s.apply(d.energy),
        kinetic: s.apply(d.kinetic),
    }
}

/// A linear system A u = b from residual rows linear in `unknowns`:
/// A = ∂R/∂u, b = −R|_{u=0}.
pub fn linear_system<'g>(
    g: &'g Graph,
    rows: &[Expr<'g>],
    unknowns: &[Expr<'g>],
) -> (Vec<Vec<Expr<'g>>>, Vec<Expr<'g>>) {
    let zero = g.constant(0.0);
    let a = rows
        .iter()
        .map(|r| unknowns.iter().map(|&u| r.diff(u)).collect())
        .collect();
    let pairs: Vec<(Expr<'g>, Expr<'g>)> = unknowns.iter().map(|&u| (u, zero)).collect();
    let mut s = Substitution::new(&pairs);
    let b = rows.iter().map(|&r| -s.apply(r)).collect();
    (a, b)
}
