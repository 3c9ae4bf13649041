//! Scene kind `double_pendulum`: two point masses on massless rods in a
//! vertical plane, angles `θ₁`, `θ₂` from the downward vertical. Chaotic for
//! large initial angles; its total energy (J) must stay constant:
//!
//! ```text
//! E = ½(m₁+m₂)l₁²θ̇₁² + ½m₂l₂²θ̇₂² + m₂l₁l₂θ̇₁θ̇₂cos(θ₁−θ₂)
//!     − (m₁+m₂)g l₁cos θ₁ − m₂ g l₂ cos θ₂
//! ```
//!
//! Outputs: `<name>.csv` (`t_s, theta1_rad, theta2_rad, omega1_rad_s,
//! omega2_rad_s, energy_J, energy_error`, the error relative to
//! `(m₁+m₂) g l₁ + m₂ g l₂`) and `<name>.svg` (angles, path of the lower
//! bob, energy error). As for the `pendulum` scene, the energy error is
//! taken on the dense output at the output times.
//!
//! ```toml
//! kind = "double_pendulum"
//! [double_pendulum]
//! mass1 = 1.0          # kg
//! mass2 = 1.0          # kg
//! length1 = 1.0        # m
//! length2 = 1.0        # m
//! gravity = 9.80665    # m/s² (default)
//! theta1_deg = 120.0   # degrees from the downward vertical
//! theta2_deg = -10.0
//! omega1 = 0.0         # rad/s (default 0)
//! omega2 = 0.0
//! [integrator]
//! method = "dopri5"
//! t_end = 20.0
//! ```

use nalgebra::Vector4;
use serde::Deserialize;

use crate::error::{RunError, SceneErrors};
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
pub use crate::textbook::double_pendulum::DoublePendulumParams;
use crate::textbook::double_pendulum::DoublePendulumSystem;

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "double_pendulum",
    about: "planar double pendulum (textbook check, chaotic)",
    parse,
    ranges: &[crate::scene::shared::pendulum::DOUBLE_PENDULUM],
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: DoublePendulumScene = doc.body()?;
    s.check()?;
    Ok(Box::new(s))
}

/// A `double_pendulum` scene.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DoublePendulumScene {
    /// Physical parameters and initial state.
    pub double_pendulum: DoublePendulumParams,
    /// Integration settings.
    pub integrator: IntegratorSpec,
}

impl DoublePendulumScene {
    /// Validates every field, reporting all problems.
    pub fn check(&self) -> Result<(), SceneErrors> {
        let p = &self.double_pendulum;
        let mut c = Checker::default();
        c.positive("double_pendulum.mass1", p.mass1);
        c.positive("double_pendulum.mass2", p.mass2);
        c.positive("double_pendulum.length1", p.length1);
        c.positive("double_pendulum.length2", p.length2);
        c.positive("double_pendulum.gravity", p.gravity);
        c.in_range("double_pendulum.theta1_deg", p.theta1_deg, -180.0, 180.0);
        c.in_range("double_pendulum.theta2_deg", p.theta2_deg, -180.0, 180.0);
        c.finite("double_pendulum.omega1", p.omega1);
        c.finite("double_pendulum.omega2", p.omega2);
        {
            use crate::scene::shared::pendulum::{DOUBLE_PENDULUM, check_all, check_spin};
            let values = [p.length1, p.length2, p.mass1, p.mass2, p.gravity];
            check_all(&mut c, DOUBLE_PENDULUM, &values);
            check_spin(
                &mut c,
                "double_pendulum.omega1",
                p.omega1,
                p.length1,
                p.gravity,
            );
            check_spin(
                &mut c,
                "double_pendulum.omega2",
                p.omega2,
                p.length2,
                p.gravity,
            );
        }
        c.extend(self.integrator.check("integrator"));
        c.finish()
    }
}

impl Written for DoublePendulumScene {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        self.integrator.work("integrator")
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        Ok(self)
    }
}

impl Scene for DoublePendulumScene {
    fn time_scales(&self) -> Option<crate::scene::TimeScales> {
        use crate::scene::{TimeScale, TimeScales, significant};
        let p = &self.double_pendulum;
        let mut scales = Vec::new();
        for (k, l) in [(1, p.length1), (2, p.length2)] {
            scales.push(TimeScale::new(
                format!("link {k}'s small-swing period 2 pi sqrt(l/g)"),
                format!(
                    "double_pendulum.length{k} = {} m, double_pendulum.gravity = {} m/s^2",
                    significant(l),
                    significant(p.gravity)
                ),
                std::f64::consts::TAU * (l / p.gravity).sqrt(),
            ));
        }
        Some(TimeScales::new(&self.integrator, scales))
    }

    fn describe(&self) -> String {
        let p = &self.double_pendulum;
        format!(
            "double pendulum m = ({}, {}) kg, l = ({}, {}) m, released at ({}°, {}°); {}",
            crate::scene::numbers::significant(p.mass1),
            crate::scene::numbers::significant(p.mass2),
            crate::scene::numbers::significant(p.length1),
            crate::scene::numbers::significant(p.length2),
            crate::scene::numbers::significant(p.theta1_deg),
            crate::scene::numbers::significant(p.theta2_deg),
            self.integrator.describe()
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let p = &self.double_pendulum;
        let system = DoublePendulumSystem::new(p);
        let x0 = Vector4::new(
            p.theta1_deg.to_radians(),
            p.theta2_deg.to_radians(),
            p.omega1,
            p.omega2,
        );
        // Energy error relative to the potential-energy scale of the problem.
        let e0 = system.energy(&x0);
        let scale = (p.mass1 + p.mass2) * p.gravity * p.length1 + p.mass2 * p.gravity * p.length2;
        let mut csv = ctx.table(
            Part::Main,
            &[
                "t_s",
                "theta1_rad",
                "theta2_rad",
                "omega1_rad_s",
                "omega2_rad_s",
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
        let (mut th1, mut th2, mut path, mut err) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut last = None;
        let mut drift: f64 = 0.0;
        let bob = |x: &Vector4<f64>| {
            (
                p.length1 * x[0].sin() + p.length2 * x[1].sin(),
                -p.length1 * x[0].cos() - p.length2 * x[1].cos(),
            )
        };
        let sink = |t: f64, x: &Vector4<f64>| -> Result<(), RunError> {
            let e = system.energy(x);
            let rel = (e - e0) / scale;
            drift = drift.max(rel.abs());
            csv.row(&[t, x[0], x[1], x[2], x[3], e, rel])?;
            let point = ((t, x[0]), (t, x[1]), bob(x), (t, rel));
            if keep.keep() {
                th1.push(point.0);
                th2.push(point.1);
                path.push(point.2);
                err.push(point.3);
                last = None;
            } else {
                last = Some(point);
            }
            Ok(())
        };
        let sol = integrate_streaming(&system, x0, spec, Vec::new(), &mut ctx.progress, sink)?;
        if let Some((a, b, c, d)) = last {
            th1.push(a);
            th2.push(b);
            path.push(c);
            err.push(d);
        }
        csv.finish()?;
        let mut fig = Figure::new();
        fig.panels.push(
            Panel::new("Double pendulum: angles", "t [s]", "angle [rad]")
                .with(Series::line("θ₁", th1))
                .with(Series::line("θ₂", th2)),
        );
        fig.panels
            .push(Panel::new("Lower bob path", "x [m]", "y [m]").with(Series::line("bob 2", path)));
        fig.panels.push(
            Panel::new("Energy error", "t [s]", "(E − E₀)/E_scale [-]").with(Series::line(
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
            integration: Some(integration_summary(&self.integrator, &sol, &[])),
            ..RunSummary::default()
        };
        out.metrics.push(Metric::new(
            "max |E - E0| / ((m1 + m2) g l1 + m2 g l2)",
            drift,
            "",
        ));
        Ok(out)
    }
}
