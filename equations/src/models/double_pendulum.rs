//! The double pendulum: two point masses m1, m2 on massless rods of lengths
//! l1, l2, absolute angles θ1, θ2 from the downward vertical, gravity g.
//!
//! Derived from the Cartesian positions of the bobs,
//! x1 = l1 sin θ1, y1 = −l1 cos θ1, x2 = x1 + l2 sin θ2, y2 = y1 − l2 cos θ2
//! (y up), with T = ½ m1 |v1|² + ½ m2 |v2|² and V = g (m1 y1 + m2 y2). The
//! textbook closed form (e.g. Goldstein, *Classical Mechanics*, §1.6 and
//! problem 1.x; any Lagrangian mechanics text) is
//!
//!   M = [[(m1+m2) l1², m2 l1 l2 cos(θ1−θ2)], [m2 l1 l2 cos(θ1−θ2), m2 l2²]],
//!   f1 = −m2 l1 l2 θ̇2² sin(θ1−θ2) − (m1+m2) g l1 sin θ1,
//!   f2 =  m2 l1 l2 θ̇1² sin(θ1−θ2) − m2 g l2 sin θ2,
//!
//! which `tests/lagrange_textbook.rs` checks the derivation against.
//! Units: SI (kg, m, m/s², rad, J).

use crate::expr::Expr;
use crate::graph::Graph;
use crate::lagrange;
use crate::model::Module;

/// The `double_pendulum` module: state x = (theta1, theta2, theta1dot,
/// theta2dot), parameters p = (m1, m2, l1, l2, g).
pub fn module(g: &Graph) -> Module {
    let coords = [
        (g.var("theta1"), g.var("theta1dot"), g.var("theta1ddot")),
        (g.var("theta2"), g.var("theta2dot"), g.var("theta2ddot")),
    ];
    let [(th1, w1, _), (th2, w2, _)] = coords;
    let (m1, m2) = (g.param("m1"), g.param("m2"));
    let (l1, l2, grav) = (g.param("l1"), g.param("l2"), g.param("g"));
    let (x1, y1) = (l1 * th1.sin(), -l1 * th1.cos());
    let (x2, y2) = (x1 + l2 * th2.sin(), y1 - l2 * th2.cos());
    let pairs = [(th1, w1), (th2, w2)];
    // Expanded, so that the simplifier folds sin² + cos² and the cross terms
    // cos θ1 cos θ2 + sin θ1 sin θ2 into cos(θ1 − θ2) (the closed form).
    let t = (0.5 * m1 * speed2(x1, y1, &pairs) + 0.5 * m2 * speed2(x2, y2, &pairs)).expand();
    let v = grav * (m1 * y1 + m2 * y2);
    let zero = g.constant(0.0);
    let lag = lagrange::derive(g, &coords, t, v, &[zero, zero]);
    Module {
        name: "double_pendulum".to_owned(),
        doc: "Double pendulum (textbook reference system): point masses `m1`, `m2` on massless rods of\n\
              lengths `l1`, `l2`, absolute angles `theta1`, `theta2` from the downward vertical, gravity `g`.\n\
              SI units."
            .to_owned(),
        functions: lag.functions(
            &[m1, m2, l1, l2, grav],
            "Reference: Goldstein, Classical Mechanics, §1.6 (double pendulum). Units: SI.",
        ),
    }
}

/// |v|² of a point at (x, y), velocities by the chain rule along `pairs`.
fn speed2<'g>(x: Expr<'g>, y: Expr<'g>, pairs: &[(Expr<'g>, Expr<'g>)]) -> Expr<'g> {
    x.dt(pairs).square() + y.dt(pairs).square()
}
