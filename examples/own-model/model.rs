//! The model, declared once and used by `build.rs` (to generate the code)
//! and by the tests (to compare the generated code with the interpreter).
//!
//! A spherical pendulum over a compliant floor: a point mass `m` (kg) on a
//! massless rod of length `l` (m) hinged at the origin, polar angle `theta`
//! (rad) from the downward vertical and azimuth `phi` (rad), gravity `g`
//! (m/s²). The bob at `(l sinθ cosφ, l sinθ sinφ, −l cosθ)` touches a
//! horizontal floor at height `z = −h` (m); the floor pushes back with a
//! Hertz load `Q = k max(δ, 0)^{3/2}` (N), `δ = l cosθ − h` the penetration
//! (m) and `k` (N/m^{3/2}) the stiffness. The contact is frictionless and
//! elastic, so
//!
//!   T = ½ m l² (θ̇² + sin²θ φ̇²),
//!   V = −m g l cosθ + (2/5) k max(δ, 0)^{5/2},
//!
//! and both the energy T + V and the vertical angular momentum
//! `L_z = m l² sin²θ φ̇` (φ is cyclic) are conserved.

use pegdyn_equations::{GenError, Generator, blocks, model::Output};

/// Name of the generated module.
pub const MODEL: &str = "spherical_pendulum";

/// Name of the second, explicit and time-dependent model.
pub const FORCED: &str = "forced_oscillator";

/// Adds the model to `generator`.
pub fn declare(generator: &mut Generator) -> Result<(), GenError> {
    generator.model(
        MODEL,
        "Spherical pendulum (point mass `m` on a rod of length `l`) over a Hertz floor at depth `h`.",
        |m| {
            let theta = m.coordinate("theta", "polar angle from the downward vertical, rad")?;
            let phi = m.coordinate("phi", "azimuth about the vertical, rad")?;
            let mass = m.parameter("m", "mass of the bob, kg")?;
            let l = m.parameter("l", "rod length, m")?;
            let g = m.parameter("g", "gravitational acceleration, m/s²")?;
            let h = m.parameter("h", "depth of the floor below the hinge, m")?;
            let k = m.parameter("k", "Hertz stiffness of the floor, N/m^1.5")?;

            let (s, c) = (theta.q.sin(), theta.q.cos());
            let t = 0.5 * mass * l.square() * (theta.v.square() + s.square() * phi.v.square());
            let delta = l * c - h;
            let v = -mass * g * l * c + blocks::hertz_potential(k, delta);
            let zero = m.g().constant(0.0);
            m.lagrange(t, v, &[zero, zero]);
            m.reference("Spherical pendulum: Goldstein, Classical Mechanics, §3.6 (Lagrangian); floor: Hertz, Q = k δ^{3/2}.");
            m.output("penetration", "Penetration δ = l cos θ − h of the bob into the floor (m; negative when apart).", Output::scalar(delta));
            m.output("floor_load", "Normal load of the floor on the bob, Q = k max(δ, 0)^{3/2} (N).", Output::scalar(blocks::hertz_load(k, delta)));
            m.output(
                "angular_momentum",
                "Vertical angular momentum L_z = m l² sin²θ φ̇ (kg·m²/s), conserved.",
                Output::scalar(mass * l.square() * s.square() * phi.v),
            );
            Ok(())
        },
    )?;
    Ok(())
}

/// Adds a first-order, explicitly time-dependent model: the undamped
/// oscillator `ÿ + ω₀² y = a cos(ω t)` as `x = (y, v)`, whose solution from
/// rest is `y(t) = a (cos ωt − cos ω₀t) / (ω₀² − ω²)` (for `ω ≠ ω₀`).
pub fn declare_forced(generator: &mut Generator) -> Result<(), GenError> {
    generator.model(
        FORCED,
        "Undamped oscillator driven by a cosine force (per unit mass).",
        |m| {
            let y = m.state("y", "displacement, m")?;
            let v = m.state("v", "velocity, m/s")?;
            let w0 = m.parameter("omega0", "natural angular frequency, rad/s")?;
            let a = m.parameter("a", "forcing amplitude per unit mass, m/s²")?;
            let w = m.parameter("omega", "forcing angular frequency, rad/s")?;
            let t = m.time();
            m.explicit(&[v, a * (w * t).cos() - w0.square() * y]);
            m.energy(0.5 * v.square() + 0.5 * w0.square() * y.square());
            Ok(())
        },
    )?;
    Ok(())
}
