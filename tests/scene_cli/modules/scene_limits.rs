//! The items of `src/scene/limits.rs`.

use pegdyn::scene::limits::*;

#[test]
fn every_violation_is_reported_with_field_and_estimate() {
    let work = [
        WorkItem::new("gamma.count", "max_grid_points", 9.2e18, 64.0),
        WorkItem::new("integrator.max_steps", "max_steps", 1e3, 0.0),
        WorkItem::new("sweep.n", "max_runs", f64::INFINITY, 0.0),
    ];
    let e = Limits::default().check(&work).unwrap_err();
    let text = e.to_string();
    assert_eq!(e.errors.len(), 3, "{text}");
    assert!(
        text.contains("gamma.count") && text.contains("9.200e18"),
        "{text}"
    );
    assert!(
        text.contains("sweep.n") && text.contains("max_runs"),
        "{text}"
    );
    assert!(text.contains("max_memory_mb"), "{text}");
}

#[test]
fn raised_limits_accept_and_nan_is_refused() {
    let work = [WorkItem::new("gamma.count", "max_grid_points", 2e6, 8.0)];
    assert!(Limits::default().check(&work).is_err());
    let raised = Limits {
        max_grid_points: 3_000_000,
        ..Limits::default()
    };
    assert!(raised.check(&work).is_ok());
    let nan = [WorkItem::new("x", "max_runs", f64::NAN, 0.0)];
    assert!(raised.check(&nan).is_err());
}

#[test]
fn overrides_take_the_table_keys_and_refuse_the_rest() {
    let o = LimitOverrides::parse(&["max_steps=20_000_000", "grid_points = 3e6"]).unwrap();
    let l = o.apply(Limits::default());
    assert_eq!((l.max_steps, l.max_grid_points), (20_000_000, 3_000_000));
    assert_eq!(l.max_runs, Limits::default().max_runs);
    let big = LimitOverrides::parse(&["max_runs=18446744073709551615"]).unwrap();
    assert_eq!(big.values, vec![("max_runs", u64::MAX)]);
    for bad in [
        "max_steps",
        "max_step=5",
        "runs=0",
        "runs=1.5",
        "runs=nan",
        "runs=1e30",
        "runs=-3",
    ] {
        let e = LimitOverrides::parse(&[bad]).unwrap_err();
        assert_eq!(e.arg, bad);
    }
    let e = LimitOverrides::parse(&["max_step=5"])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("unknown limit `max_step`") && e.contains("max_steps"),
        "{e}"
    );
}

#[test]
fn sample_count_matches_the_grid() {
    assert_eq!(sample_count(0.0, 1.0, 0.3), 5.0);
    assert!(sample_count(0.0, 1e9, 1e-300).is_infinite());
}
