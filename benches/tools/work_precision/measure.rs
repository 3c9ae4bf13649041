//! One point of a work-precision diagram: run a method, time it (median of
//! repeated batches), and measure its error against the reference at the
//! common output times.

use std::time::Instant;

use nalgebra::SVector;
use pegdyn::integrate::{Method, Options, OutputMode, Solution, Solver, Stats};
use pegdyn::system::OdeSystem;

use crate::problems::Problem;

/// A trajectory at the common output times (`None` where the run stopped
/// early or failed).
pub type Trajectory<const N: usize> = Vec<Option<SVector<f64, N>>>;

/// The measured point.
#[derive(Clone, Debug)]
pub struct Point {
    /// `rk4`, `dopri5`, `rodas3` or `rodas4`.
    pub method: &'static str,
    /// `h` for RK4, `rtol` otherwise.
    pub setting: f64,
    /// Work counters of one run.
    pub stats: Stats,
    /// Median wall time of one run (s).
    pub wall_s: f64,
    /// Error of the coordinates at `t_end` (max norm); infinite if the run
    /// did not reach it.
    pub err_end: f64,
    /// Largest coordinate error over the output times.
    pub err_max: f64,
    /// Why the run stopped (`ReachedEnd` when it succeeded).
    pub stop: String,
    /// `false` when an error of the point is not at least 2× the
    /// reference's error estimate (the reference cannot judge it).
    pub resolved: bool,
}

/// Options with output at `times` and `atol = atol_scale · rtol`.
fn options(rtol: f64, atol_scale: f64, times: &[f64]) -> Options {
    let mut o = Options::with_tolerances(rtol, rtol * atol_scale);
    o.output = OutputMode::AtTimes(times.to_vec());
    o.max_steps = 20_000_000;
    o
}

/// Runs `method` once.
pub fn run<const N: usize, S: OdeSystem<N>>(
    pb: &Problem<N, S>,
    method: Method,
    rtol: f64,
    times: &[f64],
) -> Solution<N> {
    Solver::new(method, options(rtol, pb.atol_scale, times))
        .solve(&pb.system, 0.0, pb.y0, pb.t_end)
        .expect("valid options")
}

/// The solution at the output times.
pub fn trajectory<const N: usize>(sol: &Solution<N>, times: &[f64]) -> Trajectory<N> {
    times
        .iter()
        .map(|&t| {
            sol.t
                .iter()
                .position(|&s| s == t)
                .map(|k| sol.x[k])
                .filter(|x| x.iter().all(|v| v.is_finite()))
        })
        .collect()
}

/// Coordinate errors of `a` against `b`: (at the last time, max over times);
/// infinite where `a` is missing.
pub fn errors<const N: usize>(
    a: &Trajectory<N>,
    b: &Trajectory<N>,
    coords: &[usize],
) -> (f64, f64) {
    let err = |x: &Option<SVector<f64, N>>, y: &Option<SVector<f64, N>>| match (x, y) {
        (Some(x), Some(y)) => coords
            .iter()
            .map(|&i| (x[i] - y[i]).abs())
            .fold(0.0, f64::max),
        _ => f64::INFINITY,
    };
    let end = a
        .last()
        .zip(b.last())
        .map_or(f64::INFINITY, |(x, y)| err(x, y));
    let max = a.iter().zip(b).map(|(x, y)| err(x, y)).fold(0.0, f64::max);
    (end, max)
}

/// Median wall time of one run of `f`: batches of runs lasting at least
/// 5 ms each (or one run), at least `repeats` batches.
pub fn median_time(repeats: usize, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    f();
    let once = start.elapsed().as_secs_f64().max(1e-9);
    let per_batch = ((5e-3 / once).ceil() as usize).clamp(1, 100_000);
    let mut times: Vec<f64> = (0..repeats.max(3))
        .map(|_| {
            let start = Instant::now();
            for _ in 0..per_batch {
                f();
            }
            start.elapsed().as_secs_f64() / per_batch as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// Measures `method` at `setting` against the reference trajectory.
#[allow(clippy::too_many_arguments)]
pub fn point<const N: usize, S: OdeSystem<N>>(
    pb: &Problem<N, S>,
    method: Method,
    setting: f64,
    times: &[f64],
    reference: &Trajectory<N>,
    reference_error: (f64, f64),
    repeats: usize,
) -> Point {
    let rtol = if matches!(method, Method::Rk4 { .. }) {
        1e-6
    } else {
        setting
    };
    let sol = run(pb, method, rtol, times);
    let (err_end, err_max) = errors(&trajectory(&sol, times), reference, pb.coords.0);
    let wall_s = median_time(repeats, || {
        std::hint::black_box(run(pb, method, rtol, times));
    });
    Point {
        method: method.name(),
        setting,
        stats: sol.stats,
        wall_s,
        err_end,
        err_max,
        stop: format!("{:?}", sol.stop),
        resolved: err_end >= 2.0 * reference_error.0 && err_max >= 2.0 * reference_error.1,
    }
}
