//! The items of `src/scene/kinds/insert_compliant/model_errors.rs`.

use pegdyn::error::SceneErrors;
use pegdyn::hertz::HertzError;
use pegdyn::internals::insert_compliant::*;
use pegdyn::scene::kinds::insert_compliant::InsertCompliantScene;
use pegdyn::scene::kinds::insert_compliant::InsertParams;

fn shipped() -> InsertParams {
    let text = include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/insert_compliant.toml"
    ));
    let doc = pegdyn::scene::Document::parse(text).unwrap_or_else(|e| panic!("{e}"));
    let s: InsertCompliantScene = doc.body().unwrap_or_else(|e| panic!("{e}"));
    s.insert_compliant
}

fn first(e: SceneErrors) -> (String, String) {
    let e = &e.errors[0].error;
    (e.field().unwrap_or_default().to_owned(), e.to_string())
}

#[test]
fn every_model_refusal_names_a_scene_field_with_its_written_value() {
    let p = shipped();
    // Refusals of the geometry as a whole: named on the clearance ratio
    // as written, with the dimensions that set the curvatures.
    for e in [
        HertzError::NotPointContact { a: -1.0, b: 5.0 },
        HertzError::LineContact {
            ratio: 2e12,
            limit: 1e12,
        },
        HertzError::NoConvergence {
            kernel: "ellipticity solve",
            iterations: 100,
            input: 3e11,
        },
        HertzError::Invalid {
            field: "curvature".into(),
            value: f64::NAN,
            reason: "must be finite",
        },
    ] {
        let what = e.to_string();
        let (field, text) = first(to_scene_error(e, &p));
        assert_eq!(field, "insert_compliant.clearance_ratio", "{text}");
        assert!(
            text.contains("= 0.002")
                && text.contains("hole_diameter = 0.05, peg_fillet = 2e-4")
                && !text.contains("NaN =")
                && text.contains(what.split(':').next().unwrap_or_default()),
            "{text}"
        );
    }
    // A field set directly: its own name and value.
    let (field, text) = first(to_scene_error(
        HertzError::Invalid {
            field: "damping".into(),
            value: p.contact_damping,
            reason: "must be finite and >= 0",
        },
        &p,
    ));
    assert_eq!(field, "insert_compliant.contact_damping", "{text}");
    // A derived field: the scene's value, and the derived one in the reason.
    let (field, text) = first(to_scene_error(
        HertzError::Invalid {
            field: "com_height".into(),
            value: 1e-5,
            reason: "must exceed peg_fillet",
        },
        &p,
    ));
    assert_eq!(field, "insert_compliant.peg_length", "{text}");
    assert!(text.contains("gives com_height = 1e-5"), "{text}");
    let (field, _) = first(to_scene_error(
        HertzError::Invalid {
            field: "hole.poisson_ratio".into(),
            value: p.hole_material.poisson_ratio,
            reason: "must lie in (-1, 0.5)",
        },
        &p,
    ));
    assert_eq!(field, "insert_compliant.hole_material.poisson_ratio");
}
