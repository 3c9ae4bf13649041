//! The replay page (`docs/replay.md`) of one held-peg insertion ([`Run`]):
//! each event of the run named for the page (the contact transitions, the
//! seat, the force limits, a miss).

use crate::compliant_peg_3d::insertion::N_STATE;
use crate::compliant_peg_3d::outcome::TERMINAL_NAMES;
use crate::integrate::EventHit;
use crate::replay::ReplayError;
use crate::replay::peg3d::{Meaning, Run3d, page};

use super::insertion::{Run, outcome_text};

/// What event `e` of `run` means: [`super::insertion::run_one`] numbers the
/// transition events from 0 and shifts the terminal ones below 0, in the
/// order of [`TERMINAL_NAMES`].
fn meaning(run: &Run, e: &EventHit<N_STATE>) -> Option<Meaning> {
    if let Some(t) = run.transitions.get(e.index) {
        return Some(Meaning::Transition(*t));
    }
    match e.index.wrapping_add(TERMINAL_NAMES.len()) {
        0 => Some(Meaning::Seated),
        1 => Some(Meaning::WristForceLimit),
        2 => Some(Meaning::ContactForceLimit),
        3 => Some(Meaning::Missed),
        _ => None,
    }
}

/// The page of `run`, titled `title` (the scene's name); `what` says in a
/// few words which run it is (the page's subtitle adds the outcome).
///
/// # Errors
/// As [`page`]: a run without samples, a non-finite number, a state the
/// contact model refuses.
pub fn insertion(title: &str, what: &str, run: &Run) -> Result<String, ReplayError> {
    let meaning = |e: &EventHit<N_STATE>| meaning(run, e);
    page(&Run3d {
        title,
        subtitle: format!("{what}; outcome: {}", outcome_text(&run.outcome)),
        system: &run.system,
        solution: &run.solution,
        meaning: &meaning,
    })
}
