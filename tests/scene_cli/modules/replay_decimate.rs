//! The items of `src/replay/decimate.rs`.

use pegdyn::replay::decimate::*;

#[test]
fn a_short_run_keeps_every_state() {
    let p = vec![Keep::Sample; 50];
    assert_eq!(keep(&p, Budget::default()), (0..50).collect::<Vec<_>>());
}

#[test]
fn a_long_run_is_bounded_and_evenly_spread_with_every_event_kept() {
    let mut p = vec![Keep::Sample; 1_000_003];
    let events = [3, 17, 500_000, 999_999];
    for &e in &events {
        p[e] = Keep::Event;
    }
    p[700_000] = Keep::Always;
    let kept = keep(
        &p,
        Budget {
            max_frames: 500,
            max_marks: 50,
        },
    );
    assert!(kept.len() <= 500, "{} frames", kept.len());
    assert!(kept.len() >= 450, "{} frames: the room is used", kept.len());
    for e in events.iter().chain(&[700_000, 0, 1_000_002]) {
        assert!(kept.contains(e), "state {e} dropped");
    }
    // The samples between events are spread over the whole run.
    let gaps: Vec<usize> = kept.windows(2).map(|w| w[1] - w[0]).collect();
    assert!(
        gaps.iter().all(|&g| g <= 2 * 1_000_003 / 450),
        "a gap too wide"
    );
}

#[test]
fn more_events_than_marks_are_thinned_but_end_states_kept() {
    let mut p = vec![Keep::Event; 10_000];
    p[4_321] = Keep::Always;
    let kept = keep(
        &p,
        Budget {
            max_frames: 300,
            max_marks: 100,
        },
    );
    assert!(kept.len() <= 101, "{}", kept.len());
    assert!(kept.contains(&4_321) && kept.contains(&0) && kept.contains(&9_999));
}

#[test]
fn no_state_keeps_nothing() {
    assert!(keep(&[], Budget::default()).is_empty());
}
