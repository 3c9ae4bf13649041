//! The items of `src/scene/kinds/insert_compliant/start.rs`.

use pegdyn::compliant_peg::PegState;
use pegdyn::internals::insert_compliant::*;
use pegdyn::scene::kinds::insert_compliant::Built;
use pegdyn::scene::kinds::insert_compliant::InsertCompliantScene;

fn shipped() -> (InsertCompliantScene, Built) {
    let text = include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/insert_compliant.toml"
    ));
    let doc = pegdyn::scene::Document::parse(text).unwrap_or_else(|e| panic!("{e}"));
    let s: InsertCompliantScene = doc.body().unwrap_or_else(|e| panic!("{e}"));
    let b = s.build().unwrap_or_else(|e| panic!("{e}"));
    (s, b)
}

#[test]
fn a_two_point_start_pressed_into_the_hole_is_refused_on_the_tilt() {
    let (s, b) = shipped();
    let p = &s.insert_compliant;
    for (tilt, penetration) in [(0.01, 1e-5), (0.02, 1e-6), (0.005, 1e-7)] {
        let start = PegState::two_point(&b.params, tilt, penetration).unwrap();
        let e = overlap(&b.params, &b.load, &start, p)
            .expect_err("an overlapping start")
            .to_string();
        assert!(
            e.contains("`insert_compliant.initial_tilt`") && e.contains("overlaps the hole"),
            "{e}"
        );
        // Touching exactly, the same tilt runs.
        let touching = PegState::two_point(&b.params, tilt, 0.0).unwrap();
        assert!(overlap(&b.params, &b.load, &touching, p).is_ok(), "{tilt}");
    }
}

#[test]
fn the_edge_contact_period_follows_the_hertz_law() {
    let (s, b) = shipped();
    let scales = time_scales(&b, &s.insert_compliant);
    let contact = &scales[0];
    let k = b.params.pair.edge.stiffness();
    let load = 5.0 + 0.002 / b.params.spec.geometry.peg_radius;
    let k_eff = 1.5 * k.powf(2.0 / 3.0) * load.cbrt();
    let expected = std::f64::consts::TAU * (b.params.spec.mass / k_eff).sqrt();
    assert!(
        (contact.period / expected - 1.0).abs() < 1e-12,
        "{contact:?}"
    );
    assert!(contact.fields.contains("peg_fillet"), "{contact:?}");
}
