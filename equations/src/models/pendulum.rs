//! The simple pendulum: a point mass m on a massless rod of length l,
//! angle θ from the downward vertical, gravity g.
//!
//! T = ½ m l² θ̇², V = −m g l cos θ, so M = m l² and f = −m g l sin θ
//! (any mechanics textbook, e.g. Goldstein, *Classical Mechanics*, §1.6).
//! Units: SI (kg, m, m/s², rad, J).

use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};

/// Declares the `pendulum` model: state x = (theta, thetadot), parameters
/// p = (m, l, g); Lagrange's equations, no adapter.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    b.doc(
        "Simple pendulum (textbook reference system): point mass `m` on a massless rod of length `l`,\n\
         angle `theta` from the downward vertical, gravity `g`. SI units.",
    );
    b.outputs(Outputs::FUNCTIONS);
    b.reference("Reference: Goldstein, Classical Mechanics, §1.6. Units: SI.");
    let th = b.coordinate_named(
        "theta",
        "thetadot",
        "thetaddot",
        "angle of the rod from the downward vertical, rad",
    )?;
    let m = b.parameter("m", "mass of the bob, kg")?;
    let l = b.parameter("l", "length of the rod, m")?;
    let grav = b.parameter("g", "gravitational acceleration, m/s²")?;
    // Position of the bob, y up; velocities by the chain rule.
    let (px, py) = (l * th.q.sin(), -l * th.q.cos());
    let pairs = [(th.q, th.v)];
    let (vx, vy) = (px.dt(&pairs), py.dt(&pairs));
    let t = 0.5 * m * (vx.square() + vy.square());
    let v = m * grav * py;
    let zero = b.g().constant(0.0);
    b.lagrange(t, v, &[zero]);
    Ok(())
}
