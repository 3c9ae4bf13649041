//! The items of `src/textbook/pendulum.rs`.

use nalgebra::Vector2;
use pegdyn::generated::pendulum as generated;
use pegdyn::system::{OdeSystem, finite_difference_jacobian};
use pegdyn::textbook::pendulum::*;

fn params(theta0_deg: f64, omega0: f64) -> PendulumParams {
    PendulumParams {
        length: 2.0,
        mass: 0.5,
        gravity: 9.81,
        theta0_deg,
        omega0,
    }
}

#[test]
fn the_generated_parameters_are_mass_length_gravity() {
    let p = generated::Params::from(&params(30.0, 0.0));
    assert_eq!((p.m, p.l, p.g), (0.5, 2.0, 9.81));
    assert_eq!(generated::X_NAMES, ["theta", "thetadot"]);
}

#[test]
fn exact_period_limits() {
    // Small amplitude: 2π√(L/g); 90°: 1.18034060... × 2π√(L/g).
    let t0 = 2.0 * std::f64::consts::PI * (2.0f64 / 9.81).sqrt();
    let small = exact_period(&params(1e-3, 0.0)).unwrap();
    assert!((small / t0 - 1.0).abs() < 1e-7);
    let right = exact_period(&params(90.0, 0.0)).unwrap();
    assert!(
        (right / t0 - 1.180340599016096).abs() < 1e-12,
        "{}",
        right / t0
    );
    assert!(exact_period(&params(0.0, 10.0)).is_none());
}

#[test]
fn jacobian_matches_finite_difference() {
    let sys = PendulumSystem::new(&params(40.0, 0.0));
    let x = Vector2::new(0.7, -0.3);
    let j = sys.jacobian(0.0, &x);
    let fd = finite_difference_jacobian(|x| sys.rhs(0.0, x), &x);
    assert!((j - fd).abs().max() < 1e-6, "{j} vs {fd}");
    assert_eq!(j[(1, 0)], -9.81 * 0.7f64.cos() / 2.0);
}
