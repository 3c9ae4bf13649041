//! The simple pendulum: a point mass m on a massless rod of length l,
//! angle θ from the downward vertical, gravity g.
//!
//! T = ½ m l² θ̇², V = −m g l cos θ, so M = m l² and f = −m g l sin θ
//! (any mechanics textbook, e.g. Goldstein, *Classical Mechanics*, §1.6).
//! Units: SI (kg, m, m/s², rad, J).

use crate::graph::Graph;
use crate::lagrange;
use crate::model::Module;

/// The `pendulum` module: state x = (theta, thetadot), parameters
/// p = (m, l, g).
pub fn module(g: &Graph) -> Module {
    let (theta, thetadot, thetaddot) = (g.var("theta"), g.var("thetadot"), g.var("thetaddot"));
    let (m, l, grav) = (g.param("m"), g.param("l"), g.param("g"));
    // Position of the bob, y up; velocities by the chain rule.
    let (px, py) = (l * theta.sin(), -l * theta.cos());
    let pairs = [(theta, thetadot)];
    let (vx, vy) = (px.dt(&pairs), py.dt(&pairs));
    let t = 0.5 * m * (vx.square() + vy.square());
    let v = m * grav * py;
    let lag = lagrange::derive(g, &[(theta, thetadot, thetaddot)], t, v, &[g.constant(0.0)]);
    Module {
        name: "pendulum".to_owned(),
        doc: "Simple pendulum (textbook reference system): point mass `m` on a massless rod of length `l`,\n\
              angle `theta` from the downward vertical, gravity `g`. SI units."
            .to_owned(),
        functions: lag.functions(&[m, l, grav], "Reference: Goldstein, Classical Mechanics, §1.6. Units: SI."),
    }
}
