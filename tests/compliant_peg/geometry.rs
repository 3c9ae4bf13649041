//! Contact geometry of the filleted peg in the filleted hole
//! (`docs/contact-geometry.md`): the hole's concave curvature stiffens the
//! contacts by more than an order of magnitude against the "fillet sphere on
//! a flat" shortcut, the wall contact splits near √(2c), and bad dimensions
//! are refused with the field named.

use pegdyn::compliant_peg::{ContactPair, PegHoleGeometry};
use pegdyn::hertz::{Curvatures, EllipticityMethod, HertzContact, HertzError, Material};

const D: f64 = 0.05;
const C: f64 = 0.002;
const RHO: f64 = 0.2e-3;

fn scene_geometry() -> PegHoleGeometry {
    PegHoleGeometry::try_new(D, 0.5 * D * (1.0 - C), RHO, RHO).unwrap()
}

#[test]
fn concave_hole_curvature_stiffens_contacts_by_more_than_an_order() {
    let g = scene_geometry();
    let steel = Material::STEEL;
    let pair = ContactPair::try_new(&g, &steel, &steel, 0.0, EllipticityMethod::Exact).unwrap();
    let sphere = HertzContact::try_new(
        &Curvatures::on_flat([1.0 / RHO, 1.0 / RHO]),
        &steel,
        &steel,
        EllipticityMethod::Exact,
    )
    .unwrap();
    for k in [pair.edge.stiffness(), pair.wall.stiffness()] {
        assert!(
            k / sphere.stiffness() > 30.0,
            "k = {k}, sphere {}",
            sphere.stiffness()
        );
        assert!(
            k / sphere.stiffness() < 300.0,
            "k = {k}, sphere {}",
            sphere.stiffness()
        );
    }
    // Curvature ratio ≈ D/(2cρ): the ellipse is long around the hole.
    let (a, b) = pair.edge.relative;
    assert!(
        ((b / a) / (D / (2.0 * C * RHO)) - 1.0).abs() < 0.01,
        "B/A = {}",
        b / a
    );
    // At θ = 0 edge and wall contacts have the same curvatures (mirror images).
    assert!((pair.edge.stiffness() / pair.wall.stiffness() - 1.0).abs() < 1e-9);
}

#[test]
fn wall_contact_splits_near_root_two_c() {
    let g = scene_geometry();
    let split = g.wall_split_tilt();
    assert!(
        (split / (2.0 * C).sqrt() - 1.0).abs() < 0.01,
        "split tilt {split}"
    );
    let steel = Material::STEEL;
    assert!(
        ContactPair::try_new(&g, &steel, &steel, 0.99 * split, EllipticityMethod::Exact).is_ok()
    );
    let past = ContactPair::try_new(&g, &steel, &steel, 1.01 * split, EllipticityMethod::Exact);
    assert!(
        matches!(past, Err(HertzError::NotPointContact { .. })),
        "{past:?}"
    );
}

#[test]
fn bad_dimensions_are_refused_with_the_field_named() {
    let field = |r: Result<PegHoleGeometry, HertzError>| match r {
        Err(HertzError::Invalid { field, .. }) => field,
        other => panic!("expected an error, got {other:?}"),
    };
    assert_eq!(
        field(PegHoleGeometry::try_new(D, 0.5 * D, RHO, RHO)),
        "peg_radius"
    );
    assert_eq!(
        field(PegHoleGeometry::try_new(D, 0.6 * D, RHO, RHO)),
        "peg_radius"
    );
    assert_eq!(
        field(PegHoleGeometry::try_new(-D, 0.01, RHO, RHO)),
        "hole_diameter"
    );
    assert_eq!(
        field(PegHoleGeometry::try_new(D, 0.02, 0.0, RHO)),
        "peg_fillet"
    );
    assert_eq!(
        field(PegHoleGeometry::try_new(D, 0.02, RHO, 0.03)),
        "hole_fillet"
    );
}
