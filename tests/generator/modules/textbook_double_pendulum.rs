//! The items of `src/textbook/double_pendulum.rs`.

use nalgebra::Vector4;
use pegdyn::generated::double_pendulum as generated;
use pegdyn::system::{OdeSystem, finite_difference_jacobian};
use pegdyn::textbook::double_pendulum::*;

#[test]
fn generated_orders_match_the_adapter() {
    assert_eq!(
        generated::Params::<f64>::NAMES,
        ["m1", "m2", "l1", "l2", "g"]
    );
    assert_eq!(
        generated::X_NAMES,
        ["theta1", "theta2", "theta1dot", "theta2dot"]
    );
}

#[test]
fn jacobian_matches_finite_difference() {
    let p = DoublePendulumParams {
        mass1: 1.3,
        mass2: 0.7,
        length1: 0.9,
        length2: 1.4,
        gravity: 9.81,
        theta1_deg: 0.0,
        theta2_deg: 0.0,
        omega1: 0.0,
        omega2: 0.0,
    };
    let sys = DoublePendulumSystem::new(&p);
    let x = Vector4::new(0.4, -1.1, 0.8, -0.5);
    let j = sys.jacobian(0.0, &x);
    let fd = finite_difference_jacobian(|x| sys.rhs(0.0, x), &x);
    assert!((j - fd).abs().max() < 1e-5, "{j} vs {fd}");
    assert_eq!((j[(0, 2)], j[(1, 3)], j[(0, 0)]), (1.0, 1.0, 0.0));
}
