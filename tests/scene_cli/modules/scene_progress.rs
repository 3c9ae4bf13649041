//! The items of `src/scene/progress.rs`.

use pegdyn::error::RunError;
use pegdyn::internals::scene::*;
use pegdyn::scene::{Progress, par_map_counted};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

#[test]
fn a_run_is_slow_after_its_step_count_or_its_wall_time_and_says_why() {
    let cause = Some("the contact's natural period = 2e-9 s (peg.contact_stiffness = 1e15)");
    let quick = Duration::from_secs(1);
    assert_eq!(
        slow_notice(SLOW_STEPS - 1, (0.0, 0.01, 1.2), quick, cause),
        None
    );
    let s = slow_notice(SLOW_STEPS, (0.0, 0.012, 1.2), quick, cause).unwrap_or_default();
    for part in [
        "100000 steps in 1 s of wall time to t = 0.012 s of 1.2 s (1.0%)",
        "about 1e7 steps in all (mean step 1.2e-7 s, ETA 1m39s)",
        "what sets the steps: the contact's natural period",
    ] {
        assert!(s.contains(part), "{part:?} missing in {s}");
    }
    // Few steps but long: the wall time makes it slow.
    let s = slow_notice(500, (0.0, 0.6, 1.2), SLOW_AFTER, None).unwrap_or_default();
    assert!(
        s.contains("500 steps in 30 s") && s.contains("about 1000 steps in all"),
        "{s}"
    );
    assert!(!s.contains("time scale"), "{s}");
    // No progress in simulated time: no projection.
    let s = slow_notice(SLOW_STEPS, (0.0, 0.0, 1.0), quick, None).unwrap_or_default();
    assert!(
        s.contains("has not advanced") && !s.contains("in all"),
        "{s}"
    );
}

#[test]
fn eta_scales_elapsed_by_the_work_left() {
    assert_eq!(eta(Duration::from_secs(10), 0.25), ", ETA 30s");
    assert_eq!(eta(Duration::from_secs(100), 0.5), ", ETA 1m40s");
    assert_eq!(eta(Duration::from_secs(3600), 0.5), ", ETA 1h00m");
    assert_eq!(eta(Duration::from_secs(1), 0.0), "");
    assert_eq!(eta(Duration::from_secs(1), f64::NAN), "");
}

#[test]
fn a_requested_stop_starts_no_further_item() {
    let mut progress = Progress::silent();
    let items: Vec<u32> = (0..64).collect();
    let all = par_map_counted(&items, &mut progress, "item", |i| i * 2).unwrap();
    assert_eq!(all[63], 126);
    progress.interrupt().request();
    let ran = AtomicUsize::new(0);
    let r = par_map_counted(&items, &mut progress, "item", |_| {
        ran.fetch_add(1, Ordering::Relaxed);
    });
    assert!(matches!(r, Err(RunError::Interrupted)));
    assert_eq!(ran.load(Ordering::Relaxed), 0);
    assert!(progress.check_interrupt().is_err());
}
