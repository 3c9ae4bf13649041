//! Scene kind `pendulum`: a simple (point-mass, massless-rod) pendulum
//! released at an angle, `θ̈ = −(g/L) sin θ`, with `θ` measured from the
//! downward vertical. A textbook check of the generator and integrators:
//! the total energy `E = ½ m L² θ̇² − m g L cos θ` must stay constant.
//!
//! Outputs: `<name>.csv` (`t_s, theta_rad, omega_rad_s, energy_J,
//! energy_error` with `energy_error = (E − E₀)/(m g L)`) and `<name>.svg`.
//! The energy error is evaluated at the output times, that is on the
//! integrator's dense output (4th order for DOPRI5, cubic Hermite for
//! RODAS3), whose interpolation error shows as spikes between steps. The
//! summary also compares the period measured from the upward zero
//! crossings of `θ` (located by events) with the exact period
//! (`textbook::pendulum::exact_period`).
//!
//! ```toml
//! kind = "pendulum"
//! [pendulum]
//! length = 1.0       # L, m
//! mass = 1.0         # m, kg
//! gravity = 9.81     # g, m/s² (default 9.81)
//! theta0_deg = 60.0  # initial angle, degrees from the downward vertical
//! omega0 = 0.0       # initial angular velocity, rad/s (default 0)
//! [integrator]
//! method = "dopri5"
//! t_end = 10.0
//! ```

use nalgebra::{SVector, Vector2};
use serde::Deserialize;

use crate::error::{RunError, SceneErrors};
use crate::integrate::{Direction, Event};
use crate::output::decimate::{Decimate, PLOT_POINTS};
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series};
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::limits::sample_count;
use crate::scene::simulate::{integrate_streaming, integration_summary};
use crate::scene::summary::{Metric, RunSummary};
use crate::scene::validate::Checker;
pub use crate::textbook::pendulum::PendulumParams;
use crate::textbook::pendulum::{PendulumSystem, exact_period};

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "pendulum",
    about: "simple pendulum released at an angle (textbook check)",
    parse,
    ranges: &[crate::scene::shared::pendulum::PENDULUM],
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: PendulumScene = doc.body()?;
    s.check()?;
    Ok(Box::new(s))
}

/// A `pendulum` scene.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PendulumScene {
    /// Physical parameters and initial state.
    pub pendulum: PendulumParams,
    /// Integration settings.
    pub integrator: IntegratorSpec,
}

impl PendulumScene {
    /// Validates every field, reporting all problems.
    pub fn check(&self) -> Result<(), SceneErrors> {
        let p = &self.pendulum;
        let mut c = Checker::default();
        c.positive("pendulum.length", p.length);
        c.positive("pendulum.mass", p.mass);
        c.positive("pendulum.gravity", p.gravity);
        c.in_range("pendulum.theta0_deg", p.theta0_deg, -180.0, 180.0);
        c.finite("pendulum.omega0", p.omega0);
        {
            use crate::scene::shared::pendulum::{PENDULUM, check_all, check_spin};
            check_all(&mut c, PENDULUM, &[p.length, p.mass, p.gravity]);
            check_spin(&mut c, "pendulum.omega0", p.omega0, p.length, p.gravity);
        }
        c.extend(self.integrator.check("integrator"));
        c.finish()
    }
}

impl Written for PendulumScene {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        self.integrator.work("integrator")
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        Ok(self)
    }
}

impl Scene for PendulumScene {
    fn time_scales(&self) -> Option<crate::scene::TimeScales> {
        use crate::scene::{TimeScale, TimeScales, significant};
        let p = &self.pendulum;
        let mut scales = vec![TimeScale::new(
            "the small-swing period 2 pi sqrt(L/g)",
            format!(
                "pendulum.length = {} m, pendulum.gravity = {} m/s^2",
                significant(p.length),
                significant(p.gravity)
            ),
            std::f64::consts::TAU * (p.length / p.gravity).sqrt(),
        )];
        if p.omega0 != 0.0 {
            scales.push(TimeScale::new(
                "a turn at the initial rate, 2 pi / omega0",
                format!("pendulum.omega0 = {} rad/s", significant(p.omega0)),
                std::f64::consts::TAU / p.omega0.abs(),
            ));
        }
        Some(TimeScales::new(&self.integrator, scales))
    }

    fn describe(&self) -> String {
        let p = &self.pendulum;
        format!(
            "simple pendulum L = {} m, m = {} kg, g = {} m/s², released at {}° with {} rad/s; {}",
            crate::scene::numbers::significant(p.length),
            crate::scene::numbers::significant(p.mass),
            crate::scene::numbers::significant(p.gravity),
            crate::scene::numbers::significant(p.theta0_deg),
            crate::scene::numbers::significant(p.omega0),
            self.integrator.describe()
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let p = &self.pendulum;
        let system = PendulumSystem::new(p);
        let x0 = Vector2::new(p.theta0_deg.to_radians(), p.omega0);
        // θ rising through zero: once per period of a libration.
        let events = vec![Event::new(|_t, x: &SVector<f64, 2>| x[0]).direction(Direction::Rising)];
        // Energy error relative to m g L, the energy scale of the problem
        // (E0 itself may be zero).
        let e0 = system.energy(&x0);
        let scale = p.mass * p.gravity * p.length;
        let mut csv = ctx.table(
            Part::Main,
            &[
                "t_s",
                "theta_rad",
                "omega_rad_s",
                "energy_J",
                "energy_error",
            ],
        )?;
        // Every sample streams to the CSV; the plots keep a decimated copy
        // (and the last sample).
        let spec = &self.integrator;
        let mut keep = Decimate::new(
            sample_count(spec.t0, spec.t_end, spec.output_interval()),
            PLOT_POINTS,
        );
        let (mut theta, mut err) = (Vec::new(), Vec::new());
        let mut last = None;
        let mut drift: f64 = 0.0;
        let sink = |t: f64, x: &SVector<f64, 2>| -> Result<(), RunError> {
            let e = system.energy(x);
            let rel = (e - e0) / scale;
            drift = drift.max(rel.abs());
            csv.row(&[t, x[0], x[1], e, rel])?;
            if keep.keep() {
                theta.push((t, x[0]));
                err.push((t, rel));
                last = None;
            } else {
                last = Some(((t, x[0]), (t, rel)));
            }
            Ok(())
        };
        let sol = integrate_streaming(&system, x0, spec, events, &mut ctx.progress, sink)?;
        if let Some((a, b)) = last {
            theta.push(a);
            err.push(b);
        }
        csv.finish()?;
        let mut fig = Figure::new();
        fig.panels.push(
            Panel::new("Simple pendulum: angle", "t [s]", "θ [rad]").with(Series::line("θ", theta)),
        );
        fig.panels.push(
            Panel::new("Energy error", "t [s]", "(E − E₀)/(m g L) [-]").with(Series::line(
                self.integrator
                    .resolved(crate::scene::integrator::DefaultMethod::NON_STIFF)
                    .0
                    .method
                    .name(),
                err,
            )),
        );
        ctx.figure(Part::Main, &fig)?;

        let mut out = RunSummary {
            integration: Some(integration_summary(
                &self.integrator,
                &sol,
                &["theta_zero_rising"],
            )),
            ..RunSummary::default()
        };
        out.metrics
            .push(Metric::new("max |E - E0| / (m g L)", drift, ""));
        let crossings: Vec<f64> = sol.events.iter().map(|e| e.t).collect();
        if let [first, .., last] = crossings[..] {
            let measured = (last - first) / (crossings.len() - 1) as f64;
            out.metrics
                .push(Metric::new("period (measured)", measured, "s"));
            if let Some(exact) = exact_period(p) {
                out.metrics.push(Metric::new("period (exact)", exact, "s"));
                out.metrics.push(Metric::new(
                    "period relative error",
                    (measured - exact).abs() / exact,
                    "",
                ));
            }
        }
        Ok(out)
    }
}
