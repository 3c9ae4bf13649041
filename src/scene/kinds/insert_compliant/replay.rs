//! The replay page of the insertion (`docs/replay.md`), drawn as the
//! section through the hole's axis: the walls drawn to 30 % of the peg's
//! length below the target depth (the model has no bore bottom), the
//! target depth reached as the seat.

use nalgebra::SVector;

use super::{Built, InsertParams};
use crate::compliant_peg::Sample;
use crate::error::RunError;
use crate::integrate::{EventHit, Solution};
use crate::replay::MarkKind;
use crate::replay::planar::{Run2d, page};
use crate::scene::context::RunContext;
use crate::scene::shared::replay;

/// Writes the page of the run `sol` of the scene with table `p`.
///
/// # Errors
/// The page's refusal (no sample, a non-finite number), or the file
/// cannot be written.
pub fn write<const N: usize>(
    ctx: &RunContext,
    p: &InsertParams,
    built: &Built,
    sol: &Solution<N>,
    sample: &dyn Fn(&SVector<f64, N>) -> Sample,
) -> Result<(), RunError> {
    // The run's only event is the terminal "inserted".
    let mark = |_: &EventHit<N>| Some((MarkKind::Seat, "target depth reached".to_string()));
    let start = if p.initial_tilt == 0.0 {
        "a centred, upright start"
    } else {
        "a two-point start"
    };
    let html = page(&Run2d {
        title: ctx.name(),
        subtitle: format!(
            "compliant planar peg pushed in from {start}: f1 = {} N, M = {} N m, mu = {}",
            p.axial_force, p.torque, p.friction
        ),
        params: &built.params,
        peg_length: p.peg_length,
        wall_depth: p.target_depth + 0.3 * p.peg_length,
        solution: sol,
        sample,
        mark: &mark,
    })?;
    replay::write(ctx, &html)
}
