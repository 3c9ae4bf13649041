//! Bad input to the jamming analysis is refused with an error naming the
//! field: μ < 0, c outside (0, 1), r ≤ 0, l ≤ 0, NaN anywhere.

use pegdyn::jamming::space3d::SphericalForce;
use pegdyn::jamming::{PegHole, diagram, geometry};

fn refused_field(r: f64, c: f64, mu: f64) -> &'static str {
    PegHole::try_new(r, c, mu).expect_err("must refuse").field
}

#[test]
fn each_bad_parameter_is_named() {
    let cases: [(f64, f64, f64, &str); 11] = [
        (0.0125, 0.01, -0.1, "mu"),
        (0.0125, 0.01, f64::NAN, "mu"),
        (0.0125, 0.01, f64::INFINITY, "mu"),
        (0.0125, 0.0, 0.3, "c"),
        (0.0125, 1.0, 0.3, "c"),
        (0.0125, -0.2, 0.3, "c"),
        (0.0125, f64::NAN, 0.3, "c"),
        (0.0, 0.01, 0.3, "r"),
        (-0.0125, 0.01, 0.3, "r"),
        (f64::NAN, 0.01, 0.3, "r"),
        (f64::NEG_INFINITY, 0.01, 0.3, "r"),
    ];
    for (r, c, mu, field) in cases {
        assert_eq!(refused_field(r, c, mu), field, "r={r} c={c} mu={mu}");
    }
}

#[test]
fn message_names_field_and_value() {
    let e = PegHole::try_new(0.0125, 1.5, 0.3).unwrap_err();
    let msg = e.to_string();
    assert!(msg.starts_with("c = 1.5"), "{msg}");
    assert!(msg.contains("(0, 1)"), "{msg}");
    let e = PegHole::try_new(0.0125, 0.01, f64::NAN).unwrap_err();
    assert!(e.to_string().starts_with("mu = NaN"), "{e}");
}

#[test]
fn depth_must_be_positive_and_finite() {
    let p = PegHole::try_new(0.0125, 0.01, 0.3).unwrap();
    for l in [0.0, -0.001, f64::NAN] {
        assert_eq!(geometry::two_point_tilt(&p, l).unwrap_err().field, "l");
        assert_eq!(
            diagram::whitney_parallelogram(&p, l).unwrap_err().field,
            "l"
        );
        assert_eq!(diagram::exact_parallelogram(&p, l).unwrap_err().field, "l");
    }
}

#[test]
fn spherical_force_checks_fields() {
    assert_eq!(
        SphericalForce::try_new(-1.0, 0.1, 0.0).unwrap_err().field,
        "F"
    );
    assert_eq!(
        SphericalForce::try_new(1.0, 4.0, 0.0).unwrap_err().field,
        "beta"
    );
    assert_eq!(
        SphericalForce::try_new(1.0, 0.1, f64::NAN)
            .unwrap_err()
            .field,
        "gamma"
    );
}
