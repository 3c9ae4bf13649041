//! Work-precision of the compliant 3-D peg's scene kinds: each run as its
//! scene runs it (an event for every contact transition; for an insertion
//! the terminal events too), its cost (steps, right-hand sides, Jacobians,
//! least CPU time of this thread over the repeats) and its error against a tight reference in the
//! quantities a user reads:
//!
//! - depth and tilt at the scene's output times, the largest difference
//!   over the largest value of the reference (target 1e-6);
//! - the peak contact normal force over the output times, relative
//!   (target 1e-3);
//! - the time of every contact transition (s; target 1e-5 s): for each of
//!   the reference's, the nearest of the run's of the same pair, count and
//!   direction (infinite when the run has none);
//! - the end time: the terminal event's (seated, a force limit) or the end
//!   of the span (s; target 1e-5 s).
//!
//! The reference is checked against a second tight run; where the two
//! differ by more than a tenth of a target (a contact whose search result
//! depends on the search's history, at the landing of an insertion), the
//! reference cannot judge: depth, tilt and transitions are compared only
//! on the samples and transitions where they agree ([`Judged`]), and the
//! share judged is printed.

use std::path::Path;

use nalgebra::SVector;
use pegdyn::compliant_peg_3d::Peg3dParams;
use pegdyn::compliant_peg_3d::insertion::{Insertion, N_STATE, depth_tilt, peg_state};
use pegdyn::compliant_peg_3d::outcome::{CountCache, TERMINAL_NAMES, transition_events};
use pegdyn::integrate::{MethodKind, OutputMode, Solution, Solver, Stats};
use pegdyn::output::csv::{CsvWriter, format_f64};
use pegdyn::output::plot::{Figure, Panel, Scale, Series, Style};
use pegdyn::scene::document::Document;
use pegdyn::scene::integrator::IntegratorSpec;
use pegdyn::scene::kinds::drop_3d::DropScene;
use pegdyn::scene::shared::compliant_peg_3d::insertion::{Built, RccScene, run_one};
use pegdyn::scene::{Method as SceneMethod, Progress};

/// The targets of the depth/tilt, peak force and transition errors, and
/// of the end time (the terminal event's, or the end of the span).
pub const TARGETS: [f64; 5] = [1e-6, 1e-6, 1e-3, 1e-5, 1e-5];

/// What a case runs.
pub enum Setup {
    /// An `insert_rcc` scene.
    Insertion(Box<Built>),
    /// A `drop_3d` scene: the peg, its start and the follower moment.
    Drop(Box<(Peg3dParams, SVector<f64, N_STATE>, f64)>),
}

/// One scene of the study.
pub struct Case {
    /// Name in file names and tables.
    pub name: String,
    /// What it is.
    pub about: String,
    /// What runs.
    pub setup: Setup,
    /// The scene's `[integrator]` table (span, output interval).
    pub spec: IntegratorSpec,
    /// `atol = atol_scale · rtol` (the scene's ratio).
    pub atol_scale: f64,
    /// The reference: method and rtol; its error is estimated against the
    /// `check` run.
    pub reference: (MethodKind, f64),
    /// The run the reference is checked against.
    pub check: (MethodKind, f64),
    /// The settings measured: (method, rtol or RK4 step).
    pub settings: Vec<(MethodKind, f64)>,
}

/// An `insert_rcc` scene file's case.
pub fn insertion(name: &str, about: &str, text: &str) -> Case {
    let scene: RccScene = Document::parse(text)
        .and_then(|d| d.body())
        .expect("the scene parses");
    let built = scene.build().expect("the scene is valid");
    Case {
        name: name.to_owned(),
        about: about.to_owned(),
        setup: Setup::Insertion(Box::new(built)),
        atol_scale: scene.integrator.atol / scene.integrator.rtol,
        spec: scene.integrator,
        reference: (MethodKind::Dopri5, 1e-11),
        check: (MethodKind::Rodas4, 1e-9),
        settings: Vec::new(),
    }
}

/// A `drop_3d` scene file's case.
pub fn drop(name: &str, about: &str, text: &str) -> Case {
    let scene: DropScene = Document::parse(text)
        .and_then(|d| d.body())
        .expect("the scene parses");
    let (params, start) = scene.build().expect("the scene is valid");
    Case {
        name: name.to_owned(),
        about: about.to_owned(),
        setup: Setup::Drop(Box::new((params, start, scene.drop.aligning_moment))),
        atol_scale: scene.integrator.atol / scene.integrator.rtol,
        spec: scene.integrator,
        reference: (MethodKind::Dopri5, 1e-11),
        check: (MethodKind::Rodas4, 1e-9),
        settings: Vec::new(),
    }
}

/// One measured run.
pub struct Measured {
    /// Work counters.
    pub stats: Stats,
    /// CPU time of the run on this thread (s).
    pub cpu_s: f64,
    /// Where it stopped (s).
    pub t_final: f64,
    /// How it stopped.
    pub stop: String,
    /// `(t, depth, tilt)` at the output times.
    pub samples: Vec<(f64, f64, f64)>,
    /// Largest contact normal force over the output times (N).
    pub peak: f64,
    /// Every transition `(event, rising, t)` in order, then the terminal
    /// event's `(usize::MAX, true, t)`.
    pub transitions: Vec<(usize, bool, f64)>,
}

/// CPU time of this thread (s): `clock_gettime(CLOCK_THREAD_CPUTIME_ID)`,
/// to the nanosecond (the kernel adds the running slice when asked; the
/// thread's `/proc/.../schedstat` is brought up to date only at scheduler
/// ticks, 4 ms here), else the wall clock since the first call.
pub fn cpu_now() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec; the call only writes it.
    if unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) } == 0 {
        return ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9;
    }
    static START: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();
    START
        .get_or_init(std::time::Instant::now)
        .elapsed()
        .as_secs_f64()
}

fn spec_for(case: &Case, kind: MethodKind, setting: f64) -> IntegratorSpec {
    let mut spec = case.spec.clone();
    spec.method = SceneMethod::Named(kind);
    spec.max_steps = 5_000_000;
    if kind == MethodKind::Rk4 {
        spec.h = Some(setting);
    } else {
        spec.h = None;
        spec.rtol = setting;
        spec.atol = setting * case.atol_scale;
    }
    spec
}

fn samples(sys: &Insertion, sol: &Solution<N_STATE>) -> (Vec<(f64, f64, f64)>, f64) {
    let prm = &sys.peg.params;
    let mut peak = 0.0_f64;
    let rows = sol
        .t
        .iter()
        .zip(&sol.x)
        .map(|(&t, y)| {
            let ys = peg_state(y);
            let (depth, tilt, _) = depth_tilt(prm, &ys);
            if let Ok(f) = sys.peg.forces(&ys) {
                peak = f.iter().map(|f| f.normal_force).fold(peak, f64::max);
            }
            (t, depth, tilt)
        })
        .collect();
    (rows, peak)
}

/// Runs `case` with `kind` at `setting` (rtol, or the step of RK4).
pub fn run(case: &Case, kind: MethodKind, setting: f64) -> Measured {
    let spec = spec_for(case, kind, setting);
    match &case.setup {
        Setup::Insertion(built) => {
            let c0 = cpu_now();
            let r = run_one(built, &spec, true, &mut Progress::silent()).expect("the run starts");
            let cpu_s = cpu_now() - c0;
            let sol = &r.solution;
            let mut transitions: Vec<(usize, bool, f64)> = sol
                .events
                .iter()
                .filter(|e| e.index < r.transitions.len())
                .map(|e| (e.index, e.rising, e.t))
                .collect();
            if let pegdyn::integrate::StopReason::Event { index, t } = sol.stop
                && index < TERMINAL_NAMES.len()
            {
                transitions.push((usize::MAX - index, true, t));
            }
            let (rows, peak) = samples(&r.system, sol);
            Measured {
                stats: sol.stats,
                cpu_s,
                t_final: sol.t_final,
                stop: format!("{} ({:?})", r.outcome.name(), sol.stop),
                samples: rows,
                peak,
                transitions,
            }
        }
        Setup::Drop(drop) => {
            let (params, start, aligning) = &**drop;
            let sys = Insertion::new(*params, None, *aligning);
            let cache = CountCache::new(&sys);
            let (events, _) = transition_events(&cache);
            let method = kind.with_step(spec.h).expect("a step for RK4");
            let mut opts = spec
                .tolerances(
                    "integrator",
                    &pegdyn::compliant_peg_3d::insertion::STATE_NAMES,
                )
                .expect("the scene's state names");
            opts.max_steps = spec.max_steps;
            opts.output = OutputMode::AtTimes(spec.output_times().collect());
            let mut solver = events
                .into_iter()
                .fold(Solver::new(method, opts), Solver::with_event);
            let c0 = cpu_now();
            let sol = solver
                .solve(&sys, spec.t0, *start, spec.t_end)
                .expect("valid options");
            let cpu_s = cpu_now() - c0;
            let transitions = sol
                .events
                .iter()
                .map(|e| (e.index, e.rising, e.t))
                .collect();
            let (rows, peak) = samples(&sys, &sol);
            Measured {
                stats: sol.stats,
                cpu_s,
                t_final: sol.t_final,
                stop: format!("{:?}", sol.stop),
                samples: rows,
                peak,
                transitions,
            }
        }
    }
}

/// Per-sample depth and tilt differences of `m` from `reference` over
/// their largest reference values; `None` where the runs' samples do not
/// line up (a run that stopped more than one sample apart).
fn sample_errors(m: &Measured, reference: &Measured) -> Option<Vec<(f64, f64)>> {
    let scale = |f: fn(&(f64, f64, f64)) -> f64| {
        reference
            .samples
            .iter()
            .map(|s| f(s).abs())
            .fold(f64::MIN_POSITIVE, f64::max)
    };
    let (sd, st) = (scale(|s| s.1), scale(|s| s.2));
    let out: Vec<(f64, f64)> = m
        .samples
        .iter()
        .zip(&reference.samples)
        .take_while(|(a, b)| a.0 == b.0)
        .map(|(a, b)| ((a.1 - b.1).abs() / sd, (a.2 - b.2).abs() / st))
        .collect();
    (out.len() + 1 >= reference.samples.len().max(m.samples.len())).then_some(out)
}

/// For each transition of `reference`, the time to the nearest transition
/// of `m` of the same event and direction (infinite when `m` has none).
fn transition_errors(m: &Measured, reference: &Measured) -> Vec<f64> {
    reference
        .transitions
        .iter()
        .map(|r| {
            m.transitions
                .iter()
                .filter(|a| (a.0, a.1) == (r.0, r.1))
                .map(|a| (a.2 - r.2).abs())
                .fold(f64::INFINITY, f64::min)
        })
        .collect()
}

/// What the reference can judge: the samples and transitions where it
/// agrees with its check run to a tenth of the targets.
pub struct Judged {
    /// Per output sample of the reference.
    pub samples: Vec<bool>,
    /// Per transition of the reference.
    pub transitions: Vec<bool>,
}

impl Judged {
    /// The samples and transitions of `reference` that `check` matches to
    /// a tenth of the targets.
    pub fn new(check: &Measured, reference: &Measured) -> Judged {
        let per = sample_errors(check, reference).unwrap_or_default();
        let samples = (0..reference.samples.len())
            .map(|k| {
                per.get(k)
                    .is_some_and(|&(d, t)| d <= 0.1 * TARGETS[0] && t <= 0.1 * TARGETS[1])
            })
            .collect();
        let transitions = transition_errors(check, reference)
            .iter()
            .map(|&e| e <= 0.1 * TARGETS[3])
            .collect();
        Judged {
            samples,
            transitions,
        }
    }

    /// `(judged, all)` samples.
    pub fn sample_share(&self) -> (usize, usize) {
        (
            self.samples.iter().filter(|&&j| j).count(),
            self.samples.len(),
        )
    }

    /// `(judged, all)` transitions.
    pub fn transition_share(&self) -> (usize, usize) {
        (
            self.transitions.iter().filter(|&&j| j).count(),
            self.transitions.len(),
        )
    }
}

/// The errors `[depth, tilt, peak force, transition times, end time]` of
/// `m` against `reference` (module documentation), depth, tilt and
/// transitions over what `judged` marks (all of them when `None`).
pub fn errors(m: &Measured, reference: &Measured, judged: Option<&Judged>) -> [f64; 5] {
    let (depth, tilt) = match sample_errors(m, reference) {
        Some(per) => per
            .iter()
            .enumerate()
            .filter(|(k, _)| judged.is_none_or(|j| j.samples[*k]))
            .fold((0.0_f64, 0.0_f64), |(d, t), (_, e)| {
                (d.max(e.0), t.max(e.1))
            }),
        None => (f64::INFINITY, f64::INFINITY),
    };
    let peak = (m.peak - reference.peak).abs() / reference.peak.abs().max(f64::MIN_POSITIVE);
    let transitions = transition_errors(m, reference)
        .iter()
        .enumerate()
        .filter(|(k, _)| judged.is_none_or(|j| j.transitions[*k]))
        .fold(0.0_f64, |a, (_, &e)| a.max(e));
    [
        depth,
        tilt,
        peak,
        transitions,
        (m.t_final - reference.t_final).abs(),
    ]
}

/// One point of a study.
pub struct Point {
    /// The method.
    pub method: MethodKind,
    /// rtol, or the step of RK4.
    pub setting: f64,
    /// The run.
    pub run: Measured,
    /// Its errors.
    pub errors: [f64; 5],
}

/// A case measured.
pub struct Study {
    /// The case's name.
    pub name: String,
    /// What it is.
    pub about: String,
    /// The reference run.
    pub reference: Measured,
    /// Its description.
    pub reference_label: String,
    /// The reference's errors against its check run.
    pub reference_errors: [f64; 5],
    /// The points.
    pub points: Vec<Point>,
    /// What the reference judges.
    pub judged: Judged,
}

/// The run of `case` with `method` at `setting` of least CPU time over
/// `repeats` runs (at least one; the runs are deterministic, only the
/// time differs).
fn least_cpu(case: &Case, method: MethodKind, setting: f64, repeats: usize) -> Measured {
    (0..repeats.max(1))
        .map(|_| run(case, method, setting))
        .min_by(|a, b| a.cpu_s.total_cmp(&b.cpu_s))
        .expect("at least one run")
}

/// A run's work: steps, right-hand sides, Jacobians and CPU time, in
/// total and per simulated second.
fn work_text(m: &Measured) -> String {
    format!(
        "{} steps, {} rhs, {} jac, {:.4} s CPU ({:.4} s per simulated s)",
        m.stats.steps,
        m.stats.rhs_calls,
        m.stats.jacobian_calls,
        m.cpu_s,
        m.cpu_s / m.t_final
    )
}

/// Prints the cost of each of `case`'s settings (least CPU time over
/// `repeats` runs), without a reference.
pub fn cost(case: &Case, repeats: usize) {
    for &(method, setting) in &case.settings {
        let m = least_cpu(case, method, setting, repeats);
        eprintln!(
            "{} {} {:e}: {}, peak {:.6e} N, {}",
            case.name,
            method.name(),
            setting,
            work_text(&m),
            m.peak,
            m.stop
        );
    }
}

/// Runs every setting of `case` against its reference; each setting
/// `repeats` times (at least once), keeping the run of least CPU time (the
/// runs are deterministic: only the time differs).
pub fn study(case: &Case, repeats: usize) -> Study {
    let reference = run(case, case.reference.0, case.reference.1);
    let check = run(case, case.check.0, case.check.1);
    let reference_errors = errors(&check, &reference, None);
    let judged = Judged::new(&check, &reference);
    eprintln!(
        "{}: reference {} rtol {:e}: {} steps, {:.1} s CPU, {}; check {} rtol {:e}: errors {}",
        case.name,
        case.reference.0.name(),
        case.reference.1,
        reference.stats.steps,
        reference.cpu_s,
        reference.stop,
        case.check.0.name(),
        case.check.1,
        Fmt(reference_errors)
    );
    let mut points = Vec::new();
    for &(method, setting) in &case.settings {
        let m = least_cpu(case, method, setting, repeats);
        let e = errors(&m, &reference, Some(&judged));
        eprintln!(
            "  {} {:e}: {}, errors {}, {}",
            method.name(),
            setting,
            work_text(&m),
            Fmt(e),
            m.stop
        );
        points.push(Point {
            method,
            setting,
            run: m,
            errors: e,
        });
    }
    Study {
        name: case.name.clone(),
        about: case.about.clone(),
        reference_label: format!(
            "{} rtol {:e} ({} steps), checked against {} rtol {:e}",
            case.reference.0.name(),
            case.reference.1,
            reference.stats.steps,
            case.check.0.name(),
            case.check.1
        ),
        reference,
        reference_errors,
        points,
        judged,
    }
}

/// Appends the points of `studies` to a CSV at `path`.
pub fn write_csv(path: &Path, studies: &[Study]) -> Result<(), Box<dyn std::error::Error>> {
    let mut w = CsvWriter::create(
        path,
        &[
            "problem",
            "method",
            "setting",
            "steps",
            "rejected",
            "rhs_calls",
            "jacobian_calls",
            "lu",
            "event_calls",
            "cpu_s",
            "simulated_s",
            "cpu_per_simulated_s",
            "err_depth",
            "err_tilt",
            "err_peak_force",
            "err_transition_s",
            "err_end_time_s",
            "transitions",
            "stop",
        ],
    )?;
    for col in [
        "err_depth",
        "err_tilt",
        "err_peak_force",
        "err_transition_s",
        "err_end_time_s",
    ] {
        w.allow_infinite(col);
    }
    for s in studies {
        let rows = std::iter::once(("reference", s.reference_errors, &s.reference, 0.0)).chain(
            s.points
                .iter()
                .map(|p| (p.method.name(), p.errors, &p.run, p.setting)),
        );
        for (method, e, m, setting) in rows {
            let cells = [
                s.name.clone(),
                method.to_owned(),
                format_f64(setting),
                m.stats.steps.to_string(),
                m.stats.rejected.to_string(),
                m.stats.rhs_calls.to_string(),
                m.stats.jacobian_calls.to_string(),
                m.stats.lu_factorizations.to_string(),
                m.stats.event_calls.to_string(),
                format_f64(m.cpu_s),
                format_f64(m.t_final),
                format_f64(m.cpu_s / m.t_final),
                format_f64(e[0]),
                format_f64(e[1]),
                format_f64(e[2]),
                format_f64(e[3]),
                format_f64(e[4]),
                m.transitions.len().to_string(),
                m.stop.replace(',', ";"),
            ];
            let refs: Vec<&str> = cells.iter().map(String::as_str).collect();
            w.row_cells(&refs)?;
        }
    }
    w.finish()?;
    Ok(())
}

/// Prints a study as a markdown table.
pub fn print_table(s: &Study) {
    println!("\n### {}\n\n{}.\n", s.name, s.about);
    println!(
        "Reference: {}; its errors: {}. Judged (the reference and its check agree to a tenth \
         of the targets): {} of {} samples, {} of {} transitions.\n",
        s.reference_label,
        Fmt(s.reference_errors),
        s.judged.sample_share().0,
        s.judged.sample_share().1,
        s.judged.transition_share().0,
        s.judged.transition_share().1
    );
    println!(
        "| method | h / rtol | steps | rejected | rhs | jac | CPU (s) | CPU per simulated s | depth | tilt | peak force | transitions (s) | end time (s) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for p in &s.points {
        let e = |v: f64| {
            if v.is_finite() {
                format!("{v:.1e}")
            } else {
                "differ".to_owned()
            }
        };
        println!(
            "| {} | {:e} | {} | {} | {} | {} | {:.3} | {:.3} | {} | {} | {} | {} | {} |",
            p.method.name(),
            p.setting,
            p.run.stats.steps,
            p.run.stats.rejected,
            p.run.stats.rhs_calls,
            p.run.stats.jacobian_calls,
            p.run.cpu_s,
            p.run.cpu_s / p.run.t_final,
            e(p.errors[0]),
            e(p.errors[1]),
            e(p.errors[2]),
            e(p.errors[3]),
            e(p.errors[4])
        );
    }
}

const METHODS: [MethodKind; 4] = [
    MethodKind::Rk4,
    MethodKind::Dopri5,
    MethodKind::Rodas3,
    MethodKind::Rodas4,
];

/// Five panels (depth, tilt, peak force, transition times, end time): error
/// against CPU time per method, the target and the reference's own error
/// as dashed lines; a panel where every run's error is zero is left out.
pub fn figure(s: &Study) -> Figure {
    let titles = [
        "depth, relative",
        "tilt, relative",
        "peak contact force, relative",
        "transition times [s]",
        "end time [s]",
    ];
    let mut fig = Figure::new();
    for (k, title) in titles.iter().enumerate() {
        let mut panel = Panel::new(
            &format!("{}: {title}", s.name),
            "CPU time per run [s]",
            "error",
        )
        .scales(Scale::Log, Scale::Log);
        let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
        for (color, method) in METHODS.iter().enumerate() {
            let mut pts: Vec<(f64, f64)> = s
                .points
                .iter()
                .filter(|p| p.method == *method && p.errors[k].is_finite() && p.errors[k] > 0.0)
                .map(|p| (p.run.cpu_s, p.errors[k]))
                .collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            for &(t, _) in &pts {
                (lo, hi) = (lo.min(t), hi.max(t));
            }
            if !pts.is_empty() {
                panel = panel.with(
                    Series::line(method.name(), pts)
                        .styled(Style::LineMarkers)
                        .colored(color),
                );
            }
        }
        if hi == 0.0 {
            // No run differs from the reference here (a drop's end time).
            continue;
        }
        panel = panel.with(
            Series::line("target", vec![(lo, TARGETS[k]), (hi, TARGETS[k])])
                .styled(Style::Dashed)
                .colored(4),
        );
        if s.reference_errors[k] > 0.0 && s.reference_errors[k].is_finite() {
            panel = panel.with(
                Series::line(
                    "reference error estimate",
                    vec![(lo, s.reference_errors[k]), (hi, s.reference_errors[k])],
                )
                .styled(Style::Dashed)
                .colored(7),
            );
        }
        fig.panels.push(panel);
    }
    fig
}

/// The five errors in short scientific notation.
struct Fmt([f64; 5]);

impl std::fmt::Display for Fmt {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [a, b, c, d, e] = self.0;
        write!(
            f,
            "depth {a:.1e}, tilt {b:.1e}, peak {c:.1e}, transitions {d:.1e} s, end {e:.1e} s"
        )
    }
}
