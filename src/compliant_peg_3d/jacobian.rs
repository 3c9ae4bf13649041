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
//! at dual numbers ([`Dual`]) seeded with the 15 state components, each
//! point and col followed through its stationary angle
//! ([`Pair::at_stationary`](super::contact::Pair::at_stationary): the
//! generated pair function in dual numbers with the angle's slot
//! eliminated by the implicit-function theorem). The ring of the peg's
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

use super::forces::{Setup, contact_wrench};
use super::frame::Motion;
use super::law::LawParams;
use super::params::Peg3dParams;
use crate::generated::compliant_peg_3d as generated;
use crate::scalar::Dual;
use nalgebra::{SMatrix, SVector};

/// The dual numbers of the Jacobian: the 15 state components and, last, a
/// contact's edge angle.
type D = Dual<16>;

/// The contact wrench `w(y)` of the contacts `setups` (found at `y`) and
/// its exact derivative `dw/dy` (7 × 15), `p` the generated functions'
/// parameter vector.
pub fn wrench(
    prm: &Peg3dParams,
    p: &SVector<f64, 16>,
    y: &SVector<f64, 15>,
    setups: &[Setup],
) -> (SVector<f64, 7>, SMatrix<f64, 7, 15>) {
    let yd: [D; 15] = std::array::from_fn(|k| D::variable(y[k], k));
    let m = Motion::of_state(&yd);
    let x = SVector::<D, 7>::from(m.pose);
    let pd = p.map(D::constant);
    let w = contact_wrench(prm, &LawParams::of(prm), &m, setups, |pair, angle, _| {
        pair.at_stationary(&x, angle, &pd)
    });
    let value = SVector::<f64, 7>::from_fn(|r, _| w[r].v);
    let deriv = SMatrix::<f64, 7, 15>::from_fn(|r, col| w[r].d[col]);
    (value, deriv)
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
    let partial = generated::rhs_jacobian(y, &w, p);
    partial.dy + partial.dw * dw
}
