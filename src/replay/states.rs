//! The states of a run in time order, as the replay sees them: the output
//! samples, the states at the events (located by the integrator, between
//! samples) and the final state; then the bounded selection of them that
//! becomes the frames ([`super::decimate`]).

use super::decimate::{Budget, Keep, keep};
use super::error::ReplayError;
use super::record::MarkKind;
use crate::integrate::{EventHit, Solution};
use nalgebra::SVector;

/// One state of a run.
#[derive(Clone, Debug, PartialEq)]
pub struct State<const N: usize> {
    /// Time (s).
    pub t: f64,
    /// The state.
    pub y: SVector<f64, N>,
    /// How much it must be kept.
    pub keep: Keep,
    /// The event it is, if any.
    pub mark: Option<(MarkKind, String)>,
}

/// What the states of a run amount to.
#[derive(Clone, Debug, PartialEq)]
pub struct Selection<const N: usize> {
    /// The kept states, in time order.
    pub states: Vec<State<N>>,
    /// How many states the run had.
    pub total: usize,
    /// How many events the run had (the final state not counted).
    pub events: usize,
}

/// The states of `sol`: every output sample, every event that `mark`
/// names (a [`MarkKind::Contact`] as [`Keep::Event`], any other as
/// [`Keep::Always`]) and the final state, marked [`MarkKind::End`] with
/// `end` (unless a terminal event is that state). An output sample at the time of an event or of the final state
/// gives way to it.
///
/// # Errors
/// [`ReplayError::NoFrames`] for a run without output samples;
/// [`ReplayError::NonFinite`] for a non-finite time or state.
pub fn of_solution<const N: usize>(
    sol: &Solution<N>,
    mut mark: impl FnMut(&EventHit<N>) -> Option<(MarkKind, String)>,
    end: &str,
) -> Result<Vec<State<N>>, ReplayError> {
    if sol.t.is_empty() {
        return Err(ReplayError::NoFrames);
    }
    let mut special: Vec<State<N>> = sol
        .events
        .iter()
        .filter_map(|e| {
            mark(e).map(|(kind, label)| State {
                t: e.t,
                y: e.x,
                keep: if kind == MarkKind::Contact {
                    Keep::Event
                } else {
                    Keep::Always
                },
                mark: Some((kind, label)),
            })
        })
        .collect();
    // The final state, unless an event that ended the run is that state.
    if !special
        .iter()
        .any(|s| s.t == sol.t_final && s.keep == Keep::Always)
    {
        special.push(State {
            t: sol.t_final,
            y: sol.x_final,
            keep: Keep::Always,
            mark: Some((MarkKind::End, end.to_string())),
        });
    }
    let mut all: Vec<State<N>> = sol
        .t
        .iter()
        .zip(&sol.x)
        .filter(|(t, _)| !special.iter().any(|s| s.t == **t))
        .map(|(&t, &y)| State {
            t,
            y,
            keep: Keep::Sample,
            mark: None,
        })
        .collect();
    all.extend(special);
    for s in &all {
        if !s.t.is_finite() || s.y.iter().any(|v| !v.is_finite()) {
            return Err(ReplayError::NonFinite {
                quantity: "state",
                t: s.t,
            });
        }
    }
    // Stable: at equal times, samples before events, events in their order.
    all.sort_by(|a, b| a.t.total_cmp(&b.t));
    Ok(all)
}

/// At most `budget` of `states` (see [`super::decimate`]).
pub fn select<const N: usize>(states: Vec<State<N>>, budget: Budget) -> Selection<N> {
    let total = states.len();
    let events = states
        .iter()
        .filter(|s| s.mark.as_ref().is_some_and(|(k, _)| *k != MarkKind::End))
        .count();
    let priority: Vec<Keep> = states.iter().map(|s| s.keep).collect();
    let kept = keep(&priority, budget);
    let mut states = states;
    let mut k = 0;
    states.retain(|_| {
        k += 1;
        kept.binary_search(&(k - 1)).is_ok()
    });
    Selection {
        states,
        total,
        events,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::{Stats, StopReason};

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
}
