//! The replay page of one run of the design (`docs/replay.md`): the
//! nominal insertion (default, `replay.run = "nominal"`), the worst grid
//! run (`"worst"`: the first that did not seat, else the slowest to seat)
//! or grid point `k` (row `k` of `<name>.csv`).

use super::design::{Design, GridRun};
use crate::error::RunError;
use crate::scene::context::RunContext;
use crate::scene::progress::Progress;
use crate::scene::shared::compliant_peg_3d::insertion::{Run, run_one};
use crate::scene::shared::compliant_peg_3d::replay::insertion;
use crate::scene::shared::replay::{self, RunChoice};

const MODEL: &str = "compliant 3-D peg held by a compliant wrist";

/// Writes the page of the run `choice` picks; `nominal` is the nominal
/// run with its transitions tracked, when the choice is the nominal run.
///
/// # Errors
/// A grid run's integrator refusal or Hertz setup error, the page's
/// refusal, or the file cannot be written.
pub fn write(
    design: &Design,
    ctx: &RunContext,
    choice: RunChoice,
    rows: &[GridRun],
    nominal: Option<Run>,
) -> Result<(), RunError> {
    let outcomes: Vec<(bool, f64)> = rows.iter().map(|r| (r.seated(), r.end)).collect();
    let (run, what) = match (choice.pick(&outcomes), nominal) {
        (Some((k, why)), _) => {
            let (p, built) = &design.points[k];
            let run = run_one(built, &design.integrator, true, &mut Progress::silent())?;
            let what = format!(
                "{MODEL}, grid point {k} ({why}): compliance centre's lateral error {} m, \
                 angular error {} deg",
                p.centre_lateral, p.angular_deg
            );
            (run, what)
        }
        (None, Some(run)) => (run, format!("{MODEL}, the nominal run")),
        // Only "nominal" picks no grid point, and it comes with its run.
        (None, None) => return Ok(()),
    };
    replay::write(ctx, &insertion(ctx.name(), &what, &run)?)
}
