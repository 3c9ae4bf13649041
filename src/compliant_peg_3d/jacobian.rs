//! The exact Jacobian of the compliant 3-D peg's right-hand side.
//!
//! `ẏ = f(y, w(y))` with the generated Newton–Euler right-hand side `f` and
//! the contact wrench `w` summed at run time, so
//!
//! ```text
//! ∂ẏ/∂y = ∂f/∂y + ∂f/∂w · dw/dy
//! ```
//!
//! with `∂f/∂y`, `∂f/∂w` from the generated `rhs_jacobian`. `dw/dy` is the
//! contact law ([`super::law`], through [`super::forces::contact_wrench`]) evaluated
//! at dual numbers ([`Dual`]) seeded with the 13 state components the law
//! reads (`p`, `q`, `v`, `ω`; the work integrals enter nowhere, their
//! columns are zero). Each point and col is followed through its
//! stationary angle ([`Pair::at_stationary`](super::contact::Pair::at_stationary):
//! the generated pair function in dual numbers of the pose `x` and the
//! angle, the angle's slot eliminated by the implicit-function theorem),
//! then carried to the state through the pose's normalization,
//! `do/dy = do/dx · dx/dy` ([`lift`]): the pair function, the largest
//! part of the work, runs at 8 slots instead of 13. The ring of the peg's
//! bottom on a flat ([`super::face`]) is evaluated in dual numbers as a
//! whole: its closed form, the hand-over weight of the ring and of the
//! plane pairs' points, and the hand-over moment.
//!
//! The contacts and their Hertz setups are given ([`Setup`]): the active
//! set (which points are in contact, which cols are subtracted) is that of
//! the state, and the stiffness `k` of each contact is held at its value
//! (exact for [`super::HertzMode::Fixed`]; with
//! [`super::HertzMode::Curvature`] the small variation of `k` with the pose
//! is left out of the Jacobian: the force's term `−(2/5) δ^{5/2}
//! ∂k/∂(pose)` ([`super::stiffness`]) enters the wrench with its value, times
//! the point's hand-over weight, but not its own derivative).

use super::contact::Geometry;
use super::forces::{Setup, contact_wrench};
use super::frame::Motion;
use super::law::LawParams;
use super::params::Peg3dParams;
use crate::generated::compliant_peg_3d as generated;
use crate::scalar::Dual;
use nalgebra::{SMatrix, SVector};

/// The dual numbers of the Jacobian: the 13 state components `p`, `q`,
/// `v`, `ω` (slots 0–12).
pub type D = Dual<13>;

/// The dual numbers of a pair function: the pose `x` (slots 0–6) and the
/// edge angle (slot 7).
type G = Dual<8>;

/// The components `p`, `q`, `v`, `ω` of the state `y` as dual numbers,
/// component `k` seeded in slot `k`.
pub fn seeded(y: &SVector<f64, 15>) -> [D; 13] {
    std::array::from_fn(|k| D::variable(y[k], k))
}

/// An output `o` of a pair function in dual numbers of the pose, carried
/// to the state: `do/dy = Σᵢ (∂o/∂xᵢ) dxᵢ/dy`, `x` the pose in dual
/// numbers of the state.
fn lift_one(o: G, x: &[D; 7]) -> D {
    let mut d = [0.0; 13];
    for (xi, &g) in x.iter().zip(&o.d[..7]) {
        if g != 0.0 {
            for (dj, xij) in d.iter_mut().zip(&xi.d) {
                *dj += g * xij;
            }
        }
    }
    D { v: o.v, d }
}

/// A contact's geometry in dual numbers of the pose, carried to the state
/// (`lift_one` of every output).
pub fn lift(g: &Geometry<G>, x: &[D; 7]) -> Geometry<D> {
    Geometry {
        normal: g.normal.map(|o| lift_one(o, x)),
        point: g.point.map(|o| lift_one(o, x)),
        penetration: lift_one(g.penetration, x),
    }
}

/// The contact wrench `w(y)` of the contacts `setups` (found at `y`) in
/// dual numbers of the state `yd` ([`seeded`]): each component carries its
/// exact derivative in the state, `p` the generated functions' parameter
/// vector.
pub fn wrench_dual(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    yd: &[D; 13],
    setups: &[Setup],
) -> [D; 7] {
    let m = Motion::of_state(yd);
    let x = SVector::<G, 7>::from_fn(|i, _| G::variable(m.pose[i].v, i));
    let pg = p.map(G::constant);
    contact_wrench(prm, &LawParams::of(prm), &m, setups, |pair, angle, _| {
        lift(&pair.at_stationary(&x, angle, &pg), &m.pose)
    })
}

/// The value and the derivative (7 × 15) of a wrench in dual numbers.
pub fn split(w: &[D; 7]) -> (SVector<f64, 7>, SMatrix<f64, 7, 15>) {
    let value = SVector::<f64, 7>::from_fn(|r, _| w[r].v);
    let deriv = SMatrix::<f64, 7, 15>::from_fn(|r, col| if col < 13 { w[r].d[col] } else { 0.0 });
    (value, deriv)
}

/// The contact wrench `w(y)` of the contacts `setups` (found at `y`) and
/// its exact derivative `dw/dy` (7 × 15), `p` the generated functions'
/// parameter vector.
pub fn wrench(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    y: &SVector<f64, 15>,
    setups: &[Setup],
) -> (SVector<f64, 7>, SMatrix<f64, 7, 15>) {
    split(&wrench_dual(prm, p, &seeded(y), setups))
}

/// `∂ẏ/∂y = ∂f/∂y + ∂f/∂w · dw/dy` (15 × 15) at `y` for the total wrench
/// `w` on the peg and its derivative `dw` (7 × 15).
pub fn chain(
    p: &SVector<f64, 16>,
    y: &SVector<f64, 15>,
    w: &SVector<f64, 7>,
    dw: &SMatrix<f64, 7, 15>,
) -> SMatrix<f64, 15, 15> {
    let partial = generated::rhs_jacobian(y, w, p);
    partial.dy + partial.dw * dw
}

/// `∂ẏ/∂y` at `y` (15 × 15) with the contacts `setups` found at `y`: the
/// generated partial derivatives plus the chain rule through the contact
/// wrench.
pub fn of(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    y: &SVector<f64, 15>,
    setups: &[Setup],
) -> SMatrix<f64, 15, 15> {
    let (w, dw) = wrench(prm, p, y, setups);
    chain(p, y, &w, &dw)
}

/// The normal force `Q` of every contact of `setups` (found at `y`), in
/// their order, in dual numbers of the state `yd` ([`seeded`]): the law
/// of [`wrench_dual`] read contact by contact.
pub fn normal_forces_dual(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    yd: &[D; 13],
    setups: &[Setup],
) -> Vec<D> {
    let m = Motion::of_state(yd);
    let x = SVector::<G, 7>::from_fn(|i, _| G::variable(m.pose[i].v, i));
    let pg = p.map(G::constant);
    let mut out = Vec::with_capacity(setups.len());
    super::forces::evaluate(
        prm,
        &LawParams::of(prm),
        &m,
        setups,
        |pair, angle, _| lift(&pair.at_stationary(&x, angle, &pg), &m.pose),
        |_, _, load, _| out.push(load.normal_force),
    );
    out
}

/// The gap `g` of `pair` at its stationary angle `angle` (rad) in dual
/// numbers of the state `yd` ([`seeded`]): `−δ` of
/// [`Pair::at_stationary`](super::contact::Pair::at_stationary) carried to
/// the state.
pub fn gap_dual(p: &SVector<f64, 16>, yd: &[D; 13], pair: super::contact::Pair, angle: f64) -> D {
    let m = Motion::of_state(yd);
    let x = SVector::<G, 7>::from_fn(|i, _| G::variable(m.pose[i].v, i));
    let pg = p.map(G::constant);
    -lift(&pair.at_stationary(&x, angle, &pg), &m.pose).penetration
}
