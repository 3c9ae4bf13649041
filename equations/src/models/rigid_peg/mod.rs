//! Dynamics of the rigid three-point peg leaning on the hole edge at K, B1, B2
//! ("Peg-on-hole: fundamental principles of motion of a peg leaning on a
//! horizontal hole edge", eqs. (22)–(31)), derived by the generator from first principles.
//!
//! Generalized coordinates q = (γ, ψ): nutation and precession, spin held
//! fixed; angular velocity ω = ψ̇ e_z − γ̇ e_n. All vectors are in the
//! rotating components (e_η, e_n, e_z) of [`geometry`], so
//! nothing depends on ψ except the fixed-frame assembly force, which is
//! rotated by −ψ. Velocities and accelerations of the centre of mass use the
//! transport theorem with the frame rate Ω = ψ̇ e_z,
//!
//! ```text
//! v_C = d/dt c + Ω × c,   a_C = d/dt v_C + Ω × v_C      (c = (η_C, 0, z_C))
//! ```
//!
//! with d/dt by [`Expr::dt`], so that no sin²ψ + cos²ψ has to cancel.
//!
//! - Kinetic energy T = ½ m |v_C|² + ½ (I_ζ (ω·u)² + I_ε ((ω·w)² + (ω·e_n)²))
//!   over the principal axes (u, w, e_n), I_ζ = m R²/2, I_ε = m(3R² + H²)/12,
//!   R = d/2; potential V = m g z_C.
//! - Generalized forces by virtual power: Q_j = M_j + F·∂v_C/∂q̇_j +
//!   Σ_i f N_i t_i·∂v_i/∂q̇_j, with v_i the material velocity of the peg at
//!   contact i (v_C + ω × (P_i − C)) and t_i the given unit friction
//!   direction. The normal forces do no virtual work (v_i·n_i ≡ 0).
//! - [`lagrange::derive`] gives M q̈ = f(q, q̇, N); the centre-of-mass rows
//!   are m a_C = F + m g + Σ_i N_i (n_i + f t_i).
//!
//! Everything is collected in a residual R (five rows: Lagrange γ, ψ;
//! centre of mass η, n, z) that is linear in q̈, the moments M and the normal
//! forces N; each variant's linear systems are its derivatives
//! ([`variants`]). Units: SI (m, kg, s, N, N·m, rad, J).

pub mod declare;
pub mod geometry;
pub mod variant;
pub mod variants;

use crate::expr::Expr;
use crate::graph::Graph;
use crate::lagrange;
use geometry::{Geometry, Params, Vec3, add, cross, dot, sub};

/// Names of the state components (x = (q, q̇)), in order.
pub const STATE: [&str; 4] = ["gamma", "psi", "gammadot", "psidot"];
/// Names of the accelerations q̈.
pub const ACCEL: [&str; 2] = ["gammaddot", "psiddot"];
/// Names of the loads: generalized moments `M_gamma`, `M_psi` (N·m) and the
/// assembly force at C in fixed-frame components `F_x`, `F_y`, `F_z` (N).
pub const LOADS: [&str; 5] = ["M_gamma", "M_psi", "F_x", "F_y", "F_z"];
/// Names of the normal forces on the peg at K, B1, B2 (N).
pub const NORMALS: [&str; 3] = ["N_K", "N_B1", "N_B2"];
/// Names of the contacts, in output order.
pub const CONTACTS: [&str; 3] = ["K", "B1", "B2"];
/// Names of the rotating components.
pub const AXES: [&str; 3] = ["eta", "n", "z"];

/// The derivation: symbols, residual rows and the auxiliary outputs.
pub struct Derivation<'g> {
    /// Parameters.
    pub p: Params<'g>,
    /// Geometry at γ.
    pub geo: Geometry<'g>,
    /// (γ, ψ, γ̇, ψ̇).
    pub state: [Expr<'g>; 4],
    /// (γ̈, ψ̈).
    pub accel: [Expr<'g>; 2],
    /// (M_γ, M_ψ, F_x, F_y, F_z).
    pub loads: [Expr<'g>; 5],
    /// (N_K, N_B1, N_B2).
    pub normal: [Expr<'g>; 3],
    /// Friction directions t_i (unit, force on the peg, rotating
    /// components), symbols `t_<contact>_<axis>`.
    pub friction_dir: [Vec3<'g>; 3],
    /// Residual rows, zero on solutions: `[M q̈ − f]_γ`, `[M q̈ − f]_ψ`, then
    /// `m a_C − F − m g − Σ N_i (n_i + f t_i)` along e_η, e_n, e_z.
    pub residual: [Expr<'g>; 5],
    /// Velocity v_C of the centre of mass, rotating components (m/s).
    pub com_velocity: Vec3<'g>,
    /// Acceleration a_C of the centre of mass, rotating components (m/s²).
    pub com_acceleration: Vec3<'g>,
    /// Material velocity of the peg at K, B1, B2 (m/s).
    pub contact_velocities: [Vec3<'g>; 3],
    /// Kinetic energy T (J).
    pub kinetic: Expr<'g>,
    /// T + V (J).
    pub energy: Expr<'g>,
}

/// Derives the 2-DOF model with friction in `g`.
pub fn derive(g: &Graph) -> Derivation<'_> {
    let p = Params::new(g);
    let state = STATE.map(|n| g.var(n));
    let accel = ACCEL.map(|n| g.var(n));
    let [gamma, psi, gd, pd] = state;
    let [gdd, pdd] = accel;
    let loads = LOADS.map(|n| g.param(n));
    let normal = NORMALS.map(|n| g.param(n));
    let friction_dir = CONTACTS.map(|c| AXES.map(|a| g.param(&format!("t_{c}_{a}"))));
    let geo = Geometry::new(g, &p, gamma);
    let zero = g.constant(0.0);
    let e_n = [zero, g.constant(1.0), zero];
    let pairs = [(gamma, gd), (psi, pd)];
    let all_pairs = [(gamma, gd), (psi, pd), (gd, gdd), (pd, pdd)];

    // Transport theorem in the frame turning at Ω = ψ̇ e_z.
    let frame_rate = [zero, zero, pd];
    let v_c = add(
        &geo.centre.map(|c| c.dt(&pairs)),
        &cross(&frame_rate, &geo.centre),
    );
    let a_c = add(&v_c.map(|c| c.dt(&all_pairs)), &cross(&frame_rate, &v_c));
    let omega = [zero, -gd, pd];
    let contact_velocities = geo
        .contacts
        .map(|pt| add(&v_c, &cross(&omega, &sub(&pt, &geo.centre))));

    // T and V from the rigid-body definitions.
    let (m, r) = (p.mass, 0.5 * p.peg);
    let i_axial = 0.5 * m * r.square();
    let i_trans = m * (3.0 * r.square() + p.height.square()) / 12.0;
    let kinetic = 0.5 * m * dot(g, &v_c, &v_c)
        + 0.5 * i_axial * dot(g, &omega, &geo.axis).square()
        + 0.5
            * i_trans
            * (dot(g, &omega, &geo.transverse).square() + dot(g, &omega, &e_n).square());
    let potential = m * p.gravity * geo.z_c;

    // Loads in rotating components: the fixed-frame force rotated by −ψ.
    let [m_gamma, m_psi, fx, fy, fz] = loads;
    let (sp, cp) = (psi.sin(), psi.cos());
    let force = [fx * cp + fy * sp, fy * cp - fx * sp, fz];
    let fric = p.friction;

    // Generalized forces by virtual power, one flat sum per coordinate so
    // that symmetric contributions of B1 and B2 can cancel term by term.
    let rates = [gd, pd];
    let q_forces: Vec<Expr<'_>> = [m_gamma, m_psi]
        .iter()
        .zip(rates)
        .map(|(&moment, rate)| {
            let mut terms = vec![moment];
            terms.extend((0..3).map(|k| force[k] * v_c[k].diff(rate)));
            for (i, v) in contact_velocities.iter().enumerate() {
                terms.extend(
                    (0..3).map(|k| fric * normal[i] * friction_dir[i][k] * v[k].diff(rate)),
                );
            }
            g.sum(terms)
        })
        .collect();
    let coords = [(gamma, gd, gdd), (psi, pd, pdd)];
    let lag = lagrange::derive(g, &coords, kinetic, potential, &q_forces);

    let lag_rows = (0..2).map(|i| {
        let inertia = g.sum((0..2).map(|j| lag.mass[i][j] * accel[j]));
        inertia - lag.forcing[i]
    });
    let weight = [zero, zero, -m * p.gravity];
    let com_rows = (0..3).map(|k| {
        let mut terms = vec![m * a_c[k], -force[k], -weight[k]];
        for i in 0..3 {
            terms.push(-normal[i] * geo.normals[i][k]);
            terms.push(-fric * normal[i] * friction_dir[i][k]);
        }
        g.sum(terms)
    });
    let rows: Vec<Expr<'_>> = lag_rows.chain(com_rows).collect();
    Derivation {
        p,
        geo,
        state,
        accel,
        loads,
        normal,
        friction_dir,
        residual: [rows[0], rows[1], rows[2], rows[3], rows[4]],
        com_velocity: v_c,
        com_acceleration: a_c,
        contact_velocities,
        kinetic,
        energy: lag.energy,
    }
}
