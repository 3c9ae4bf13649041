//! Runtime of the compliant model: the generated model's parameters carry
//! the spec's and the load's values, the two-point start has both contact forces
//! positive, and bad input is refused with the field named.

use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, CompliantSystem, Load, PegState};
use pegdyn::hertz::{HertzError, Material};

fn field(r: Result<CompliantParams, HertzError>) -> String {
    match r {
        Err(HertzError::Invalid { field, .. }) => field,
        other => panic!("expected an error, got {other:?}"),
    }
}

#[test]
fn the_model_parameters_carry_the_spec_and_the_load() {
    use pegdyn::generated::{compliant_peg as all, compliant_peg_elastic as elastic};
    let p = CompliantParams::try_new(CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1)).unwrap();
    let load = Load {
        axial: 1.0,
        radial: 2.0,
        torque: 3.0,
    };
    let m = all::Params::from((&p, &load));
    assert_eq!((m.f1, m.f2, m.M), (1.0, 2.0, 3.0));
    assert_eq!(
        (m.m, m.J, m.l_c),
        (p.spec.mass, p.spec.inertia, p.spec.com_height)
    );
    assert_eq!((m.r, m.D), (p.spec.geometry.peg_radius, 0.05));
    assert_eq!(
        (m.k_edge, m.k_wall),
        (p.pair.edge.stiffness(), p.pair.wall.stiffness())
    );
    // The vector the generated functions take holds the fields in order.
    let v = p.vector(&load);
    assert!(v.iter().all(|x| x.is_finite()));
    assert_eq!(all::Params::from(&v), m);
    let e = elastic::Params::from((&p, &load));
    assert_eq!((e.m, e.k_wall, e.M), (m.m, m.k_wall, m.M));
    assert_eq!(e.g_star, p.shear_modulus());
}

#[test]
fn tilted_peg_in_two_point_contact_has_both_forces_positive() {
    let p = CompliantParams::try_new(CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1)).unwrap();
    for theta in [0.004, 0.01, 0.03] {
        let s = PegState::two_point(&p, theta, 1e-7).unwrap();
        let sample = CompliantSystem::new(&p, &Load::default()).sample(&s.to_vector());
        assert!(
            sample.f_edge > 0.0 && sample.f_wall > 0.0,
            "θ = {theta}: {sample:?}"
        );
        assert!(
            (sample.delta_edge - 1e-7).abs() < 1e-12 && (sample.delta_wall - 1e-7).abs() < 1e-12
        );
        // Depth ≈ (D − 2r cos θ)/sin θ, the sharp-edged two-point geometry
        // (the fillets shift the contact points by fractions of ρ).
        let r = 0.5 * 0.05 * (1.0 - 0.002);
        let expected = (0.05 - 2.0 * r * theta.cos()) / theta.sin();
        assert!(
            (s.depth(&p) / expected - 1.0).abs() < 0.1,
            "depth {} vs {expected}",
            s.depth(&p)
        );
    }
}

#[test]
fn bad_input_is_refused_with_the_field_named() {
    let ok = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1);
    let mut s = ok;
    s.geometry.peg_radius = 0.025;
    assert_eq!(field(CompliantParams::try_new(s)), "peg_radius");
    let mut s = ok;
    s.friction = -0.1;
    assert_eq!(field(CompliantParams::try_new(s)), "friction");
    let mut s = ok;
    s.peg = Material {
        youngs_modulus: 0.0,
        poisson_ratio: 0.3,
    };
    assert_eq!(field(CompliantParams::try_new(s)), "peg.youngs_modulus");
    let mut s = ok;
    s.hole = Material {
        youngs_modulus: 2e11,
        poisson_ratio: 0.5,
    };
    assert_eq!(field(CompliantParams::try_new(s)), "hole.poisson_ratio");
    let mut s = ok;
    s.hole.poisson_ratio = -1.2;
    assert_eq!(field(CompliantParams::try_new(s)), "hole.poisson_ratio");
    let mut s = ok;
    s.slip_velocity = 0.0;
    assert_eq!(field(CompliantParams::try_new(s)), "slip_velocity");
    let mut s = ok;
    s.reference_tilt = 0.06;
    assert_eq!(field(CompliantParams::try_new(s)), "reference_tilt");
    let p = CompliantParams::try_new(ok).unwrap();
    assert!(
        matches!(PegState::two_point(&p, 0.0, 0.0), Err(HertzError::Invalid { field, .. }) if field == "tilt")
    );
}

/// Whitney's wedging geometry: the line between the two contact points lies
/// inside both friction cones when the depth is below about `μD`
/// (μ = 0.1, D = 50 mm: 5 mm), not when the peg is deeper.
#[test]
fn contact_line_lies_in_the_friction_cones_only_when_shallow() {
    use pegdyn::compliant_peg::simulate::contact_line_in_cones;
    let p = CompliantParams::try_new(CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1)).unwrap();
    let shallow = PegState::two_point(&p, 0.04, 0.0).unwrap();
    let deep = PegState::two_point(&p, 0.005, 0.0).unwrap();
    assert!(shallow.depth(&p) < 0.004 && deep.depth(&p) > 0.015);
    assert!(contact_line_in_cones(&p, &shallow.to_vector()));
    assert!(!contact_line_in_cones(&p, &deep.to_vector()));
    // The mirror lean is classified alike.
    let mut mirror = shallow;
    (mirror.x, mirror.theta) = (-shallow.x, -shallow.theta);
    assert!(contact_line_in_cones(&p, &mirror.to_vector()));
}
