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
//! which `tests/generator/lagrange_textbook.rs` checks the derivation against.
//! Units: SI (kg, m, m/s², rad, J).

use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};
use crate::expr::Expr;

/// Declares the `double_pendulum` model: state x = (theta1, theta2,
/// theta1dot, theta2dot), parameters p = (m1, m2, l1, l2, g); Lagrange's
/// equations, no adapter.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    b.doc(
        "Double pendulum (textbook reference system): point masses `m1`, `m2` on massless rods of\n\
         lengths `l1`, `l2`, absolute angles `theta1`, `theta2` from the downward vertical, gravity `g`.\n\
         SI units.",
    );
    b.outputs(Outputs::FUNCTIONS);
    b.reference("Reference: Goldstein, Classical Mechanics, §1.6 (double pendulum). Units: SI.");
    let c1 = b.coordinate_named(
        "theta1",
        "theta1dot",
        "theta1ddot",
        "angle of the upper rod from the downward vertical, rad",
    )?;
    let c2 = b.coordinate_named(
        "theta2",
        "theta2dot",
        "theta2ddot",
        "angle of the lower rod from the downward vertical, rad",
    )?;
    let (th1, w1, th2, w2) = (c1.q, c1.v, c2.q, c2.v);
    let m1 = b.parameter("m1", "mass of the upper bob, kg")?;
    let m2 = b.parameter("m2", "mass of the lower bob, kg")?;
    let l1 = b.parameter("l1", "length of the upper rod, m")?;
    let l2 = b.parameter("l2", "length of the lower rod, m")?;
    let grav = b.parameter("g", "gravitational acceleration, m/s²")?;
    let (x1, y1) = (l1 * th1.sin(), -l1 * th1.cos());
    let (x2, y2) = (x1 + l2 * th2.sin(), y1 - l2 * th2.cos());
    let pairs = [(th1, w1), (th2, w2)];
    // Expanded, so that the simplifier folds sin² + cos² and the cross terms
    // cos θ1 cos θ2 + sin θ1 sin θ2 into cos(θ1 − θ2) (the closed form).
    let t = (0.5 * m1 * speed2(x1, y1, &pairs) + 0.5 * m2 * speed2(x2, y2, &pairs)).expand();
    let v = grav * (m1 * y1 + m2 * y2);
    let zero = b.g().constant(0.0);
    b.lagrange(t, v, &[zero, zero]);
    Ok(())
}

/// |v|² of a point at (x, y), velocities by the chain rule along `pairs`.
fn speed2<'g>(x: Expr<'g>, y: Expr<'g>, pairs: &[(Expr<'g>, Expr<'g>)]) -> Expr<'g> {
    x.dt(pairs).square() + y.dt(pairs).square()
}
