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
//! which `tests/generator/lagrange_textbook.rs` checks. Units: SI (kg, m, N, rad, J).

use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};

/// Declares the `cart_pole` model: state x = (xc, theta, xcdot, thetadot),
/// parameters p = (mc, m, l, g, u); Lagrange's equations, no adapter.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    b.doc(
        "Cart-pole (textbook reference system): cart of mass `mc` at `xc` pushed by force `u`, point\n\
         mass `m` on a massless rod of length `l` at angle `theta` from the downward vertical,\n\
         gravity `g`. SI units.",
    );
    b.outputs(Outputs::FUNCTIONS);
    b.reference("Reference: Tedrake, Underactuated Robotics, ch. 3 (cart-pole). Units: SI.");
    let cart = b.coordinate_named(
        "xc",
        "xcdot",
        "xcddot",
        "position of the cart on its track, m",
    )?;
    let pole = b.coordinate_named(
        "theta",
        "thetadot",
        "thetaddot",
        "angle of the rod from the downward vertical, rad",
    )?;
    let (xc, vc, th, w) = (cart.q, cart.v, pole.q, pole.v);
    let mc = b.parameter("mc", "mass of the cart, kg")?;
    let m = b.parameter("m", "mass of the bob, kg")?;
    let l = b.parameter("l", "length of the rod, m")?;
    let grav = b.parameter("g", "gravitational acceleration, m/s²")?;
    let u = b.parameter("u", "horizontal force pushing the cart, N")?;
    let pairs = [(xc, vc), (th, w)];
    let (bx, by) = (xc + l * th.sin(), -l * th.cos());
    let v2 = bx.dt(&pairs).square() + by.dt(&pairs).square();
    // Expanded, so that sin² θ + cos² θ folds (the closed form's m l² θ̇²).
    let t = (0.5 * mc * vc.square() + 0.5 * m * v2).expand();
    let v = m * grav * by;
    let zero = b.g().constant(0.0);
    b.lagrange(t, v, &[u, zero]);
    Ok(())
}
