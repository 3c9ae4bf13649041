//! The `[sensitivities]` table of an `insert_rcc` scene: derivatives of
//! the insertion's metrics with respect to design fields of the scene, by
//! forward sensitivities of the held compliant 3-D peg along them
//! ([`crate::compliant_peg_3d::design`], integrated by
//! [`crate::sensitivity::integrate`]).
//!
//! ```toml
//! [sensitivities]
//! parameters = ["wrist.lateral_stiffness", "peg.friction", "robot.lateral_error"]
//! ```
//!
//! The fields are those of
//! [`crate::scene::shared::compliant_peg_3d::design::FIELDS`]; each moves
//! the model and the start through the scene's translation in dual
//! numbers. A sensitivity run carries up to
//! [`N_DESIGN`] fields; a table naming more is run in passes of that many
//! (each pass integrates the state again with its fields' columns). The metrics and their flags are in [`metrics`]; the files
//! (`<scene>.sensitivities.csv`, the tornado plot) and the printed ranking
//! in [`crate::scene::shared::sensitivities::output`]. See
//! `docs/sensitivities.md`, "In scenes".

pub mod metrics;
mod trajectory;

use crate::compliant_peg_3d::design::{Directions, N_DESIGN};
use crate::compliant_peg_3d::insertion::{Insertion, N_STATE};
use crate::error::{RunError, SceneError, SceneErrors};
use crate::integrate::{Method, Options, Stats};
use crate::scene::context::RunContext;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::limits::WorkItem;
use crate::scene::shared::compliant_peg_3d::design::{
    FIELDS, Seeds, design, fixed_stiffness, seeds, slot_values,
};
use crate::scene::shared::compliant_peg_3d::insertion::{Built, RccScene};
use crate::scene::shared::sensitivities::{
    ErrorControl, PARAMETERS_FIELD as FIELD, StopOrError, choose,
};
use crate::scene::shared::sensitivities::{Row, output};
use crate::scene::simulate::solver_config;
use crate::scene::summary::Metric;
use nalgebra::SMatrix;

pub use crate::scene::shared::sensitivities::SensitivitiesTable;

/// The chosen fields' slots in [`FIELDS`], or the errors naming
/// `sensitivities.parameters`: an unknown name (with the valid ones), a
/// name given twice, an empty list, or contacts whose stiffness comes from
/// the curvatures (its variation with the geometry is not carried).
///
/// # Errors
/// Every problem with the table, named.
pub fn check(table: &SensitivitiesTable, b: &Built) -> Result<Vec<usize>, SceneErrors> {
    let (chosen, mut errors) = choose(&table.parameters, &FIELDS);
    if !fixed_stiffness(&b.params) {
        errors.push(SceneError::invalid(
            FIELD,
            &table.parameters,
            "sensitivities need a fixed Hertz stiffness, peg.contact_stiffness (the curvature \
             stiffness's variation with the geometry is not carried)",
        ));
    }
    if errors.is_empty() {
        Ok(chosen)
    } else {
        Err(SceneErrors::new(errors))
    }
}

/// Bytes of one step kept by the sensitivity run: its time, largest
/// contact force and wrist force, twice for the vectors' growth.
const PASS_STEP_BYTES: f64 = 2.0 * 8.0 * 3.0;

/// The sensitivity runs a table of `fields` fields takes: one per
/// [`N_DESIGN`] fields.
pub fn passes(fields: usize) -> usize {
    fields.div_ceil(N_DESIGN)
}

/// The work of the sensitivities, for the scene's `[limits]`: each of the
/// [`passes`] keeps three numbers of each of up to `integrator.max_steps`
/// steps, and takes up to `integrator.max_steps` steps of `N (1 + P)`
/// components, counted as `(1 + P) · max_steps` steps of the model's `N`
/// states for its `P` fields (as `insert_compliant` counts them), for a
/// table of `fields` fields.
pub fn work(integrator: &IntegratorSpec, fields: usize) -> Vec<WorkItem> {
    let steps = integrator.max_steps as f64;
    let runs = passes(fields) as f64;
    let p = fields as f64;
    vec![
        WorkItem::new(FIELD, "max_output_samples", steps, runs * PASS_STEP_BYTES),
        WorkItem::new(FIELD, "max_steps", (runs + p) * steps, 0.0),
    ]
}

/// Runs the sensitivities of the `chosen` fields and writes their files;
/// returns the ranking notes for the run's summary.
///
/// # Errors
/// The files cannot be written, or the integrator refuses its input.
pub fn run(
    ctx: &RunContext,
    scene: &RccScene,
    b: &Built,
    integrator: &IntegratorSpec,
    chosen: &[usize],
) -> Result<Vec<Metric>, RunError> {
    let (rows, work) = compute(scene, b, integrator, chosen)?;
    let mut notes = output::write(ctx, &rows, &metrics::METRICS, "")?;
    if let Some(w) = work {
        let runs = passes(chosen.len());
        let how = if runs == 1 {
            String::new()
        } else {
            format!(" in {runs} passes")
        };
        let fallback = if w.fallback_steps == 0 {
            String::new()
        } else {
            format!(
                "; {} steps across a contact splitting in two judged by the state's error alone",
                w.fallback_steps
            )
        };
        notes.push(Metric::note(
            "sensitivity run",
            format!(
                "{} steps, {} evaluations of the variational system ({} fields{how}, {} \
                 components){fallback}",
                w.steps,
                w.rhs_calls,
                chosen.len(),
                trajectory::M
            ),
        ));
    }
    Ok(notes)
}

/// Whether the field of slot `j` moves nothing the run depends on: every
/// derivative of the model's quantities and of the start in the slot is
/// zero (an empty slot moves nothing).
fn unused(scene: &RccScene, b: &Built, seeds: &Seeds) -> [bool; N_DESIGN] {
    let (d, y0) = design(scene, b, seeds);
    let mut moved = [false; N_DESIGN];
    let mut mark = |x: &crate::compliant_peg_3d::design::Q| {
        for (m, v) in moved.iter_mut().zip(&x.d[..N_DESIGN]) {
            *m |= *v != 0.0;
        }
    };
    d.p.iter().chain(&y0).for_each(&mut mark);
    let w = &d.wrist;
    let r = &d.robot;
    [d.law.friction, d.law.damping, d.law.slip_scale]
        .iter()
        .chain(&[w.centre_height, w.axial, w.angular, w.torsional])
        .chain(&w.lateral)
        .chain(&r.start)
        .chain(&[r.tilt, r.speed, r.end, r.precession_rate, r.spin_rate])
        .for_each(&mut mark);
    moved.map(|m| !m)
}

/// What [`compute`] gives: the rows, and the sensitivity runs' work
/// counters summed (None when every row is flagged because a run
/// failed).
pub type Computed = (Vec<Row>, Option<Stats>);

/// The rows of the `chosen` fields (indices into [`FIELDS`]) of scene
/// `scene` built into `b`, integrated with `integrator`'s method,
/// tolerances, span and step budget, and the sensitivity runs' work: one
/// run per [`N_DESIGN`] fields ([`passes`]), the rows metric by metric in
/// the order of `chosen`. The chosen fields that move something are
/// seeded; the others are constants (their columns stay zero); the step
/// control measures what the table's [`ErrorControl`] says.
///
/// # Errors
/// [`RunError::Sensitivity`] when the integrator refuses its input.
pub fn compute(
    scene: &RccScene,
    b: &Built,
    integrator: &IntegratorSpec,
    chosen: &[usize],
) -> Result<Computed, RunError> {
    if chosen.len() <= N_DESIGN {
        return compute_pass(scene, b, integrator, chosen);
    }
    let mut rows = Vec::new();
    let mut work = Some(Stats::default());
    for fields in chosen.chunks(N_DESIGN) {
        let (pass, w) = compute_pass(scene, b, integrator, fields)?;
        rows.extend(pass);
        work = work.zip(w).map(|(mut a, b)| {
            a += &b;
            a
        });
    }
    Ok((metric_major(rows, chosen), work))
}

/// `rows` of several passes ordered metric by metric (in the order the
/// metrics first appear), each metric's fields in the order of `chosen`.
fn metric_major(mut rows: Vec<Row>, chosen: &[usize]) -> Vec<Row> {
    let mut names: Vec<&'static str> = Vec::new();
    for r in &rows {
        if !names.contains(&r.metric) {
            names.push(r.metric);
        }
    }
    let at = |r: &Row| {
        let metric = names.iter().position(|n| *n == r.metric);
        let field = chosen.iter().position(|&k| FIELDS[k] == r.parameter);
        (metric, field)
    };
    rows.sort_by_key(at);
    rows
}

/// [`compute`] for at most [`N_DESIGN`] fields: one sensitivity run.
fn compute_pass(
    scene: &RccScene,
    b: &Built,
    integrator: &IntegratorSpec,
    fields: &[usize],
) -> Result<Computed, RunError> {
    let all = seeds(fields);
    let unused = unused(scene, b, &all);
    let active: Seeds = std::array::from_fn(|j| all[j].filter(|_| !unused[j]));
    let (d, y0q) = design(scene, b, &active);
    let dy0 = SMatrix::<f64, N_STATE, N_DESIGN>::from_fn(|i, k| y0q[i].d[k]);
    let (sys, y0, (method, options)) = plain(b, integrator)?;
    let (t0, t_end, seat) = (integrator.t0, integrator.t_end, b.criteria.seat_depth);
    let values = slot_values(scene, &all);
    let p = active.iter().flatten().count();
    let control = ErrorControl::of(scene.sensitivities.as_ref());
    let run_options = control.options(&options, N_STATE, p, trajectory::M);
    let dir = Directions {
        system: &sys,
        design: d,
        values,
    };
    let result = trajectory::derivatives(
        &dir,
        (t0, y0, dy0),
        t_end,
        b.criteria,
        (method, &run_options),
    );
    let (scan, der) = match result {
        Ok(found) => found,
        Err(e) => return Ok((metrics::failed(fields, &e.flag()?), None)),
    };
    let inputs = metrics::Inputs {
        sys: &sys,
        design: &d,
        values: &values,
        scan: &scan,
        d: &der,
        ends: (t_end, seat),
    };
    let names: Vec<&'static str> = fields.iter().map(|&k| FIELDS[k]).collect();
    let rows = metrics::rows(&inputs, &names, &unused);
    Ok((rows, Some(der.work)))
}

/// The plain run of a scene: its system, start state, and the method and
/// options of its integrator (the sensitivity run's before their scaling).
type PlainRun = (
    Insertion,
    nalgebra::SVector<f64, N_STATE>,
    (Method, Options),
);

/// The plain run of `b` with `integrator`.
///
/// # Errors
/// [`RunError::Integrate`] for `rk4` without a step.
fn plain(b: &Built, integrator: &IntegratorSpec) -> Result<PlainRun, RunError> {
    let sys = Insertion::new(b.params, Some(b.held), 0.0);
    let y0 = b.start_state(&sys);
    let names = &crate::compliant_peg_3d::insertion::STATE_NAMES;
    let (method, _) = solver_config(integrator, names)?;
    let options = Options {
        max_steps: integrator.max_steps,
        h0: integrator.h,
        ..integrator.tolerances("integrator", names)?
    };
    Ok((sys, y0, (method, options)))
}

/// The metrics' values of scene `scene` built into `b` by plain runs (no
/// sensitivities) with the events of the sensitivity run: each metric of
/// [`metrics::METRICS`] the run has, with its value (the reference of the
/// derivatives' differences); `None` when the run stops short.
///
/// # Errors
/// [`RunError::Sensitivity`] when the integrator refuses its input.
pub fn metric_values(
    scene: &RccScene,
    b: &Built,
    integrator: &IntegratorSpec,
) -> Result<Option<Vec<(&'static str, f64)>>, RunError> {
    let none: Seeds = [None; N_DESIGN];
    let (d, _) = design(scene, b, &none);
    let (sys, y0, (method, options)) = plain(b, integrator)?;
    let dir = Directions {
        system: &sys,
        design: d,
        values: slot_values(scene, &none),
    };
    let start = (integrator.t0, y0);
    match trajectory::values(
        &dir,
        start,
        integrator.t_end,
        b.criteria,
        (method, &options),
    ) {
        Ok(v) => Ok(Some(
            v.into_iter()
                .map(|(k, v)| (metrics::METRICS[k], v))
                .collect(),
        )),
        Err(StopOrError::Error(e)) => Err(e.into()),
        Err(StopOrError::Stopped(_)) => Ok(None),
    }
}
