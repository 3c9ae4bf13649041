//! The items of `src/scene/kinds/insert_compliant/ranges.rs`.

use pegdyn::scene::kinds::insert_compliant::ranges::*;
use pegdyn::scene::validate::Checker;

fn shipped() -> CompliantFields {
    CompliantFields {
        hole_diameter: 0.05,
        clearance_ratio: 0.002,
        peg_length: 0.1,
        peg_fillet: 2e-4,
        hole_fillet: 2e-4,
        youngs_modulus: [210e9, 210e9],
        poisson_ratio: [0.3, 0.3],
        load: 5.0 + 0.002 / 0.025,
        initial_depth: 0.0,
        target_depth: 0.03,
    }
}

fn errors(f: &CompliantFields) -> String {
    let mut c = Checker::default();
    check_compliant(&mut c, "insert_compliant", f);
    c.finish().err().map(|e| e.to_string()).unwrap_or_default()
}

#[test]
fn the_shipped_scene_is_in_range() {
    assert_eq!(errors(&shipped()), "");
}

#[test]
fn hostile_values_are_refused_with_their_own_value() {
    let e = errors(&CompliantFields {
        peg_fillet: 1e-200,
        ..shipped()
    });
    assert!(
        e.contains("insert_compliant.peg_fillet") && e.contains("1e-200"),
        "{e}"
    );
    let e = errors(&CompliantFields {
        youngs_modulus: [1e-30, 210e9],
        ..shipped()
    });
    assert!(
        e.contains("peg_material.youngs_modulus") && e.contains("1e-30"),
        "{e}"
    );
    let e = errors(&CompliantFields {
        clearance_ratio: 0.0,
        ..shipped()
    });
    assert!(e.contains("clearance_ratio` = 0.0"), "{e}");
    let e = errors(&CompliantFields {
        clearance_ratio: 1e-15,
        ..shipped()
    });
    assert!(e.contains("clearance_ratio` = 1e-15"), "{e}");
    let e = errors(&CompliantFields {
        target_depth: 0.2,
        ..shipped()
    });
    assert!(
        e.contains("target_depth` = 0.2") && e.contains("peg_length"),
        "{e}"
    );
}
