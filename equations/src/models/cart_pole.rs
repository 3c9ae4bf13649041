//! The cart-pole: a cart of mass mc on a horizontal track (position xc),
//! pushed by a force u, carrying a point mass m on a massless rod of length
//! l at angle θ from the downward vertical; gravity g.
//!
//! Derived from the bob position (xc + l sin θ, −l cos θ) (y up), with
//! T = ½ mc ẋc² + ½ m |v_bob|², V = −m g l cos θ and generalized forces
//! Q = (u, 0). The textbook closed form (e.g. Tedrake, *Underactuated
//! Robotics*, ch. 3, with θ measured from the downward vertical) is
//!
//!   M = [[mc + m, m l cos θ], [m l cos θ, m l²]],
//!   f = (u + m l θ̇² sin θ, −m g l sin θ),
//!
//! which `tests/lagrange_textbook.rs` checks. Units: SI (kg, m, N, rad, J).

use crate::graph::Graph;
use crate::lagrange;
use crate::model::Module;

/// The `cart_pole` module: state x = (xc, theta, xcdot, thetadot),
/// parameters p = (mc, m, l, g, u).
pub fn module(g: &Graph) -> Module {
    let coords = [
        (g.var("xc"), g.var("xcdot"), g.var("xcddot")),
        (g.var("theta"), g.var("thetadot"), g.var("thetaddot")),
    ];
    let [(xc, vc, _), (th, w, _)] = coords;
    let (mc, m, l) = (g.param("mc"), g.param("m"), g.param("l"));
    let (grav, u) = (g.param("g"), g.param("u"));
    let pairs = [(xc, vc), (th, w)];
    let (bx, by) = (xc + l * th.sin(), -l * th.cos());
    let v2 = bx.dt(&pairs).square() + by.dt(&pairs).square();
    // Expanded, so that sin² θ + cos² θ folds (the closed form's m l² θ̇²).
    let t = (0.5 * mc * vc.square() + 0.5 * m * v2).expand();
    let v = m * grav * by;
    let lag = lagrange::derive(g, &coords, t, v, &[u, g.constant(0.0)]);
    Module {
        name: "cart_pole".to_owned(),
        doc: "Cart-pole (textbook reference system): cart of mass `mc` at `xc` pushed by force `u`, point\n\
              mass `m` on a massless rod of length `l` at angle `theta` from the downward vertical,\n\
              gravity `g`. SI units."
            .to_owned(),
        functions: lag.functions(
            &[mc, m, l, grav, u],
            "Reference: Tedrake, Underactuated Robotics, ch. 3 (cart-pole). Units: SI.",
        ),
    }
}
