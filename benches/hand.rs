//! Hand-derived closed forms of the generated functions, with exactly the
//! generated signatures, so that benches time both on the same inputs and
//! `tests/generator/hand_forms.rs` checks that both agree (an independent derivation).
//!
//! Textbook systems (Goldstein §1.6; Tedrake, *Underactuated Robotics*,
//! ch. 3), written from the closed forms, not from the generated code:
//! `M q̈ = f`, `ẋ = (q̇, M⁻¹ f)` by Cramer's rule, and the Jacobian terms
//! `G = ∂f/∂x − Σⱼ (∂M₍·ⱼ₎/∂x) q̈ⱼ` (n × 2n). Hertz: `src/hertz/contact.rs`
//! (9)–(13). Quasi-statics: `pegdyn::jamming::quasi_static` (Eqs. 51–54)
//! and `pegdyn::jamming::forces` (Whitney's frame).

use nalgebra::{Matrix1, Matrix1x2, Matrix2, Matrix2x4, SMatrix, SVector, Vector2, Vector4};
use pegdyn::jamming::PegHole;
use pegdyn::jamming::forces::{sliding_contact_forces, sliding_wrench};
use pegdyn::jamming::quasi_static::{PaperPeg, PegAcc, PegLoad};

type V<const N: usize> = SVector<f64, N>;

/// `(q̇, M⁻¹ f)` for two coordinates, `x = (q, q̇)`, by Cramer's rule
/// (`M` symmetric).
fn cramer_rhs(x: &V<4>, mm: &Matrix2<f64>, f: &Vector2<f64>) -> V<4> {
    let det = mm[(0, 0)] * mm[(1, 1)] - mm[(0, 1)] * mm[(0, 1)];
    Vector4::new(
        x[2],
        x[3],
        (f[0] * mm[(1, 1)] - mm[(0, 1)] * f[1]) / det,
        (mm[(0, 0)] * f[1] - mm[(0, 1)] * f[0]) / det,
    )
}

/// Simple pendulum, `x = (θ, θ̇)`, `p = (m, l, g)`.
pub mod pendulum {
    use super::*;

    /// `M = m l²`, `f = −m g l sin θ`.
    pub fn dynamics(x: &V<2>, p: &V<3>) -> (SMatrix<f64, 1, 1>, V<1>) {
        let (m, l, g) = (p[0], p[1], p[2]);
        (
            Matrix1::new(m * l * l),
            V::<1>::new(-m * g * l * x[0].sin()),
        )
    }

    /// `(θ̇, −(g/l) sin θ)`.
    pub fn rhs(x: &V<2>, p: &V<3>) -> V<2> {
        Vector2::new(x[1], -p[2] / p[1] * x[0].sin())
    }

    /// `G = (−m g l cos θ, 0)` (M is constant).
    pub fn jacobian_terms(x: &V<2>, _qdd: &V<1>, p: &V<3>) -> SMatrix<f64, 1, 2> {
        Matrix1x2::new(-p[0] * p[2] * p[1] * x[0].cos(), 0.0)
    }

    /// `½ m l² θ̇² − m g l cos θ`.
    pub fn energy(x: &V<2>, p: &V<3>) -> f64 {
        let (m, l, g) = (p[0], p[1], p[2]);
        0.5 * m * l * l * x[1] * x[1] - m * g * l * x[0].cos()
    }
}

/// Double pendulum with absolute angles, `x = (θ₁, θ₂, θ̇₁, θ̇₂)`,
/// `p = (m₁, m₂, l₁, l₂, g)`. With `k = m₂ l₁ l₂`, `c = cos(θ₁ − θ₂)`,
/// `s = sin(θ₁ − θ₂)`: `M = [[(m₁+m₂) l₁², k c], [k c, m₂ l₂²]]`,
/// `f = (−k θ̇₂² s − (m₁+m₂) g l₁ sin θ₁, k θ̇₁² s − m₂ g l₂ sin θ₂)`.
pub mod double_pendulum {
    use super::*;

    fn parts(x: &V<4>, p: &V<5>) -> (Matrix2<f64>, Vector2<f64>) {
        let (m1, m2, l1, l2, g) = (p[0], p[1], p[2], p[3], p[4]);
        let (s, c) = (x[0] - x[1]).sin_cos();
        let k = m2 * l1 * l2;
        let mass = Matrix2::new((m1 + m2) * l1 * l1, k * c, k * c, m2 * l2 * l2);
        let forcing = Vector2::new(
            -k * x[3] * x[3] * s - (m1 + m2) * g * l1 * x[0].sin(),
            k * x[2] * x[2] * s - m2 * g * l2 * x[1].sin(),
        );
        (mass, forcing)
    }

    /// Mass matrix and forcing.
    pub fn dynamics(x: &V<4>, p: &V<5>) -> (SMatrix<f64, 2, 2>, V<2>) {
        parts(x, p)
    }

    /// `(θ̇₁, θ̇₂, M⁻¹ f)` by Cramer's rule.
    pub fn rhs(x: &V<4>, p: &V<5>) -> V<4> {
        let (mm, f) = parts(x, p);
        cramer_rhs(x, &mm, &f)
    }

    /// `G` (2 × 4) from the derivatives of `f` and of `M₁₂ = k c`
    /// (`∂M₁₂/∂θ₁ = −k s = −∂M₁₂/∂θ₂`).
    pub fn jacobian_terms(x: &V<4>, qdd: &V<2>, p: &V<5>) -> SMatrix<f64, 2, 4> {
        let (m1, m2, l1, l2, g) = (p[0], p[1], p[2], p[3], p[4]);
        let (s, c) = (x[0] - x[1]).sin_cos();
        let k = m2 * l1 * l2;
        let (w1, w2) = (x[2], x[3]);
        Matrix2x4::new(
            -k * w2 * w2 * c - (m1 + m2) * g * l1 * x[0].cos() + k * s * qdd[1],
            k * w2 * w2 * c - k * s * qdd[1],
            0.0,
            -2.0 * k * w2 * s,
            k * w1 * w1 * c + k * s * qdd[0],
            -k * w1 * w1 * c - m2 * g * l2 * x[1].cos() - k * s * qdd[0],
            2.0 * k * w1 * s,
            0.0,
        )
    }

    /// `T + V`.
    pub fn energy(x: &V<4>, p: &V<5>) -> f64 {
        let (m1, m2, l1, l2, g) = (p[0], p[1], p[2], p[3], p[4]);
        let c = (x[0] - x[1]).cos();
        let (w1, w2) = (x[2], x[3]);
        0.5 * (m1 + m2) * l1 * l1 * w1 * w1
            + 0.5 * m2 * l2 * l2 * w2 * w2
            + m2 * l1 * l2 * w1 * w2 * c
            - (m1 + m2) * g * l1 * x[0].cos()
            - m2 * g * l2 * x[1].cos()
    }
}

/// Cart-pole, `x = (x_c, θ, ẋ_c, θ̇)`, `p = (m_c, m, l, g, u)`:
/// `M = [[m_c + m, m l cos θ], [m l cos θ, m l²]]`,
/// `f = (u + m l θ̇² sin θ, −m g l sin θ)`.
pub mod cart_pole {
    use super::*;

    fn parts(x: &V<4>, p: &V<5>) -> (Matrix2<f64>, Vector2<f64>) {
        let (mc, m, l, g, u) = (p[0], p[1], p[2], p[3], p[4]);
        let (s, c) = x[1].sin_cos();
        let mass = Matrix2::new(mc + m, m * l * c, m * l * c, m * l * l);
        let forcing = Vector2::new(u + m * l * x[3] * x[3] * s, -m * g * l * s);
        (mass, forcing)
    }

    /// Mass matrix and forcing.
    pub fn dynamics(x: &V<4>, p: &V<5>) -> (SMatrix<f64, 2, 2>, V<2>) {
        parts(x, p)
    }

    /// `(ẋ_c, θ̇, M⁻¹ f)` by Cramer's rule.
    pub fn rhs(x: &V<4>, p: &V<5>) -> V<4> {
        let (mm, f) = parts(x, p);
        cramer_rhs(x, &mm, &f)
    }

    /// `G` (2 × 4); only `M₁₂ = m l cos θ` depends on the state.
    pub fn jacobian_terms(x: &V<4>, qdd: &V<2>, p: &V<5>) -> SMatrix<f64, 2, 4> {
        let (m, l, g) = (p[1], p[2], p[3]);
        let (s, c) = x[1].sin_cos();
        let w = x[3];
        Matrix2x4::new(
            0.0,
            m * l * w * w * c + m * l * s * qdd[1],
            0.0,
            2.0 * m * l * w * s,
            0.0,
            -m * g * l * c + m * l * s * qdd[0],
            0.0,
            0.0,
        )
    }

    /// `T + V`.
    pub fn energy(x: &V<4>, p: &V<5>) -> f64 {
        let (mc, m, l, g) = (p[0], p[1], p[2], p[3]);
        let c = x[1].cos();
        let (v, w) = (x[2], x[3]);
        0.5 * (mc + m) * v * v + m * l * c * v * w + 0.5 * m * l * l * w * w - m * g * l * c
    }
}

/// Hertz contact, `c = (Σρ, E*, m_a, m_b, δ*)` (`src/hertz/contact.rs`).
pub mod hertz {
    use super::*;

    /// `a, b = m_{a,b} (3Q/(2ΣρE*))^{1/3}`, `p₀ = 3Q/(2π a b)`,
    /// `δ = δ* (⅛ (3/(2E*))² Q² Σρ)^{1/3}`; `Q = max(load, 0)`.
    pub fn ellipse(load: &V<1>, c: &V<5>) -> (f64, f64, f64, f64) {
        let q = if load[0] > 0.0 || load[0].is_nan() {
            load[0]
        } else {
            0.0
        };
        let (sum, e, ma, mb, ds) = (c[0], c[1], c[2], c[3], c[4]);
        let t = (1.5 * q / (sum * e)).cbrt();
        let (a, b) = (ma * t, mb * t);
        let p0 = 1.5 * q / (std::f64::consts::PI * a * b);
        let r = 1.5 / e;
        let delta = ds * (0.125 * r * r * q * q * sum).cbrt();
        (a, b, p0, delta)
    }

    /// `k = (2E*/3) √(8 / (δ*³ Σρ))`.
    pub fn stiffness(c: &V<5>) -> f64 {
        2.0 / 3.0 * c[1] * (8.0 / (c[4] * c[4] * c[4] * c[0])).sqrt()
    }
}

/// Quasi-static contact forces: `pegdyn::jamming` hand forms.
pub mod quasi_static {
    use super::*;

    fn peg(pose: &V<2>, p: &V<5>) -> PaperPeg {
        PaperPeg {
            theta: pose[0],
            l: pose[1],
            mu: p[0],
            r: p[1],
            l_c: p[2],
            m: p[3],
            j: p[4],
        }
    }

    fn parts(load: &V<2>, acc: &V<3>) -> (PegLoad, PegAcc) {
        (
            PegLoad {
                f1: load[0],
                f2: load[1],
            },
            PegAcc {
                xdd: acc[0],
                ydd: acc[1],
                thdd: acc[2],
            },
        )
    }

    /// Eq. 52: `(f_A, f_B, M)`.
    pub fn two_point(pose: &V<2>, load: &V<2>, acc: &V<3>, p: &V<5>) -> (f64, f64, f64) {
        let (u, a) = parts(load, acc);
        let s = peg(pose, p).two_point(u, a);
        (s.f_a, s.f_b, s.m)
    }

    /// Eq. 53 (corrected): `(f_A, M)`.
    pub fn edge_only(pose: &V<2>, load: &V<2>, acc: &V<3>, p: &V<5>) -> (f64, f64) {
        let (u, a) = parts(load, acc);
        let s = peg(pose, p).edge_only(u, a);
        (s.f_a, s.m)
    }

    /// Eq. 54: `(f_B, M)`.
    pub fn tip_only(pose: &V<2>, load: &V<2>, acc: &V<3>, p: &V<5>) -> (f64, f64) {
        let (u, a) = parts(load, acc);
        let s = peg(pose, p).tip_only(u, a);
        (s.f_b, s.m)
    }

    /// Whitney's frame at the tip: `(f_tip, f_edge, M)`; NaN for a
    /// radius or friction `PegHole` rejects.
    pub fn whitney_tip(pose: &V<2>, w: &V<2>, q: &V<2>) -> (f64, f64, f64) {
        let Ok(hole) = PegHole::try_new(q[1], 0.01, q[0]) else {
            return (f64::NAN, f64::NAN, f64::NAN);
        };
        let f = sliding_contact_forces(&hole, pose[0], w[0], w[1]);
        let m = sliding_wrench(&hole, pose[1], pose[0], f).m;
        (f.tip, f.edge, m)
    }
}

/// The rigid three-point peg: `pegdyn::rigid_peg::kinematics` and
/// `dynamics` (hand-derived) from the generated functions' inputs
/// `x = (γ, ψ, γ̇, ψ̇)`, `p = (D, d, H, m, g, f, γ0)`,
/// `loads = (M_γ, M_ψ, F_x, F_y, F_z)`, `t` = friction directions at K, B1,
/// B2 (local components). The hand path includes building the pose from γ,
/// ψ (its geometry), as the generated code does. NaN outside the
/// three-point range.
pub mod rigid_peg {
    use super::*;
    use nalgebra::{Matrix3, Vector3};
    use pegdyn::rigid_peg::dynamics::{
        forward_system, kinetic_energy, potential_energy, prescribed_system,
    };
    use pegdyn::rigid_peg::kinematics::Pose;
    use pegdyn::rigid_peg::{Loads, PegParams};

    pub(crate) fn params(p: &V<7>) -> PegParams {
        PegParams {
            hole_diameter: p[0],
            peg_diameter: p[1],
            height: p[2],
            mass: p[3],
            gravity: p[4],
            friction: p[5],
        }
    }

    fn loads(l: &V<5>) -> Loads {
        Loads {
            m_gamma: l[0],
            m_psi: l[1],
            force: [l[2], l[3], l[4]],
        }
    }

    fn directions(t: &V<9>) -> [Vector3<f64>; 3] {
        [0, 3, 6].map(|k| Vector3::new(t[k], t[k + 1], t[k + 2]))
    }

    type System = (SMatrix<f64, 5, 5>, V<5>);

    fn nan_system() -> System {
        (SMatrix::repeat(f64::NAN), V::repeat(f64::NAN))
    }

    /// `forward_system`: `A u = b` for `u = (γ̈, ψ̈, N_K, N_B1, N_B2)`.
    pub fn forward(x: &V<4>, p: &V<7>, l: &V<5>, t: &V<9>) -> System {
        let pp = params(p);
        let Ok(pose) = Pose::try_new(&pp, x[0], x[1]) else {
            return nan_system();
        };
        forward_system(
            &pp,
            &loads(l),
            &pose,
            Vector2::new(x[2], x[3]),
            &directions(t),
        )
    }

    /// `prescribed_system`: `A u = b` for `u = (M_γ, M_ψ, N_K, N_B1, N_B2)`.
    pub fn prescribed(x: &V<4>, qdd: &V<2>, p: &V<7>, l: &V<5>, t: &V<9>) -> System {
        let pp = params(p);
        let Ok(pose) = Pose::try_new(&pp, x[0], x[1]) else {
            return nan_system();
        };
        let qd = Vector2::new(x[2], x[3]);
        prescribed_system(&pp, &loads(l), &pose, qd, *qdd, &directions(t))
    }

    /// Contact-point velocities in local components (rows K, B1, B2).
    pub fn contact_velocities(x: &V<4>, p: &V<7>) -> SMatrix<f64, 3, 3> {
        let Ok(pose) = Pose::try_new(&params(p), x[0], x[1]) else {
            return Matrix3::repeat(f64::NAN);
        };
        let kin = pose.kinematics(Vector2::new(x[2], x[3]));
        Matrix3::from_fn(|i, k| kin.v_contacts_local[i][k])
    }

    /// `(T, T + V)`.
    pub fn energy(x: &V<4>, p: &V<7>) -> (f64, f64) {
        let pp = params(p);
        let Ok(pose) = Pose::try_new(&pp, x[0], x[1]) else {
            return (f64::NAN, f64::NAN);
        };
        let t = kinetic_energy(&pp, &pose, &pose.kinematics(Vector2::new(x[2], x[3])));
        (t, t + potential_energy(&pp, &pose))
    }
}

/// The frictionless rigid peg: the hand forms of [`rigid_peg`] with `f = 0`.
pub mod rigid_peg_frictionless {
    use super::*;

    fn frictionless(p: &V<7>) -> V<7> {
        let mut q = *p;
        q[5] = 0.0;
        q
    }

    /// [`rigid_peg::forward`] at `f = 0` (no friction directions).
    pub fn forward(x: &V<4>, p: &V<7>, l: &V<5>) -> (SMatrix<f64, 5, 5>, V<5>) {
        super::rigid_peg::forward(x, &frictionless(p), l, &V::zeros())
    }

    /// [`rigid_peg::prescribed`] at `f = 0` (no friction directions).
    pub fn prescribed(x: &V<4>, qdd: &V<2>, p: &V<7>, l: &V<5>) -> (SMatrix<f64, 5, 5>, V<5>) {
        super::rigid_peg::prescribed(x, qdd, &frictionless(p), l, &V::zeros())
    }

    /// [`rigid_peg::contact_velocities`].
    pub fn contact_velocities(x: &V<4>, p: &V<7>) -> SMatrix<f64, 3, 3> {
        super::rigid_peg::contact_velocities(x, p)
    }

    /// [`rigid_peg::energy`].
    pub fn energy(x: &V<4>, p: &V<7>) -> (f64, f64) {
        super::rigid_peg::energy(x, p)
    }
}
