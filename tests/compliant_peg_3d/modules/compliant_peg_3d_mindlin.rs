//! The items of `src/compliant_peg_3d/mindlin.rs`.

use pegdyn::compliant_peg_3d::mindlin::*;
use pegdyn::compliant_peg_3d::params::Peg3dParams;

fn law() -> Mindlin {
    Mindlin::of(&Peg3dParams::steel(0.01, 0.02, 0.0101, 5e-4, 5e-4, 0.02))
}

#[test]
fn steel_ratio_is_two_one_minus_nu_over_two_minus_nu() {
    let nu = 0.3;
    assert!((law().ratio - 2.0 * (1.0 - nu) / (2.0 - nu)).abs() < 1e-14);
}

#[test]
fn a_point_at_rest_keeps_its_displacement_and_carries_its_spring_force() {
    let mut law = law();
    law.friction = 0.3;
    let touch = Touch {
        normal: [0.0, 0.0, 1.0],
        velocity: [0.0; 3],
        elastic: 10.0,
        normal_stiffness: 1.5 * 10.0 / 1e-7,
        exponent: 0.5,
        penetration: 1e-7,
    };
    let xi = [1e-9, -2e-9, 0.0];
    let s = spring(&law, &touch, &xi);
    assert_eq!(s.rate, [0.0; 3]);
    let kt = law.ratio * touch.normal_stiffness;
    for (f, x) in s.force.iter().zip(&xi) {
        assert!((f + kt * x).abs() <= 1e-15 * kt * 1e-9);
    }
    // P = ∂E_t/∂δ at fixed ξ, k_t ∝ δ^{1/2}: a central difference.
    let e = |d: f64| 0.5 * kt * (d / 1e-7).sqrt() * (xi[0] * xi[0] + xi[1] * xi[1]);
    let fd = (e(1e-7 * (1.0 + 1e-6)) - e(1e-7 * (1.0 - 1e-6))) / (2e-13);
    assert!((s.normal - fd).abs() < 1e-8 * fd.abs());
}
