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
//! files in [`crate::scene::shared::sensitivities::output`]. See `docs/sensitivities.md`, "In scenes".

pub mod fields;
mod hertz_tangent;
pub mod metrics;
mod trajectory;

use super::{Built, InsertParams};
use crate::compliant_peg::directions::CompliantDirections;
use crate::compliant_peg::params::N_PARAMS;
use crate::compliant_peg::system::N_STATE;
use crate::compliant_peg::{ContactSet, FrictionLaw};
use crate::error::{RunError, SceneError, SceneErrors};
use crate::generated::compliant_peg as all;
use crate::integrate::Options;
use crate::scene::context::RunContext;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::limits::WorkItem;
use crate::scene::shared::sensitivities::output;
use crate::scene::shared::sensitivities::{PARAMETERS_FIELD as FIELD, StopOrError, choose};
use crate::scene::summary::Metric;
use fields::{FIELDS, N_FIELDS};
use nalgebra::{SMatrix, SVector};
use trajectory::{Derivatives, Scan};

pub use crate::scene::shared::sensitivities::{ErrorControl, SensitivitiesTable};

/// What [`compute`] gives: the rows, and the sensitivity run's accepted
/// steps and right-hand-side evaluations (None when every row is flagged
/// because the run failed).
pub type Computed = (Vec<metrics::Row>, Option<(usize, usize)>);

/// The chosen fields' indices into [`FIELDS`], or the errors naming
/// `sensitivities.parameters`: an unknown name (with the valid ones), a
/// name given twice, an empty list, or a model variant without parameter
/// Jacobians.
pub fn check(table: &SensitivitiesTable, b: &Built) -> Result<Vec<usize>, SceneErrors> {
    let (chosen, mut errors) = choose(&table.parameters, &FIELDS);
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
    (chosen, control): (&[usize], ErrorControl),
) -> Result<Vec<Metric>, RunError> {
    let (rows, work) = compute(p, b, integrator, (chosen, control))?;
    let mut notes = output::write(ctx, &rows, &metrics::METRICS, "insert_compliant.")?;
    if let Some((steps, calls)) = work {
        let q = integrated(p, b, chosen).len();
        notes.push(Metric::note(
            "sensitivity run",
            format!(
                "{steps} steps, {calls} evaluations of the variational system ({q} of the {} \
                 fields named integrated, padded to {} components)",
                chosen.len(),
                N_STATE * (1 + N_FIELDS)
            ),
        ));
    }
    Ok(notes)
}

/// Bytes of one step kept by the plain pass: the time, the state, and the
/// four contacts' force and penetration (136 bytes), twice for the
/// vectors' growth.
const PASS_STEP_BYTES: f64 = 2.0 * 8.0 * (1 + N_STATE + 2 * trajectory::N_CONTACTS) as f64;

/// The work of the sensitivities of `chosen` fields, for the scene's
/// `[limits]`: the plain pass keeps up to `integrator.max_steps` steps
/// (`max_output_samples`, and their memory), and the sensitivity run takes
/// up to `integrator.max_steps` steps of `N (1 + P)` components for `P`
/// integrated fields, counted as `(1 + P) · max_steps` steps of the
/// model's `N` states (`max_steps`). Both name `sensitivities.parameters`.
pub fn work(
    p: &InsertParams,
    b: &Built,
    integrator: &IntegratorSpec,
    chosen: &[usize],
) -> Vec<WorkItem> {
    let q = integrated(p, b, chosen).len() as f64;
    let steps = integrator.max_steps as f64;
    vec![
        WorkItem::new(FIELD, "max_output_samples", steps, PASS_STEP_BYTES),
        WorkItem::new(FIELD, "max_steps", (1.0 + q) * steps, 0.0),
    ]
}

/// The fields integrated for `chosen` ones (indices into [`FIELDS`]):
/// those that move something the run depends on, in [`FIELDS`] order. A
/// field that moves nothing is a zero without integrating it.
pub fn integrated(p: &InsertParams, b: &Built, chosen: &[usize]) -> Vec<usize> {
    let (dp, dy0) = fields::jacobians(p, b);
    let mut columns: Vec<usize> = chosen
        .iter()
        .copied()
        .filter(|&k| !fields::unused(k, &dp, &dy0))
        .collect();
    columns.sort_unstable();
    columns
}

/// The rows of `chosen` fields (indices into [`FIELDS`]) for the scene's
/// parameters `p` built into `b`, integrated with `integrator`'s
/// tolerances, span and step budget (always Dormand–Prince 5(4)), and the
/// sensitivity run's accepted steps and right-hand-side evaluations (None
/// when it failed and every row is flagged). Only the chosen fields that
/// move something are integrated: `N (1 + P)` components for `P` of them.
///
/// # Errors
/// [`RunError::Sensitivity`] when the model refuses its parameters or
/// the integrator its input.
pub fn compute(
    p: &InsertParams,
    b: &Built,
    integrator: &IntegratorSpec,
    (chosen, control): (&[usize], ErrorControl),
) -> Result<Computed, RunError> {
    let (dp, dy0) = fields::jacobians(p, b);
    let values = fields::values(p);
    let unused: [bool; N_FIELDS] = std::array::from_fn(|k| fields::unused(k, &dp, &dy0));
    let columns = integrated(p, b, chosen);
    // Every field's direction: the plain pass and the metrics' gradients
    // (no integration along them).
    let all = CompliantDirections::new(&b.params, &b.load, dp, values)?;
    let options = Options {
        max_steps: integrator.max_steps,
        h0: integrator.h,
        ..integrator.tolerances("integrator", &all::Y_NAMES)?
    };
    let y0 = b.initial.to_vector();
    let (t0, t_end, target) = (integrator.t0, integrator.t_end, p.target_depth);
    let scan = trajectory::scan(&all, (t0, y0), t_end, target, &options)?;
    let run = Along {
        b,
        dp: &dp,
        dy0: &dy0,
        values: &values,
        columns: &columns,
        start: (t0, y0),
        t_end,
        target,
        options: &options,
        control,
        scan: &scan,
    };
    let d = match run.run() {
        Ok(d) => d,
        Err(e) => return Ok((metrics::failed(chosen, &e.flag()?), None)),
    };
    let rows = metrics::rows(
        &all,
        &values,
        (&scan, &d),
        &y0,
        (t_end, target),
        chosen,
        &unused,
    );
    Ok((rows, Some(d.work)))
}

/// The sensitivity run along the fields `columns` (indices into
/// [`FIELDS`]) of the full `∂p/∂q`, `∂y₀/∂q`.
struct Along<'a> {
    b: &'a Built,
    dp: &'a SMatrix<f64, N_PARAMS, N_FIELDS>,
    dy0: &'a SMatrix<f64, N_STATE, N_FIELDS>,
    values: &'a SVector<f64, N_FIELDS>,
    columns: &'a [usize],
    start: (f64, SVector<f64, N_STATE>),
    t_end: f64,
    target: f64,
    options: &'a Options,
    control: ErrorControl,
    scan: &'a Scan,
}

/// Components of the sensitivity run: the state and one column per field.
const M: usize = N_STATE * (1 + N_FIELDS);

impl Along<'_> {
    /// The run along the fields `columns`, each in its own column among
    /// every field's. The system's size is a compile-time constant and each
    /// size a compiled copy of the integrator and the sensitivity driver
    /// (the sizes 4, 8 and 21 together took a release build of the library
    /// from 92 s to 158 s of CPU), so there is one size: the columns of the
    /// fields not integrated have zero `∂p/∂q` and `∂y₀/∂q` and their
    /// sensitivities stay exactly zero. The step control measures what
    /// [`ErrorControl`] says: with the sensitivities in it, the tolerances
    /// are scaled so that the run takes the steps the run along the
    /// columns alone would, at the cost of every field
    /// (docs/sensitivities.md, "Accuracy and cost").
    fn run(&self) -> Result<Derivatives<N_FIELDS>, StopOrError> {
        let c = self.columns;
        let mut dp = SMatrix::<f64, N_PARAMS, N_FIELDS>::zeros();
        let mut dy0 = SMatrix::<f64, N_STATE, N_FIELDS>::zeros();
        for &k in c {
            dp.set_column(k, &self.dp.column(k));
            dy0.set_column(k, &self.dy0.column(k));
        }
        let sys = CompliantDirections::new(&self.b.params, &self.b.load, dp, *self.values)?;
        let target_column = c
            .contains(&fields::TARGET_DEPTH)
            .then_some(fields::TARGET_DEPTH);
        let options = self.control.options(self.options, N_STATE, c.len(), M);
        let (t0, y0) = self.start;
        trajectory::derivatives::<N_FIELDS, M>(
            &sys,
            (t0, y0, dy0),
            self.t_end,
            (self.target, target_column),
            &options,
            self.scan,
        )
    }
}
