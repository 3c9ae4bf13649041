//! The items of `src/scene/validate.rs`.

use pegdyn::scene::validate::*;

#[test]
fn rejects_non_finite_with_field_and_value() {
    for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = positive("peg.mass", v).unwrap_err().to_string();
        assert!(
            e.contains("peg.mass") && e.contains(&format!("{v:?}")),
            "{e}"
        );
    }
}

#[test]
fn sign_checks() {
    assert!(positive("a", 0.0).is_err());
    assert_eq!(positive("a", 1e-300).ok(), Some(1e-300));
    assert!(non_negative("a", -1e-300).is_err());
    assert_eq!(non_negative("a", 0.0).ok(), Some(0.0));
    assert!(in_range("a", 1.5, 0.0, 1.0).is_err());
    assert!(greater_than("t_end", 1.0, "t0", 1.0).is_err());
    assert_eq!(greater_than("t_end", 2.0, "t0", 1.0).ok(), Some(2.0));
}

#[test]
fn repeated_list_entries_are_named_with_the_entry_they_repeat() {
    let mut c = Checker::default();
    c.distinct("grid.a", &[0.0, 2e-4, 1.0, 2e-4, -0.0, 3.0]);
    c.distinct("grid.b", &[1.0, f64::NAN, f64::NAN]);
    let e = c.finish().unwrap_err();
    let got: Vec<String> = e.errors.iter().map(|l| l.error.to_string()).collect();
    assert_eq!(got.len(), 2, "{got:?}");
    assert!(
        got[0].starts_with("`grid.a[3]` = 0.0002: repeats grid.a[1]"),
        "{got:?}"
    );
    assert!(
        got[1].starts_with("`grid.a[4]` = -0.0: repeats grid.a[0]"),
        "{got:?}"
    );
}

#[test]
fn checker_collects_all() {
    let mut c = Checker::default();
    c.positive("a", -1.0);
    c.finite("b", f64::NAN);
    c.positive("c", 2.0);
    let e = c.finish().unwrap_err();
    assert_eq!(e.errors.len(), 2);
    assert_eq!(e.errors[1].error.field(), Some("b"));
}
