//! The `[sensitivities]` table of an `insert_compliant` scene: derivatives
//! of the run's metrics with respect to scene fields, by forward
//! sensitivities of the compliant planar peg along each field
//! ([`crate::compliant_peg::directions`], integrated by
//! [`crate::sensitivity::integrate`]).
//!
//! ```toml
//! [sensitivities]
//! parameters = ["insert_compliant.friction", "insert_compliant.clearance_ratio"]
//! ```
//!
//! Each field moves the model parameters and the start through the chain
//! rule of [`fields`]; the metrics and their flags are in [`metrics`], the
//! files in [`output`]. See `docs/sensitivities.md`, "In scenes".

pub mod fields;
mod hertz_tangent;
pub mod metrics;
pub mod output;
mod trajectory;

use serde::Deserialize;

use super::{Built, InsertParams};
use crate::compliant_peg::directions::CompliantDirections;
use crate::compliant_peg::{ContactSet, FrictionLaw};
use crate::error::{RunError, SceneError, SceneErrors};
use crate::integrate::Options;
use crate::scene::context::RunContext;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::summary::Metric;
use crate::sensitivity::SensitivityError;
use fields::{FIELDS, N_FIELDS};
use trajectory::StopOrError;

/// The `[sensitivities]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SensitivitiesTable {
    /// The scene fields to differentiate by, e.g.
    /// `"insert_compliant.friction"` (one of [`FIELDS`]).
    pub parameters: Vec<String>,
}

const FIELD: &str = "sensitivities.parameters";

/// What [`compute`] gives: the rows, and the sensitivity run's accepted
/// steps and right-hand-side evaluations (None when every row is flagged
/// because the run failed).
pub type Computed = (Vec<metrics::Row>, Option<(usize, usize)>);

/// The chosen fields' indices into [`FIELDS`], or the errors naming
/// `sensitivities.parameters`: an unknown name (with the valid ones), a
/// name given twice, an empty list, or a model variant without parameter
/// Jacobians.
pub fn check(table: &SensitivitiesTable, b: &Built) -> Result<Vec<usize>, SceneErrors> {
    let mut errors = Vec::new();
    let mut chosen = Vec::new();
    if table.parameters.is_empty() {
        errors.push(SceneError::invalid(
            FIELD,
            &table.parameters,
            format!(
                "name at least one field; the fields are: {}",
                FIELDS.join(", ")
            ),
        ));
    }
    for name in &table.parameters {
        match FIELDS.iter().position(|f| f == name) {
            None => errors.push(SceneError::invalid(
                FIELD,
                name,
                format!("unknown field; the fields are: {}", FIELDS.join(", ")),
            )),
            Some(k) if chosen.contains(&k) => {
                errors.push(SceneError::invalid(FIELD, name, "named twice"));
            }
            Some(k) => chosen.push(k),
        }
    }
    let spec = &b.params.spec;
    if spec.contacts != ContactSet::All {
        errors.push(SceneError::invalid(
            FIELD,
            &table.parameters,
            "sensitivities need insert_compliant.contacts = \"all\" (the lean contact set's \
             parameter Jacobian is not generated)",
        ));
    }
    if spec.friction_law != FrictionLaw::Regularized {
        errors.push(SceneError::invalid(
            FIELD,
            &table.parameters,
            "sensitivities need insert_compliant.friction_law = \"regularized\" (the elastic \
             law's parameter Jacobian is not generated)",
        ));
    }
    if errors.is_empty() {
        Ok(chosen)
    } else {
        Err(SceneErrors::new(errors))
    }
}

/// Runs the sensitivities of `chosen` fields and writes their files;
/// returns the ranking notes for the run's summary.
///
/// # Errors
/// The files cannot be written, or the model refuses its parameters.
pub fn run(
    ctx: &RunContext,
    p: &InsertParams,
    b: &Built,
    integrator: &IntegratorSpec,
    chosen: &[usize],
) -> Result<Vec<Metric>, RunError> {
    let (rows, work) = compute(p, b, integrator, chosen)?;
    let mut notes = output::write(ctx, &rows)?;
    if let Some((steps, calls)) = work {
        notes.push(Metric::note(
            "sensitivity run",
            format!(
                "{steps} steps, {calls} evaluations of the variational system ({} fields \
                 integrated together, {} asked for)",
                N_FIELDS,
                chosen.len()
            ),
        ));
    }
    Ok(notes)
}

/// The rows of `chosen` fields (indices into [`FIELDS`]) for the scene's
/// parameters `p` built into `b`, integrated with `integrator`'s
/// tolerances, span and step budget (always Dormand–Prince 5(4)), and the
/// sensitivity run's accepted steps and right-hand-side evaluations (None
/// when it failed and every row is flagged).
///
/// # Errors
/// [`RunError::Sensitivity`] when the model refuses its parameters or
/// the integrator its input.
pub fn compute(
    p: &InsertParams,
    b: &Built,
    integrator: &IntegratorSpec,
    chosen: &[usize],
) -> Result<Computed, RunError> {
    let (dp, dy0) = fields::jacobians(p, b);
    let values = fields::values(p);
    let unused: [bool; N_FIELDS] = std::array::from_fn(|k| fields::unused(k, &dp, &dy0));
    let sys = CompliantDirections::new(&b.params, &b.load, dp, values)?;
    let options = Options {
        max_steps: integrator.max_steps,
        h0: integrator.h,
        ..Options::with_tolerances(integrator.rtol, integrator.atol)
    };
    let y0 = b.initial.to_vector();
    let (t0, t_end, target) = (integrator.t0, integrator.t_end, p.target_depth);
    let scan = trajectory::scan(&sys, (t0, y0), t_end, target, &options)?;
    let d = match trajectory::derivatives(&sys, (t0, y0, dy0), t_end, target, &options, &scan) {
        Ok(d) => d,
        Err(StopOrError::Error(SensitivityError::TangentialEvent { t, .. })) => {
            return Ok((
                metrics::failed(
                    chosen,
                    &format!("an event is crossed tangentially at t = {t:.6e} s"),
                ),
                None,
            ));
        }
        Err(StopOrError::Error(e)) => return Err(e.into()),
        Err(StopOrError::Stopped(stop)) => {
            return Ok((
                metrics::failed(
                    chosen,
                    &format!("the sensitivity run stopped short: {stop:?}"),
                ),
                None,
            ));
        }
    };
    let rows = metrics::rows(
        &sys,
        &values,
        (&scan, &d),
        &y0,
        (t_end, target),
        chosen,
        &unused,
    );
    Ok((rows, Some(d.work)))
}
