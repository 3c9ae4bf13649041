//! The exact Jacobian of the compliant 3-D peg's right-hand side.
//!
//! `ẏ = f(y, w(y))` with the generated Newton–Euler right-hand side `f` and
//! the contact wrench `w` summed at run time, so
//!
//! ```text
//! ∂ẏ/∂y = ∂f/∂y + ∂f/∂w · dw/dy
//! ```
//!
//! with `∂f/∂y`, `∂f/∂w` from the generated `rhs_jacobian`. `dw/dy` follows
//! each contact through its angle: the contact sits at a stationary angle
//! `α*(x)` of its pair's gap (`g′(α*, x) = 0`), so by the implicit-function
//! theorem `dα*/dx = −(∂g′/∂x) / g″`, and every output `o` of the pair's
//! generated function (gap, force direction, point) has the total
//! derivative `do/dx = ∂o/∂x + ∂o/∂α · dα*/dx` (for the gap the second term
//! vanishes: the envelope theorem). The partial derivatives come from
//! evaluating the generated pair functions at [`Dual`] numbers seeded with
//! the 15 state components and the angle; the contact law (Hertz,
//! Hunt–Crossley damping, regularized Coulomb friction with the material
//! point's velocity, the subtracted cols of [`super::merge`]) is then
//! evaluated in the same dual numbers. The active set (which points are in
//! contact, which cols are subtracted) is that of the state; the stiffness
//! `k` of each contact is held at its value (exact for
//! [`super::HertzMode::Fixed`]; with [`super::HertzMode::Curvature`] the
//! small variation of `k` with the pose is left out of the Jacobian: the
//! force's term `−(2/5) δ^{5/2} ∂k/∂(pose)` ([`super::stiffness`]) enters
//! the wrench's value but not its derivative). The ring of the peg's bottom on a flat
//! ([`super::face`]) is evaluated in dual numbers as a whole: its closed
//! form, the hand-over weight of the ring and of the plane pairs' points,
//! and the hand-over moment.

use super::dual::{Dual, N};
use super::face;
use super::prune;
use super::search::Pair;
use super::system::{ContactForce, Peg3d};
use crate::generated::compliant_peg_3d as generated;
use crate::scalar::Real;
use nalgebra::{SMatrix, SVector};

type D3 = [Dual; 3];

fn sub(a: &D3, b: &D3) -> D3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add(a: &D3, b: &D3) -> D3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: &D3, s: Dual) -> D3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn dot(a: &D3, b: &D3) -> Dual {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: &D3, b: &D3) -> D3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The generated pair function at dual arguments.
fn eval(
    pair: Pair,
    x: &SVector<Dual, 7>,
    a: Dual,
    p: &SVector<Dual, 16>,
) -> generated::PairGeometry<Dual> {
    let a = SVector::<Dual, 1>::new(a);
    match pair {
        Pair::EdgeSide => generated::edge_side(x, &a, p),
        Pair::RimWall => generated::rim_wall(x, &a, p),
        Pair::RimTop => generated::rim_top(x, &a, p),
        Pair::RimBottom => generated::rim_bottom(x, &a, p),
        Pair::RimEdge => generated::rim_edge(x, &a, p),
    }
}

/// Gap, force direction and point of `pair` at its stationary angle
/// `angle`, as duals in the state alone (the angle's slot eliminated by
/// `dα*/dy = −(∂g′/∂y) / g″`).
pub(super) fn at_stationary(
    pair: Pair,
    x: &SVector<Dual, 7>,
    angle: f64,
    p: &SVector<Dual, 16>,
) -> (Dual, D3, D3) {
    let g = eval(pair, x, Dual::variable(angle, N - 1), p);
    let (gap, d1, n, pt) = (g.gap, g.d1, g.normal, g.point);
    let curv = d1.d[N - 1];
    let mut slope = [0.0; N];
    for (k, s) in slope.iter_mut().enumerate().take(N - 1) {
        *s = -d1.d[k] / curv;
    }
    let total = |o: Dual| {
        let mut d = o.d;
        let da = d[N - 1];
        for k in 0..N - 1 {
            d[k] += da * slope[k];
        }
        d[N - 1] = 0.0;
        Dual { v: o.v, d }
    };
    (
        total(gap),
        [total(n[0]), total(n[1]), total(n[2])],
        [total(pt[0]), total(pt[1]), total(pt[2])],
    )
}

/// The contact wrench `w(y)` of `forces` (found at `y`) and its exact
/// derivative `dw/dy` (7 × 15).
pub fn wrench(
    sys: &Peg3d,
    y: &SVector<f64, 15>,
    forces: &[ContactForce],
) -> (SVector<f64, 7>, SMatrix<f64, 7, 15>) {
    let yd: Vec<Dual> = (0..15).map(|k| Dual::variable(y[k], k)).collect();
    let qn = (yd[3] * yd[3] + yd[4] * yd[4] + yd[5] * yd[5] + yd[6] * yd[6]).sqrt();
    let q = [yd[3] / qn, yd[4] / qn, yd[5] / qn, yd[6] / qn];
    let x = SVector::<Dual, 7>::from_column_slice(&[yd[0], yd[1], yd[2], q[0], q[1], q[2], q[3]]);
    let p = sys.param_vector().map(Dual::constant);
    let centre = [yd[0], yd[1], yd[2]];
    let v = [yd[7], yd[8], yd[9]];
    // ω in the hole frame: R(q) ω_body.
    let (w0, i, j, k) = (q[0], q[1], q[2], q[3]);
    let one = Dual::constant(1.0);
    let two = Dual::constant(2.0);
    let rot = [
        [
            one - two * (j * j + k * k),
            two * (i * j - w0 * k),
            two * (i * k + w0 * j),
        ],
        [
            two * (i * j + w0 * k),
            one - two * (i * i + k * k),
            two * (j * k - w0 * i),
        ],
        [
            two * (i * k - w0 * j),
            two * (j * k + w0 * i),
            one - two * (i * i + j * j),
        ],
    ];
    let ob = [yd[10], yd[11], yd[12]];
    let om = [dot(&rot[0], &ob), dot(&rot[1], &ob), dot(&rot[2], &ob)];
    let prm = &sys.params;
    let (mu, alpha, vs) = (
        Dual::constant(prm.friction),
        Dual::constant(prm.damping),
        Dual::constant(prm.slip_scale),
    );
    let zero = Dual::constant(0.0);
    let mut w = [zero; 7];
    // The hand-over weight s(u) of the plane pairs' points and, per pair,
    // their unweighted potential (for the ring's hand-over moment).
    let xs: [Dual; 7] = x.into();
    let xf = x.map(|d| d.v);
    let ax = face::axis(&xs);
    let (s_w, _) = face::blend(ax[0] * ax[0] + ax[1] * ax[1]);
    let mut v_point = [zero; Pair::ALL.len()];
    let index = |pair: Pair| Pair::ALL.iter().position(|q| *q == pair).unwrap_or(0);
    for f in forces {
        let c = &f.contact;
        let mut extra = [zero; 3];
        let (qe, n, pt) = if c.ring {
            // The distributed ring of the peg's bottom on a flat, weighted
            // by 1 − s(u) of the hand-over, and the hand-over moment
            // 2 a_z s′(u) (V_point − V_ring) (a × e_z) ([`super::face`]).
            let Some(z0) = face::plane(c.pair, prm) else {
                continue;
            };
            let Some(r) = face::ring(prm, z0, f.stiffness, &xs) else {
                continue;
            };
            let (s, ds) = face::blend(r.u);
            let m = Dual::constant(2.0) * r.axis[2] * ds * (v_point[index(c.pair)] - r.potential);
            extra = [m * r.axis[1], -(m * r.axis[0]), zero];
            let cop = face::centre_of_pressure(&xs, &r, z0);
            ((one - s) * r.force, [zero, zero, one], cop)
        } else {
            let (gap, n, pt) = at_stationary(c.pair, &x, c.angle, &p);
            let d = -gap;
            let blended = face::plane(c.pair, prm).is_some()
                && prune::ring_applies(c.pair, prm, &xf)
                && s_w.v < 1.0
                && s_w.v > 0.0;
            let k = if blended {
                let k = f.stiffness / s_w.v;
                v_point[index(c.pair)] =
                    v_point[index(c.pair)] + Dual::constant(0.4 * k) * d * d * d.sqrt();
                Dual::constant(k) * s_w
            } else {
                Dual::constant(f.stiffness)
            };
            (k * d * d.sqrt(), n, pt)
        };
        let arm = sub(&pt, &centre);
        let vc = add(&v, &cross(&om, &arm));
        let vn = dot(&n, &vc);
        let ddot = -vn;
        let q_n = (qe * (one + alpha * ddot)).max0();
        let vt = sub(&vc, &scale(&n, vn));
        let ft = scale(&vt, -(mu * q_n) / (dot(&vt, &vt) + vs * vs).sqrt());
        let force = add(&scale(&n, q_n), &ft);
        let torque = cross(&arm, &force);
        for m in 0..3 {
            w[m] = w[m] + force[m];
            w[3 + m] = w[3 + m] + torque[m] + extra[m];
        }
        w[6] = w[6] + (q_n - qe) * ddot - dot(&ft, &vt);
        if f.stiffness_force != nalgebra::Vector3::zeros()
            || f.stiffness_torque != nalgebra::Vector3::zeros()
        {
            // The curvature stiffness's −(2/5) δ^{5/2} ∂k/∂(pose), held
            // constant (its value only).
            for m in 0..3 {
                w[m] = w[m] + Dual::constant(f.stiffness_force[m]);
                w[3 + m] = w[3 + m] + Dual::constant(f.stiffness_torque[m]);
            }
        }
        if let Some(s) = &c.saddle {
            let (gap_c, n_c, pt_c) = at_stationary(c.pair, &x, s.angle, &p);
            let dc = -gap_c;
            let kc = f.col_force / (s.penetration * s.penetration.sqrt());
            let back = scale(&n_c, -(Dual::constant(kc) * dc * dc.sqrt()));
            let t = cross(&sub(&pt_c, &centre), &back);
            for m in 0..3 {
                w[m] = w[m] + back[m];
                w[3 + m] = w[3 + m] + t[m];
            }
        }
    }
    let value = SVector::<f64, 7>::from_fn(|r, _| w[r].v);
    let deriv = SMatrix::<f64, 7, 15>::from_fn(|r, col| w[r].d[col]);
    (value, deriv)
}

/// `∂ẏ/∂y` at `y` (15 × 15): the generated partial derivatives plus the
/// chain rule through the contact wrench.
pub fn of(sys: &Peg3d, y: &SVector<f64, 15>, forces: &[ContactForce]) -> SMatrix<f64, 15, 15> {
    let (w, dw) = wrench(sys, y, forces);
    let partial = generated::rhs_jacobian(y, &w, sys.param_vector());
    partial.dy + partial.dw * dw
}
