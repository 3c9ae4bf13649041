//! Scene kind `rotation_assist`: the `insert_rcc` insertion over a grid of
//! lateral × angular errors, at several precession rates `ψ̇` and spin
//! rates `φ̇` (0 included): does rotating the peg help it in? Runs in
//! parallel (rayon) with a progress line.
//!
//! The `[peg]`, `[wrist]`, `[robot]`, `[criteria]` and `[integrator]`
//! tables are those of `insert_rcc` (the robot's errors and rates are
//! replaced by the grid's); `[grid]`:
//!
//! ```toml
//! [grid]
//! lateral_errors = [0.0, 2e-4]          # m
//! angular_errors_deg = [0.5, 1.5]
//! precession_rates = [0.0, 20.0]        # rad/s
//! spin_rates = [0.0, 20.0]              # rad/s
//! yield_pressure = 1.5e9                # Pa, the stated yield for p0
//! ```
//!
//! Writes `<name>.csv` (`lateral_error_m, angular_error_deg,
//! precession_rate, spin_rate, outcome, outcome_code, end_time_s,
//! insertion_time_s, peak_contact_N, peak_pressure_Pa, pressure_over_yield,
//! peak_wrist_moment_Nm, peak_wrist_force_N`; `insertion_time_s` is the end
//! time of seated runs, else empty) and `<name>.svg`: per rotation pair,
//! the outcome and the peak contact force over the error grid.
//!
//! An optional `[sensitivities]` table (the fields of `insert_rcc`'s,
//! [`crate::scene::shared::compliant_peg_3d::design::FIELDS`], the grid's
//! own axes among them: `robot.lateral_error`, `robot.angular_error_deg`,
//! `robot.precession_rate`, `robot.spin_rate`) adds every grid point's
//! derivatives of the insertion's metrics
//! ([`crate::scene::kinds::insert_rcc::sensitivities`]): `<name>.sensitivities.csv`
//! (`lateral_error_m, angular_error_deg, precession_rate, spin_rate,
//! metric, parameter, value, derivative, elasticity, flag`, a row per
//! point, metric and field).

pub(crate) mod figure;
pub mod grid;

use serde::Deserialize;

use crate::error::{RunError, SceneErrors};
use crate::output::csv::format_f64;
use crate::output::names::Part;
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::integrator::DefaultMethod;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::kinds::insert_rcc::sensitivities;
use crate::scene::limits::{WorkItem, try_with_capacity};
use crate::scene::progress::{Progress, par_map_counted};
use crate::scene::shared::compliant_peg_3d::insertion::{
    Built, RccScene, at_grid_point, outcome_text, run_one,
};
use crate::scene::shared::compliant_peg_3d::{ranges, replay, tables};
use crate::scene::shared::replay::{GridReplayTable, RunChoice};
use crate::scene::shared::sensitivities::{
    Row as SensitivityRow, SensitivitiesTable, output as sensitivities_output,
};
use crate::scene::summary::{Metric, RunSummary};
use crate::scene::validate::Checker;
use grid::{ANGULAR_ERRORS, LATERAL_ERRORS, PRECESSION_RATES, SPIN_RATES, YIELD_PRESSURE};

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "rotation_assist",
    about: "compliant 3-D peg insertions over errors x precession x spin: does rotation help?",
    parse,
    ranges: &[
        ranges::PEG,
        ranges::WRIST,
        ranges::ROBOT,
        ranges::CRITERIA,
        grid::GRID,
    ],
};

/// The `[grid]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridTable {
    /// Lateral errors (m).
    pub lateral_errors: Vec<f64>,
    /// Angular errors (degrees).
    pub angular_errors_deg: Vec<f64>,
    /// Precession rates `ψ̇` (rad/s).
    pub precession_rates: Vec<f64>,
    /// Spin rates `φ̇` (rad/s).
    pub spin_rates: Vec<f64>,
    /// The yield pressure the peak Hertz pressure is compared with (Pa).
    pub yield_pressure: f64,
}

/// A `rotation_assist` scene as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepScene {
    /// `[peg]`.
    pub peg: tables::PegTable,
    /// `[wrist]`.
    pub wrist: tables::WristTable,
    /// `[robot]`: the base motion.
    pub robot: tables::RobotTable,
    /// `[criteria]`.
    pub criteria: tables::CriteriaTable,
    /// `[grid]`.
    pub grid: GridTable,
    /// `[integrator]`.
    pub integrator: IntegratorSpec,
    /// `[replay]` (optional; the page shows the worst run by default).
    #[serde(default)]
    pub replay: GridReplayTable,
    /// `[sensitivities]` (optional): derivatives at every grid point.
    #[serde(default)]
    pub sensitivities: Option<SensitivitiesTable>,
}

/// One grid point.
#[derive(Debug, Clone, Copy)]
#[doc(hidden)]
pub struct Point {
    /// The robot's lateral error, m.
    pub lateral: f64,
    /// The robot's angular error, degrees.
    pub angular_deg: f64,
    /// The precession rate `ψ̇`, rad/s.
    pub precession: f64,
    /// The spin rate `φ̇`, rad/s.
    pub spin: f64,
}

#[derive(Debug)]
struct Ready {
    scene: SweepScene,
    points: Vec<(Point, Built)>,
    /// The `[robot]` table's own run, when `replay.run = "nominal"`.
    nominal: Option<Built>,
    integrator: IntegratorSpec,
    method_reason: &'static str,
    /// The fields of the `[sensitivities]` table (indices into
    /// [`crate::scene::shared::compliant_peg_3d::design::FIELDS`]), empty
    /// without one.
    sensitivities: Vec<usize>,
}

impl SweepScene {
    fn as_rcc(&self, p: &Point) -> RccScene {
        let mut robot = self.robot.clone();
        robot.lateral_error = p.lateral;
        robot.angular_error_deg = p.angular_deg;
        robot.precession_rate = p.precession;
        robot.spin_rate = p.spin;
        RccScene {
            peg: self.peg.clone(),
            wrist: self.wrist.clone(),
            robot,
            criteria: self.criteria.clone(),
            integrator: self.integrator.clone(),
            replay: Default::default(),
            // Its error control is the sensitivity runs'.
            sensitivities: self.sensitivities.clone(),
        }
    }
}

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: SweepScene = doc.body()?;
    let mut c = Checker::default();
    let g = &s.grid;
    // The shared tables first, so that a bad peg is named as such and not
    // through the ranges it narrows.
    let _ = s.peg.build(&mut c);
    // Each entry against the robot's range of the field it replaces, named
    // as the grid entry (the bore's D narrows the lateral range, once it is
    // valid itself).
    let d = if ranges::HOLE_DIAMETER.contains(s.peg.hole_diameter) {
        s.peg.hole_diameter
    } else {
        f64::NAN
    };
    for (range, list) in [
        (LATERAL_ERRORS.within(-2.0 * d, 2.0 * d), &g.lateral_errors),
        (ANGULAR_ERRORS, &g.angular_errors_deg),
        (PRECESSION_RATES, &g.precession_rates),
        (SPIN_RATES, &g.spin_rates),
    ] {
        if list.is_empty() {
            c.push(crate::error::SceneError::invalid(
                range.field,
                "[]",
                "must list at least one value",
            ));
        }
        for (k, v) in list.iter().enumerate() {
            let field = format!("{}[{k}]", range.field);
            c.finite(&field, *v);
            range.check_as(&mut c, &field, *v);
        }
        c.distinct(range.field, list);
    }
    YIELD_PRESSURE.require(&mut c, g.yield_pressure);
    // The robot's own errors and rates, which the grid replaces, are values
    // of the scene all the same: finite and in their ranges.
    let r = &s.robot;
    ranges::LATERAL_ERROR
        .within(-2.0 * d, 2.0 * d)
        .require(&mut c, r.lateral_error);
    ranges::ANGULAR_ERROR.require(&mut c, r.angular_error_deg);
    ranges::PRECESSION_RATE.require(&mut c, r.precession_rate);
    ranges::SPIN_RATE.require(&mut c, r.spin_rate);
    // The integrator's span sets the work estimate: checked before it.
    c.extend(s.integrator.check("integrator"));
    if let Some(run) = s.replay.run {
        // A product of list lengths past `usize` saturates: every index is then in range.
        if let Err(e) = run.check(s.grid_points() as usize) {
            c.push(e);
        }
    }
    c.finish()?;
    Ok(Box::new(s))
}

impl SweepScene {
    /// The number of grid points, from the lists' lengths (as f64: a
    /// product of four lengths may not fit a `usize`).
    fn grid_points(&self) -> f64 {
        let g = &self.grid;
        [
            g.lateral_errors.len(),
            g.angular_errors_deg.len(),
            g.precession_rates.len(),
            g.spin_rates.len(),
        ]
        .iter()
        .map(|&n| n as f64)
        .product()
    }
}

impl Written for SweepScene {
    fn work(&self) -> Vec<WorkItem> {
        let mut w = self.integrator.work("integrator");
        if let Some(t) = &self.sensitivities {
            w.extend(sensitivities::work(&self.integrator, t.parameters.len()));
        }
        // Every point's insertion is built before the runs start, and
        // every run keeps its row.
        let each = std::mem::size_of::<(Point, Built)>() + std::mem::size_of::<Row>();
        w.push(WorkItem::new(
            "grid",
            "max_runs",
            self.grid_points(),
            each as f64,
        ));
        w
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        let s = *self;
        let g = &s.grid;
        let n = s.grid_points();
        let mut points = try_with_capacity(n as usize, "grid points", "max_runs").map_err(|e| {
            SceneErrors::from(crate::error::SceneError::invalid("grid", n, e.to_string()))
        })?;
        // Each point's refusals named as the grid's entries.
        let mut c = Checker::default();
        for (i, &lateral) in g.lateral_errors.iter().enumerate() {
            for (j, &angular_deg) in g.angular_errors_deg.iter().enumerate() {
                for (k, &precession) in g.precession_rates.iter().enumerate() {
                    for (l, &spin) in g.spin_rates.iter().enumerate() {
                        let p = Point {
                            lateral,
                            angular_deg,
                            precession,
                            spin,
                        };
                        match s.as_rcc(&p).build() {
                            Ok(built) => points.push((p, built)),
                            Err(e) => grid_point_errors(e, &p, [i, j, k, l], &mut c),
                        }
                    }
                }
            }
        }
        c.finish()?;
        // The table's fields, checked against the first point's model (the
        // grid moves no field that the check reads).
        let chosen = match (&s.sensitivities, points.first()) {
            (Some(t), Some((_, b))) => sensitivities::check(t, b)?,
            _ => Vec::new(),
        };
        let nominal = match s.replay.run {
            Some(RunChoice::Nominal) => {
                let r = &s.robot;
                let p = Point {
                    lateral: r.lateral_error,
                    angular_deg: r.angular_error_deg,
                    precession: r.precession_rate,
                    spin: r.spin_rate,
                };
                Some(s.as_rcc(&p).build()?)
            }
            _ => None,
        };
        let (integrator, method_reason) = s.integrator.resolved(DefaultMethod::NON_STIFF);
        Ok(Box::new(Ready {
            scene: s,
            points,
            nominal,
            integrator,
            method_reason,
            sensitivities: chosen,
        }))
    }
}

/// The errors of the grid point `p` at list indices `at` (lateral,
/// angular, precession, spin) named as the grid's entries, not as the
/// robot fields they replace.
fn grid_point_errors(e: SceneErrors, p: &Point, at: [usize; 4], c: &mut Checker) {
    let [i, j, k, l] = at;
    let names = [
        format!("grid.lateral_errors[{i}]"),
        format!("grid.precession_rates[{k}]"),
        format!("grid.spin_rates[{l}]"),
        format!("grid.angular_errors_deg[{j}]"),
    ];
    let point = [
        (names[0].clone(), p.lateral),
        (names[1].clone(), p.precession),
        (names[2].clone(), p.spin),
        (names[3].clone(), p.angular_deg),
    ];
    let renames = [
        ("robot.lateral_error", names[0].as_str(), p.lateral),
        ("robot.precession_rate", names[1].as_str(), p.precession),
        ("robot.spin_rate", names[2].as_str(), p.spin),
        ("robot.angular_error_deg", names[3].as_str(), p.angular_deg),
    ];
    at_grid_point(e, &point, &renames, c);
}

/// One run's row.
#[derive(Debug, Clone)]
#[doc(hidden)]
pub struct Row {
    /// The grid point run.
    pub point: Point,
    /// The outcome's name.
    pub outcome: String,
    /// The outcome's code (`outcome_code` of the table).
    pub code: f64,
    /// The run's end time, s.
    pub end: f64,
    /// Whether the peg seated.
    pub seated: bool,
    /// The peak contact force, N.
    pub peak_contact: f64,
    /// The peak contact pressure, Pa.
    pub peak_pressure: f64,
    /// The peak wrist moment, N m.
    pub peak_moment: f64,
    /// The peak wrist force, N.
    pub peak_wrist: f64,
}

/// One grid point's run, and its sensitivity rows for the fields `chosen`
/// (none when empty).
fn one(
    scene: &SweepScene,
    (p, b): (Point, &Built),
    spec: &IntegratorSpec,
    chosen: &[usize],
) -> Result<(Row, Vec<SensitivityRow>), RunError> {
    let mut silent = Progress::silent();
    let run = run_one(b, spec, false, &mut silent)?;
    let peaks = run.peaks()?;
    let derivatives = if chosen.is_empty() {
        Vec::new()
    } else {
        sensitivities::compute(&scene.as_rcc(&p), b, spec, chosen)?.0
    };
    let row = Row {
        point: p,
        outcome: outcome_text(&run.outcome),
        code: run.outcome.code(),
        end: run.solution.t_final,
        seated: run.outcome == crate::compliant_peg_3d::outcome::Outcome::Seated,
        peak_contact: peaks.contact,
        peak_pressure: peaks.pressure,
        peak_moment: peaks.wrist_moment,
        peak_wrist: peaks.wrist_force,
    };
    Ok((row, derivatives))
}

impl Scene for Ready {
    fn describe(&self) -> String {
        format!(
            "rotation assist: {} insertions ({} lateral x {} angular errors x {} precession x {} \
             spin rates); {} ({})",
            self.points.len(),
            self.scene.grid.lateral_errors.len(),
            self.scene.grid.angular_errors_deg.len(),
            self.scene.grid.precession_rates.len(),
            self.scene.grid.spin_rates.len(),
            self.integrator.describe(),
            self.method_reason
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let runs = par_map_counted(&self.points, &mut ctx.progress, "insertion", |(p, b)| {
            one(&self.scene, (*p, b), &self.integrator, &self.sensitivities)
        })?;
        let runs: Vec<(Row, Vec<SensitivityRow>)> = runs.into_iter().collect::<Result<_, _>>()?;
        let (rows, derivatives): (Vec<Row>, Vec<Vec<SensitivityRow>>) = runs.into_iter().unzip();
        let yield_p = self.scene.grid.yield_pressure;
        let mut csv = ctx.table(
            Part::Main,
            &[
                "lateral_error_m",
                "angular_error_deg",
                "precession_rate",
                "spin_rate",
                "outcome",
                "outcome_code",
                "end_time_s",
                "insertion_time_s",
                "peak_contact_N",
                "peak_pressure_Pa",
                "pressure_over_yield",
                "peak_wrist_moment_Nm",
                "peak_wrist_force_N",
            ],
        )?;
        for r in &rows {
            csv.row_cells(&[
                &format_f64(r.point.lateral),
                &format_f64(r.point.angular_deg),
                &format_f64(r.point.precession),
                &format_f64(r.point.spin),
                &r.outcome,
                &format_f64(r.code),
                &format_f64(r.end),
                &if r.seated {
                    format_f64(r.end)
                } else {
                    String::new()
                },
                &format_f64(r.peak_contact),
                &format_f64(r.peak_pressure),
                &format_f64(r.peak_pressure / yield_p),
                &format_f64(r.peak_moment),
                &format_f64(r.peak_wrist),
            ])?;
        }
        csv.finish()?;
        ctx.figure(Part::Main, &figure::heat_maps(&rows))?;
        let mut out = RunSummary::default();
        if !self.sensitivities.is_empty() {
            out.metrics
                .extend(write_sensitivities(ctx, &rows, &derivatives)?);
        }
        let seated = rows.iter().filter(|r| r.seated).count();
        out.metrics.push(Metric::new("runs", rows.len() as f64, ""));
        out.metrics.push(Metric::new("seated", seated as f64, ""));
        for (pr, sr) in rate_pairs(&rows) {
            let sel: Vec<&Row> = rows
                .iter()
                .filter(|r| r.point.precession == pr && r.point.spin == sr)
                .collect();
            let seated: Vec<&&Row> = sel.iter().filter(|r| r.seated).collect();
            let peak = sel.iter().map(|r| r.peak_contact).fold(0.0, f64::max);
            let tag = format!("psidot {pr} rad/s, phidot {sr} rad/s");
            out.metrics.push(Metric::new(
                format!("{tag}: seated of {}", sel.len()),
                seated.len() as f64,
                "",
            ));
            // A mean over no seated run is not a time: left out.
            if !seated.is_empty() {
                let mean_t = seated.iter().map(|r| r.end).sum::<f64>() / seated.len() as f64;
                out.metrics.push(Metric::new(
                    format!("{tag}: mean insertion time"),
                    mean_t,
                    "s",
                ));
            }
            out.metrics
                .push(Metric::new(format!("{tag}: peak contact force"), peak, "N"));
        }
        let pmax = rows.iter().map(|r| r.peak_pressure).fold(0.0, f64::max);
        out.metrics.push(Metric::new(
            "peak Hertz pressure / yield",
            pmax / yield_p,
            "",
        ));
        if self.scene.replay.wanted(ctx) {
            let outcomes: Vec<(bool, f64)> = rows.iter().map(|r| (r.seated, r.end)).collect();
            let describe = |p: &Point| {
                format!(
                    "lateral error {} m, angular error {} deg, precession {} rad/s, spin {} rad/s",
                    p.lateral, p.angular_deg, p.precession, p.spin
                )
            };
            let spec = &self.integrator;
            let nominal = || {
                let run = |b| run_one(b, spec, true, &mut Progress::silent());
                self.nominal.as_ref().map(run).transpose()
            };
            let choice = self.scene.replay.run.unwrap_or(RunChoice::Worst);
            replay::write_grid(
                ctx,
                choice,
                &outcomes,
                &self.points,
                describe,
                spec,
                nominal,
            )?;
        }
        Ok(out)
    }
}

/// Writes every grid point's sensitivity rows (`<name>.sensitivities.csv`,
/// the point's coordinates first) and returns the summary's note: rows,
/// and how many are flagged.
fn write_sensitivities(
    ctx: &RunContext,
    rows: &[Row],
    derivatives: &[Vec<SensitivityRow>],
) -> Result<Vec<Metric>, RunError> {
    let mut header = vec![
        "lateral_error_m",
        "angular_error_deg",
        "precession_rate",
        "spin_rate",
    ];
    header.extend(sensitivities_output::HEADER);
    let mut csv = ctx.table(Part::Sub("sensitivities"), &header)?;
    let (mut written, mut flagged) = (0_usize, 0_usize);
    for (r, ds) in rows.iter().zip(derivatives) {
        let p = &r.point;
        let at = [p.lateral, p.angular_deg, p.precession, p.spin].map(format_f64);
        for d in ds {
            let cells = sensitivities_output::cells(d);
            let row: Vec<&str> = at.iter().chain(&cells).map(String::as_str).collect();
            csv.row_cells(&row)?;
            written += 1;
            flagged += usize::from(d.derivative.is_none());
        }
    }
    csv.finish()?;
    Ok(vec![Metric::note(
        "sensitivities",
        format!(
            "{written} rows over {} grid points, {flagged} without a derivative (see the flag \
             column of the CSV)",
            rows.len()
        ),
    )])
}

#[doc(hidden)]
pub fn rate_pairs(rows: &[Row]) -> Vec<(f64, f64)> {
    let mut pairs: Vec<(f64, f64)> = Vec::new();
    for r in rows {
        let k = (r.point.precession, r.point.spin);
        if !pairs.contains(&k) {
            pairs.push(k);
        }
    }
    pairs
}
