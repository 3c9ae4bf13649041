//! The `design_margins` scene as written ([`DesignScene`]), validated with
//! every grid point built ([`Design`]), and its grid runs ([`GridRun`]).

use serde::Deserialize;

use super::chamfer::{Capture, InitialError, Verdict};
use super::ranges;
use super::sensitivities::CaptureSensitivitiesTable;
use crate::compliant_peg_3d::outcome::Outcome;
use crate::error::{RunError, SceneError, SceneErrors};
use crate::scene::integrator::{DefaultMethod, IntegratorSpec};
use crate::scene::limits::try_with_capacity;
use crate::scene::progress::{Progress, par_map_counted};
use crate::scene::shared::compliant_peg_3d::insertion::{Built, RccScene, at_grid_point, run_one};
use crate::scene::shared::compliant_peg_3d::tables::{
    CriteriaTable, PegTable, RobotTable, WristTable,
};
use crate::scene::shared::replay::GridReplayTable;
use crate::scene::validate::Checker;

/// The `[grid]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridTable {
    /// Lateral errors of the compliance centre (m), along
    /// `robot.lateral_error_direction_deg`.
    pub centre_lateral_errors: Vec<f64>,
    /// Angular errors (degrees), towards `robot.tilt_direction_deg`.
    pub angular_errors_deg: Vec<f64>,
    /// Seat depth of the grid runs (m, default `criteria.seat_depth`).
    pub seat_depth: Option<f64>,
}

/// A `design_margins` scene as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DesignScene {
    /// `[peg]`.
    pub peg: PegTable,
    /// `[wrist]`.
    pub wrist: WristTable,
    /// `[robot]`: the nominal motion (its errors are the nominal run's).
    pub robot: RobotTable,
    /// `[criteria]`.
    pub criteria: CriteriaTable,
    /// `[grid]`.
    pub grid: GridTable,
    /// `[integrator]`.
    pub integrator: IntegratorSpec,
    /// `[replay]` (optional; the page shows the nominal run by default).
    #[serde(default)]
    pub replay: GridReplayTable,
    /// `[sensitivities]` (optional): the capture widths' derivatives.
    #[serde(default)]
    pub sensitivities: Option<CaptureSensitivitiesTable>,
}

/// One grid point: the robot's initial errors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    /// Lateral error of the compliance centre (m).
    pub centre_lateral: f64,
    /// Angular error (degrees).
    pub angular_deg: f64,
}

/// A validated `design_margins` scene.
#[derive(Debug, Clone)]
pub struct Design {
    /// The scene as written.
    pub scene: DesignScene,
    /// The nominal insertion (the `[robot]` table's errors).
    pub nominal: Built,
    /// Each grid point with its insertion.
    pub points: Vec<(Point, Built)>,
    /// The capture geometry.
    pub capture: Capture,
    /// The integrator, method resolved.
    pub integrator: IntegratorSpec,
    /// Why that method, for the description.
    pub method_reason: &'static str,
    /// The slots in [`super::sensitivities::FIELDS`] of the fields the
    /// `[sensitivities]` table names (None without the table).
    pub sensitivities: Option<Vec<usize>>,
}

/// One grid run.
#[derive(Debug, Clone, PartialEq)]
pub struct GridRun {
    /// The initial errors.
    pub point: Point,
    /// The capture rule's verdict.
    pub verdict: Verdict,
    /// How the run ended.
    pub outcome: Outcome,
    /// End time (s).
    pub end: f64,
    /// End depth of the tip (m).
    pub end_depth: f64,
    /// The contact pairs at the end, e.g. `rim_top`.
    pub end_contacts: String,
    /// Largest contact normal force over the output samples, the events
    /// and the final state (N).
    pub peak_contact: f64,
    /// Largest wrist force over the output samples, the events and the
    /// final state (N).
    pub peak_wrist: f64,
}

impl GridRun {
    /// True when the simulated peg seated.
    pub fn seated(&self) -> bool {
        self.outcome == Outcome::Seated
    }

    /// True when the capture rule and the simulation agree (accepted and
    /// seated, or rejected and not seated).
    pub fn agrees(&self) -> bool {
        self.verdict.accepts() == self.seated()
    }
}

impl DesignScene {
    /// The `insert_rcc` scene of grid point `p`: the tip's lateral error
    /// `e_c − L_c sin θ (cos ψ, sin ψ)` and the tilt `θ`, and the grid's
    /// seat depth.
    pub fn as_rcc(&self, p: &Point) -> RccScene {
        let dir = self.robot.lateral_error_direction_deg.to_radians();
        let az = self.robot.tilt_direction_deg.to_radians();
        let lever = self.wrist.centre_height * p.angular_deg.to_radians().sin();
        let tip = [
            p.centre_lateral * dir.cos() - lever * az.cos(),
            p.centre_lateral * dir.sin() - lever * az.sin(),
        ];
        let mut robot = self.robot.clone();
        // Signed along the error direction when the tip stays on its line.
        let along = tip[0] * dir.cos() + tip[1] * dir.sin();
        let across = -tip[0] * dir.sin() + tip[1] * dir.cos();
        if across.abs() <= 1e-12 * along.abs().max(1e-9) {
            robot.lateral_error = along;
        } else {
            robot.lateral_error = tip[0].hypot(tip[1]);
            robot.lateral_error_direction_deg = tip[1].atan2(tip[0]).to_degrees();
        }
        robot.angular_error_deg = p.angular_deg;
        let mut criteria = self.criteria.clone();
        if let Some(s) = self.grid.seat_depth {
            criteria.seat_depth = s;
        }
        RccScene {
            peg: self.peg.clone(),
            wrist: self.wrist.clone(),
            robot,
            criteria,
            integrator: self.integrator.clone(),
            replay: Default::default(),
            sensitivities: None,
        }
    }

    /// The nominal `insert_rcc` scene.
    pub fn nominal(&self) -> RccScene {
        RccScene {
            peg: self.peg.clone(),
            wrist: self.wrist.clone(),
            robot: self.robot.clone(),
            criteria: self.criteria.clone(),
            integrator: self.integrator.clone(),
            replay: Default::default(),
            sensitivities: None,
        }
    }

    /// Validates every table and builds every grid point: [`Self::checked`]
    /// then [`Checked::build`].
    ///
    /// # Errors
    /// Every invalid field, named (grid points by their list index).
    pub fn prepare(&self) -> Result<Design, SceneErrors> {
        self.checked()?.build()
    }

    /// Validates every table and the nominal insertion, building no grid
    /// point.
    ///
    /// # Errors
    /// Every invalid field, named (list entries by their index).
    pub fn checked(&self) -> Result<Checked, SceneErrors> {
        let nominal = self.nominal().build()?;
        let mut c = Checker::default();
        let g = &self.grid;
        for (name, list, range) in [
            (
                "centre_lateral_errors",
                &g.centre_lateral_errors,
                &ranges::CENTRE_LATERAL_ERRORS,
            ),
            (
                "angular_errors_deg",
                &g.angular_errors_deg,
                &ranges::ANGULAR_ERRORS,
            ),
        ] {
            if list.is_empty() {
                c.push(SceneError::invalid(
                    format!("grid.{name}"),
                    "[]",
                    "must list at least one value",
                ));
            }
            for (k, v) in list.iter().enumerate() {
                let field = format!("grid.{name}[{k}]");
                c.finite(&field, *v);
                range.check_as(&mut c, &field, *v);
            }
            c.distinct(&format!("grid.{name}"), list);
        }
        if let Some(s) = g.seat_depth {
            c.finite("grid.seat_depth", s);
            ranges::SEAT_DEPTH.check(&mut c, s);
            let bore = nominal.params.bore_depth;
            if s.is_finite() && s >= 0.999 * bore {
                c.push(SceneError::invalid(
                    "grid.seat_depth",
                    s,
                    format!("must be below 0.999 peg.bore_depth = {:e} m", 0.999 * bore),
                ));
            }
        }
        let sensitivities = match self
            .sensitivities
            .as_ref()
            .map(CaptureSensitivitiesTable::chosen)
        {
            Some(Ok(chosen)) => Some(chosen),
            Some(Err(e)) => {
                c.extend(Err(e));
                None
            }
            None => None,
        };
        if let Some(run) = self.replay.run {
            let points = g.centre_lateral_errors.len() * g.angular_errors_deg.len();
            if let Err(e) = run.check(points) {
                c.push(e);
            }
        }
        c.finish()?;
        Ok(Checked {
            scene: self.clone(),
            nominal,
            sensitivities,
        })
    }
}

/// A `design_margins` scene whose tables and nominal insertion are
/// valid, its grid not yet built.
#[derive(Debug, Clone)]
pub struct Checked {
    /// The scene as written.
    pub scene: DesignScene,
    /// The nominal insertion.
    pub nominal: Built,
    /// The slots of the `[sensitivities]` table's fields, as
    /// [`Design::sensitivities`].
    pub sensitivities: Option<Vec<usize>>,
}

impl Checked {
    /// The number of grid points, from the lists' lengths.
    pub fn grid_points(&self) -> f64 {
        let g = &self.scene.grid;
        g.centre_lateral_errors.len() as f64 * g.angular_errors_deg.len() as f64
    }

    /// Builds every grid point's insertion.
    ///
    /// # Errors
    /// A grid point whose tip error leaves the robot's range (naming the
    /// list entry), or the memory for the points cannot be reserved.
    pub fn build(self) -> Result<Design, SceneErrors> {
        let Checked {
            scene,
            nominal,
            sensitivities,
        } = self;
        let n = scene.grid.centre_lateral_errors.len() * scene.grid.angular_errors_deg.len();
        let mut points = try_with_capacity(n, "grid points", "max_runs")
            .map_err(|e| SceneErrors::from(SceneError::invalid("grid", n, e.to_string())))?;
        let (g, d) = (&scene.grid, nominal.params.hole_diameter);
        let mut c = Checker::default();
        for (i, &centre_lateral) in g.centre_lateral_errors.iter().enumerate() {
            for (j, &angular_deg) in g.angular_errors_deg.iter().enumerate() {
                let p = Point {
                    centre_lateral,
                    angular_deg,
                };
                let rcc = scene.as_rcc(&p);
                // The robot accepts tip errors within ±2 D: name the grid
                // entry that leads there.
                if rcc.robot.lateral_error.abs() > 2.0 * d {
                    c.push(SceneError::invalid(
                        format!("grid.centre_lateral_errors[{i}]"),
                        centre_lateral,
                        format!(
                            "with angular error {angular_deg} deg the tip's error e_c - L_c sin(theta) \
                             is {:e} m, beyond 2 peg.hole_diameter",
                            rcc.robot.lateral_error
                        ),
                    ));
                    continue;
                }
                match rcc.build() {
                    Ok(built) => points.push((p, built)),
                    Err(e) => {
                        let (lateral, angular) = (
                            format!("grid.centre_lateral_errors[{i}]"),
                            format!("grid.angular_errors_deg[{j}]"),
                        );
                        at_grid_point(
                            e,
                            &[
                                (lateral.clone(), centre_lateral),
                                (angular.clone(), angular_deg),
                            ],
                            &[
                                ("robot.lateral_error", &lateral, centre_lateral),
                                ("robot.angular_error_deg", &angular, angular_deg),
                            ],
                            &mut c,
                        );
                    }
                }
            }
        }
        c.finish()?;
        let prm = &nominal.params;
        let capture = Capture {
            peg_radius: prm.peg_radius(),
            bore_radius: prm.bore_radius(),
            rim_fillet: prm.rim_fillet,
            mouth_fillet: prm.mouth_fillet,
            friction: prm.friction,
            centre_height: nominal.held.wrist.centre_height,
        };
        let (integrator, method_reason) = scene.integrator.resolved(DefaultMethod::NON_STIFF);
        Ok(Design {
            scene,
            nominal,
            points,
            capture,
            integrator,
            method_reason,
            sensitivities,
        })
    }
}

impl Design {
    /// The capture rule at grid point `p`.
    pub fn verdict(&self, p: &Point) -> Verdict {
        let dir = self.scene.robot.lateral_error_direction_deg.to_radians();
        self.capture.verdict(&InitialError {
            centre: [p.centre_lateral * dir.cos(), p.centre_lateral * dir.sin()],
            tilt: p.angular_deg.to_radians(),
            azimuth: self.scene.robot.tilt_direction_deg.to_radians(),
        })
    }

    /// Runs every grid point in parallel, reporting each finished run to
    /// `progress`.
    ///
    /// # Errors
    /// The first run's integrator refusal or Hertz setup error.
    pub fn run_grid(&self, progress: &mut Progress) -> Result<Vec<GridRun>, RunError> {
        par_map_counted(&self.points, progress, "insertion", |(p, b)| {
            self.one(*p, b)
        })?
        .into_iter()
        .collect()
    }

    fn one(&self, p: Point, b: &Built) -> Result<GridRun, RunError> {
        let run = run_one(b, &self.integrator, false, &mut Progress::silent())?;
        let peaks = run.peaks()?;
        let end = run
            .system
            .sample(run.solution.t_final, &run.solution.x_final)?;
        let mut pairs: Vec<&str> = end.forces.iter().map(|f| f.contact.pair.name()).collect();
        pairs.dedup();
        Ok(GridRun {
            point: p,
            verdict: self.verdict(&p),
            outcome: run.outcome,
            end: run.solution.t_final,
            end_depth: end.depth,
            end_contacts: pairs.join(" "),
            peak_contact: peaks.contact,
            peak_wrist: peaks.wrist_force,
        })
    }
}
