//! Event accuracy of the rigid forward scene (`scenes/align_forward.toml`):
//! the whole run through `pegdyn::rigid_peg::trajectory::simulate`, with its
//! contact events, to its first event (the lift-off of K near 13 ms). For
//! each method setting: the event found, the error of its time and of the
//! state there against DOPRI5 at rtol 1e-14, the work and the median wall
//! time.

use nalgebra::Vector4;
use pegdyn::integrate::{Method, Options, Stats};
use pegdyn::output::csv::{CsvWriter, format_f64};
use pegdyn::rigid_peg::forward::ForwardModel;
use pegdyn::rigid_peg::stop::ForwardStop;
use pegdyn::rigid_peg::trajectory::{Trajectory, simulate};
use std::path::Path;

use crate::measure::median_time;
use crate::problems::align_forward_scene;

/// One row of the event table.
pub struct EventPoint {
    method: &'static str,
    setting: f64,
    stop: String,
    dt: f64,
    dx: f64,
    stats: Stats,
    wall_s: f64,
}

/// The time and state where a run stopped (state only for located events;
/// time NaN where [`ForwardStop::point`] has none).
fn stop_point(stop: &ForwardStop) -> (f64, Option<Vector4<f64>>) {
    stop.point().unwrap_or((f64::NAN, None))
}

fn run(
    model: &ForwardModel,
    x0: Vector4<f64>,
    span: (f64, f64),
    method: Method,
    rtol: f64,
    atol_ratio: f64,
) -> Trajectory {
    let mut o = Options::with_tolerances(rtol, rtol * atol_ratio);
    o.store = false;
    o.max_steps = 20_000_000;
    simulate(model, x0, span.0, span.1, method, &o).expect("valid scene")
}

/// (time error, state error) of `a`'s stop against `b`'s; NaN unless both
/// stopped at the same located event.
fn errors(a: &Trajectory, b: &Trajectory) -> (f64, f64) {
    if a.stop.name() != b.stop.name() {
        return (f64::NAN, f64::NAN);
    }
    let ((ta, xa), (tb, xb)) = (stop_point(&a.stop), stop_point(&b.stop));
    let dx = xa.zip(xb).map_or(f64::NAN, |(x, y)| (x - y).amax());
    ((ta - tb).abs(), dx)
}

/// Runs the table; prints it as markdown and writes `<out>/rigid_events.csv`.
pub fn study(out: &Path, repeats: usize) -> Result<(), Box<dyn std::error::Error>> {
    let (scene, model) = align_forward_scene();
    let x0 = scene.initial_state();
    let spec = &scene.integrator;
    let span = (spec.t0, spec.t_end);
    let ratio = spec.atol / spec.rtol;
    let reference = run(&model, x0, span, Method::Dopri5, 1e-14, ratio);
    let check = run(&model, x0, span, Method::Dopri5, 1e-13, ratio);
    let ref_err = errors(&check, &reference);
    let (t_ref, _) = stop_point(&reference.stop);
    let settings = [1e-4, 5e-5, 2e-5, 1e-5]
        .iter()
        .map(|&h| (Method::Rk4 { h }, h))
        .chain(
            [
                1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12,
            ]
            .iter()
            .map(|&r| (Method::Dopri5, r)),
        )
        .chain(
            [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8]
                .iter()
                .map(|&r| (Method::Rodas3, r)),
        )
        .chain(
            [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8]
                .iter()
                .map(|&r| (Method::Rodas4, r)),
        );
    let mut points = Vec::new();
    for (method, setting) in settings {
        let rtol = if matches!(method, Method::Rk4 { .. }) {
            1e-6
        } else {
            setting
        };
        let tr = run(&model, x0, span, method, rtol, ratio);
        let (dt, dx) = errors(&tr, &reference);
        let wall_s = median_time(repeats, || {
            std::hint::black_box(run(&model, x0, span, method, rtol, ratio));
        });
        points.push(EventPoint {
            method: method.name(),
            setting,
            stop: tr.stop.name(),
            dt,
            dx,
            stats: tr.stats,
            wall_s,
        });
    }
    println!(
        "\n### rigid_forward events\n\nscenes/align_forward.toml run by `simulate` with its events to its first event. \
         Reference: DOPRI5 rtol 1e-14 ({} steps), stop `{}` at t = {t_ref:.12} s; its error estimate \
         (vs rtol 1e-13): {:.1e} s in the event time, {:.1e} in the state there.\n",
        reference.stats.steps,
        reference.stop.name(),
        ref_err.0,
        ref_err.1
    );
    println!(
        "| method | h / rtol | event | steps | rejected | rhs | jac | event calls | time (ms) | event time err (s) | state err |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    let e = |v: f64| {
        if v.is_finite() {
            format!("{v:.1e}")
        } else {
            "different event".to_owned()
        }
    };
    for p in &points {
        println!(
            "| {} | {:e} | {} | {} | {} | {} | {} | {} | {:.3} | {} | {} |",
            p.method,
            p.setting,
            p.stop,
            p.stats.steps,
            p.stats.rejected,
            p.stats.rhs_calls,
            p.stats.jacobian_calls,
            p.stats.event_calls,
            p.wall_s * 1e3,
            e(p.dt),
            e(p.dx)
        );
    }
    let mut w = CsvWriter::create(
        &out.join("rigid_events.csv"),
        &[
            "method",
            "setting",
            "stop",
            "steps",
            "rejected",
            "rhs_calls",
            "jacobian_calls",
            "event_calls",
            "wall_s",
            "event_time_err",
            "state_err",
            "ref_event_time_err",
            "ref_state_err",
        ],
    )?;
    for p in &points {
        let cells = [
            p.method.to_owned(),
            format_f64(p.setting),
            p.stop.clone(),
            p.stats.steps.to_string(),
            p.stats.rejected.to_string(),
            p.stats.rhs_calls.to_string(),
            p.stats.jacobian_calls.to_string(),
            p.stats.event_calls.to_string(),
            format_f64(p.wall_s),
            format_f64(p.dt),
            format_f64(p.dx),
            format_f64(ref_err.0),
            format_f64(ref_err.1),
        ];
        let refs: Vec<&str> = cells.iter().map(String::as_str).collect();
        w.row_cells(&refs)?;
    }
    w.finish()?;
    Ok(())
}
