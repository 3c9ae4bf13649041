//! Lagrange's equations of the second kind, derived symbolically.
//!
//! For generalized coordinates q, kinetic energy T(q, q̇, t), potential
//! V(q, t) and generalized (non-conservative) forces Q,
//!
//!   d/dt ∂T/∂q̇_i − ∂T/∂q_i + ∂V/∂q_i = Q_i .
//!
//! Expanding the time derivative gives M(q) q̈ = f(q, q̇, t) with
//!
//!   M_ij = ∂²T/∂q̇_i∂q̇_j,
//!   f_i  = Q_i − ∂V/∂q_i + ∂T/∂q_i − Σ_j (∂²T/∂q̇_i∂q_j) q̇_j − ∂²T/∂q̇_i∂t.
//!
//! For a first-order state x = (q, q̇), ẋ = (q̇, M⁻¹f); an implicit integrator
//! needs J = ∂ẋ/∂x. Differentiating M q̈ = f gives
//!
//!   ∂q̈/∂x = M⁻¹ G,   G = ∂f/∂x − Σ_j (∂M_{·j}/∂x) q̈_j   (n × 2n),
//!
//! so J = [[0, I], [M⁻¹ G]] costs one LU solve of M at run time once G is
//! evaluated at the current q̈ (which the right-hand side has just computed).

use crate::expr::Expr;
use crate::graph::{Graph, SymKind};

/// One generalized coordinate: (q, q̇, q̈) as symbols.
pub type Coord<'g> = (Expr<'g>, Expr<'g>, Expr<'g>);

/// The equations of motion M(q) q̈ = f(q, q̇, p) of a Lagrangian system.
#[derive(Clone)]
pub struct Lagrange<'g> {
    /// The arena the expressions live in.
    pub g: &'g Graph,
    /// The coordinates (q, q̇, q̈), in order.
    pub coords: Vec<Coord<'g>>,
    /// Mass matrix M_ij = ∂²T/∂q̇_i∂q̇_j (symmetric by construction: the
    /// upper triangle is derived and mirrored).
    pub mass: Vec<Vec<Expr<'g>>>,
    /// Generalized forcing f_i (everything but M q̈).
    pub forcing: Vec<Expr<'g>>,
    /// Total mechanical energy T + V.
    pub energy: Expr<'g>,
}

/// Derives M and f from T, V and the generalized forces `q_forces` (one per
/// coordinate).
///
/// # Panics
/// If `q_forces.len() != coords.len()`, or a coordinate, velocity or
/// acceleration is not a symbol (bugs in the calling model).
pub fn derive<'g>(
    g: &'g Graph,
    coords: &[Coord<'g>],
    t: Expr<'g>,
    v: Expr<'g>,
    q_forces: &[Expr<'g>],
) -> Lagrange<'g> {
    let n = coords.len();
    assert_eq!(q_forces.len(), n, "one generalized force per coordinate");
    let time = g
        .lookup("t")
        .filter(|&s| g.sym_info(s).kind == SymKind::Time);
    let mut mass = vec![vec![g.constant(0.0); n]; n];
    let mut forcing = Vec::with_capacity(n);
    for (i, &(qi, qdi, _)) in coords.iter().enumerate() {
        let p_i = t.diff(qdi); // generalized momentum ∂T/∂q̇_i
        for (j, &(_, qdj, _)) in coords.iter().enumerate().skip(i) {
            let m = p_i.diff(qdj);
            mass[i][j] = m;
            mass[j][i] = m;
        }
        let gyro = g.sum(coords.iter().map(|&(qj, qdj, _)| p_i.diff(qj) * qdj));
        let explicit = time.map_or(g.constant(0.0), |s| {
            g.expr(crate::diff::diff(g, p_i.id(), s))
        });
        forcing.push(q_forces[i] - v.diff(qi) + t.diff(qi) - gyro - explicit);
    }
    Lagrange {
        g,
        coords: coords.to_vec(),
        mass,
        forcing,
        energy: t + v,
    }
}

impl<'g> Lagrange<'g> {
    /// Number of degrees of freedom.
    pub fn dof(&self) -> usize {
        self.coords.len()
    }

    /// The state x = (q_1..q_n, q̇_1..q̇_n).
    pub fn state(&self) -> Vec<Expr<'g>> {
        let q = self.coords.iter().map(|c| c.0);
        q.chain(self.coords.iter().map(|c| c.1)).collect()
    }

    /// The accelerations q̈ as symbols.
    pub fn accelerations(&self) -> Vec<Expr<'g>> {
        self.coords.iter().map(|c| c.2).collect()
    }

    /// G = ∂f/∂x − Σ_j (∂M_{·j}/∂x) q̈_j, n × 2n, with q̈ as free symbols.
    pub fn accel_jacobian_terms(&self) -> Vec<Vec<Expr<'g>>> {
        let x = self.state();
        let qdd = self.accelerations();
        (0..self.dof())
            .map(|i| {
                x.iter()
                    .map(|&xk| {
                        let dm = self
                            .g
                            .sum(qdd.iter().zip(&self.mass[i]).map(|(&a, &m)| m.diff(xk) * a));
                        self.forcing[i].diff(xk) - dm
                    })
                    .collect()
            })
            .collect()
    }

    /// q̈ = M⁻¹ f in closed form by Cramer's rule, for 1 to 3 degrees of
    /// freedom (`None` beyond: solve M q̈ = f numerically at run time).
    pub fn accelerations_solved(&self) -> Option<Vec<Expr<'g>>> {
        let n = self.dof();
        if n == 0 || n > 3 {
            return None;
        }
        let det = det(self.g, &self.mass);
        Some(
            (0..n)
                .map(|k| {
                    let mut a = self.mass.clone();
                    for (row, f) in a.iter_mut().zip(&self.forcing) {
                        row[k] = *f;
                    }
                    crate::lagrange::det(self.g, &a) / det
                })
                .collect(),
        )
    }

    /// ẋ = (q̇, M⁻¹ f), when [`Lagrange::accelerations_solved`] applies.
    pub fn rhs(&self) -> Option<Vec<Expr<'g>>> {
        let qdd = self.accelerations_solved()?;
        Some(self.coords.iter().map(|c| c.1).chain(qdd).collect())
    }
}

/// Determinant of a 1×1, 2×2 or 3×3 matrix by cofactor expansion.
///
/// # Panics
/// For larger matrices.
pub fn det<'g>(g: &'g Graph, a: &[Vec<Expr<'g>>]) -> Expr<'g> {
    match a.len() {
        1 => a[0][0],
        2 => a[0][0] * a[1][1] - a[0][1] * a[1][0],
        3 => g.sum((0..3).map(|j| {
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            a[0][j] * (a[1][j1] * a[2][j2] - a[1][j2] * a[2][j1])
        })),
        n => panic!("det: {n}×{n} not supported (solve numerically)"),
    }
}
