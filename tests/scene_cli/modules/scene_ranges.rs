//! The items of `src/scene/ranges.rs`.

use pegdyn::scene::ranges::*;
use pegdyn::scene::validate::Checker;

#[test]
fn a_field_already_refused_is_not_refused_twice() {
    let range = FieldRange::new("pendulum.length", 1e-6, 1e6, "m", "test");
    let mut c = Checker::default();
    c.positive("pendulum.length", -1.0);
    range.check(&mut c, -1.0);
    range.check_as(&mut c, "pendulum.mass", -1.0);
    let e = c.finish().unwrap_err();
    let fields: Vec<_> = e.errors.iter().map(|l| l.error.field()).collect();
    assert_eq!(fields, [Some("pendulum.length"), Some("pendulum.mass")]);
}

#[test]
fn every_declared_range_is_documented_and_sound() {
    let doc = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/scenes.md"));
    for kind in pegdyn::scene::kinds::KINDS {
        for r in kind.ranges.iter().flat_map(|t| t.iter()) {
            assert!(
                r.min < r.max && !r.why.is_empty(),
                "{} {}",
                kind.name,
                r.field
            );
            let last = r.field.rsplit('.').next().unwrap_or(r.field);
            assert!(
                doc.contains(&format!("`{}`", r.field)) || doc.contains(&format!("`{last}`")),
                "docs/scenes.md does not document {} {}",
                kind.name,
                r.field
            );
        }
    }
}

#[test]
fn a_dependent_range_shows_the_scene_bounds_and_keeps_the_declared_ones() {
    let r = FieldRange::new("peg.rim_fillet", 1e-7, 1e3, "m", "at most r/2");
    let refusal = |range: FieldRange, v: f64| {
        let mut c = Checker::default();
        assert_eq!(range.require(&mut c, v).to_bits(), v.to_bits());
        c.finish().err().map(|e| e.to_string()).unwrap_or_default()
    };
    let e = refusal(r.within(0.0, 0.005), 0.01);
    assert!(
        e.contains("0.01: must lie in [1e-7, 5e-3] m: at most r/2"),
        "{e}"
    );
    let noisy = 0.5 * 0.5 * 1e-6 * (1.0 - 0.001);
    let e = refusal(r.within(0.0, noisy), 1e-3);
    assert!(e.contains("must lie in [1e-7, 2.4975e-7] m"), "{e}");
    let e = refusal(r.within(0.0, f64::NAN), 2e3);
    assert!(e.contains("2000.0: must lie in [1e-7, 1e3] m"), "{e}");
    let e = refusal(r.within(0.0, 0.005), f64::INFINITY);
    assert!(
        e.contains("inf: must be a finite number") && !e.contains("lie in"),
        "{e}"
    );
    assert_eq!(refusal(r.within(0.0, 0.005), 0.004), "");
}

#[test]
fn a_range_names_field_value_limits_and_reason() {
    let r = FieldRange::new("peg.height", 1e-6, 1e3, "m", "a reason");
    let mut c = Checker::default();
    r.check(&mut c, 7.7e-154);
    r.check(&mut c, 0.07);
    r.check(&mut c, f64::NAN);
    r.check_as(&mut c, "peg.height[1]", 2e3);
    let e = c.finish().unwrap_err();
    assert_eq!(e.errors.len(), 2);
    let text = e.to_string();
    assert!(text.contains("peg.height` = 7.7e-154"), "{text}");
    assert!(text.contains("[1e-6, 1e3] m: a reason"), "{text}");
    assert!(text.contains("peg.height[1]` = 2000.0"), "{text}");
}
