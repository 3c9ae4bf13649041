//! The items of `src/replay/states.rs`.

use nalgebra::SVector;
use pegdyn::integrate::{EventHit, Solution};
use pegdyn::integrate::{Stats, StopReason};
use pegdyn::replay::decimate::{Budget, Keep};
use pegdyn::replay::error::ReplayError;
use pegdyn::replay::record::MarkKind;
use pegdyn::replay::states::*;

fn solution(n: usize) -> Solution<1> {
    Solution {
        t: (0..n).map(|i| i as f64).collect(),
        x: (0..n).map(|i| SVector::from([i as f64])).collect(),
        events: vec![EventHit {
            index: 0,
            t: 2.0,
            x: SVector::from([2.5]),
            rising: true,
        }],
        stop: StopReason::ReachedEnd,
        stats: Stats::default(),
        t_final: n as f64 - 0.5,
        x_final: SVector::from([-1.0]),
        non_finite: None,
        model_error: None,
    }
}

#[test]
fn events_and_the_final_state_join_the_samples_in_time_order() {
    let s = of_solution(
        &solution(5),
        |_| Some((MarkKind::Contact, "a".into())),
        "end",
    )
    .unwrap();
    let t: Vec<f64> = s.iter().map(|s| s.t).collect();
    // The sample at t = 2 gives way to the event there.
    assert_eq!(t, [0.0, 1.0, 2.0, 3.0, 4.0, 4.5]);
    assert_eq!(s[2].y[0], 2.5);
    assert_eq!(s[2].keep, Keep::Event);
    assert_eq!(s[5].mark, Some((MarkKind::End, "end".into())));
    assert_eq!(s[5].y[0], -1.0);
}

#[test]
fn no_sample_and_non_finite_states_are_refused() {
    let mut empty = solution(0);
    empty.events.clear();
    assert_eq!(
        of_solution(&empty, |_| None, "end"),
        Err(ReplayError::NoFrames)
    );
    let mut nan = solution(4);
    nan.x[3][0] = f64::NAN;
    assert_eq!(
        of_solution(&nan, |_| None, "end"),
        Err(ReplayError::NonFinite {
            quantity: "state",
            t: 3.0
        })
    );
}

#[test]
fn a_selection_counts_what_it_left_out() {
    let s = of_solution(
        &solution(10_000),
        |_| Some((MarkKind::Seat, "s".into())),
        "e",
    )
    .unwrap();
    let sel = select(
        s,
        Budget {
            max_frames: 100,
            max_marks: 10,
        },
    );
    assert_eq!((sel.total, sel.events), (10_001, 1));
    assert!(sel.states.len() <= 100);
    assert!(sel.states.iter().any(|s| s.t == 2.0 && s.y[0] == 2.5));
}
