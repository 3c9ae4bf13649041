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
