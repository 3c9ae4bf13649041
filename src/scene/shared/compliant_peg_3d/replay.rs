//! The replay page (`docs/replay.md`) of one held-peg insertion ([`Run`]):
//! each event of the run named for the page (the contact transitions, the
//! seat, the force limits, a miss); and the page of the run a grid kind's
//! `replay.run` picks ([`write_grid`]).

use crate::compliant_peg_3d::insertion::N_STATE;
use crate::compliant_peg_3d::outcome::TERMINAL_NAMES;
use crate::error::RunError;
use crate::integrate::EventHit;
use crate::replay::ReplayError;
use crate::replay::peg3d::{Meaning, Run3d, page};
use crate::scene::context::RunContext;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::progress::Progress;
use crate::scene::shared::replay::{self, RunChoice};

use super::insertion::{Built, Run, outcome_text, run_one};

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

/// The model's words at the head of every held-peg page's subtitle.
const HELD: &str = "compliant 3-D peg held by a compliant wrist";

/// Writes the page of a grid kind (`rotation_assist`, `design_margins`):
/// grid point `k` if `choice` picks one among `points` (in the CSV's row
/// order, their runs ending as `outcomes`: seated, end time), integrated
/// again with its contact transitions located (the grid's runs skip them;
/// the trajectory is the same), described by `describe`; else the nominal
/// run `nominal` hands over (`None`: no page).
///
/// # Errors
/// The run's integrator refusal or Hertz setup error, the page's refusal,
/// or the file cannot be written.
pub fn write_grid<P>(
    ctx: &RunContext,
    choice: RunChoice,
    outcomes: &[(bool, f64)],
    points: &[(P, Built)],
    describe: impl Fn(&P) -> String,
    spec: &IntegratorSpec,
    nominal: impl FnOnce() -> Result<Option<Run>, RunError>,
) -> Result<(), RunError> {
    let (run, what) = match choice
        .pick(outcomes)
        .and_then(|(k, why)| Some((k, why, points.get(k)?)))
    {
        Some((k, why, (p, built))) => (
            run_one(built, spec, true, &mut Progress::silent())?,
            format!("{HELD}, grid point {k} ({why}): {}", describe(p)),
        ),
        None => match nominal()? {
            Some(run) => (
                run,
                format!("{HELD}, the nominal run (the [robot] table as written)"),
            ),
            None => return Ok(()),
        },
    };
    replay::write(ctx, &insertion(ctx.name(), &what, &run)?)
}
