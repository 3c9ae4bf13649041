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

use nalgebra::{SMatrix, SVector, Vector4};
use serde::Deserialize;

use crate::error::{RunError, SceneErrors};
use crate::generated::double_pendulum as generated;
use crate::output::csv::CsvWriter;
use crate::output::plot::{Figure, Panel, Series};
use crate::scene::pendulum::STANDARD_GRAVITY;
use crate::scene::simulate::{integrate, integration_summary};
use crate::scene::validate::Checker;
use crate::scene::{Document, IntegratorSpec, Kind, Metric, RunContext, RunSummary, Scene};
use crate::system::{OdeSystem, finite_difference_jacobian};

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "double_pendulum",
    about: "planar double pendulum (textbook check, chaotic)",
    parse,
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Scene>, SceneErrors> {
    let s: DoublePendulumScene = doc.body()?;
    s.check()?;
    Ok(Box::new(s))
}

fn standard_gravity() -> f64 {
    STANDARD_GRAVITY
}

/// The `[double_pendulum]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DoublePendulumParams {
    /// Upper bob mass `m₁`, kg.
    pub mass1: f64,
    /// Lower bob mass `m₂`, kg.
    pub mass2: f64,
    /// Upper rod length `l₁`, m.
    pub length1: f64,
    /// Lower rod length `l₂`, m.
    pub length2: f64,
    /// Gravitational acceleration `g`, m/s².
    #[serde(default = "standard_gravity")]
    pub gravity: f64,
    /// Initial upper angle, degrees from the downward vertical.
    pub theta1_deg: f64,
    /// Initial lower angle, degrees from the downward vertical.
    pub theta2_deg: f64,
    /// Initial upper angular velocity, rad/s.
    #[serde(default)]
    pub omega1: f64,
    /// Initial lower angular velocity, rad/s.
    #[serde(default)]
    pub omega2: f64,
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
        c.extend(self.integrator.check("integrator"));
        c.finish()
    }
}

impl Scene for DoublePendulumScene {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        self.integrator.work("integrator")
    }

    fn describe(&self) -> String {
        let p = &self.double_pendulum;
        format!(
            "double pendulum m = ({}, {}) kg, l = ({}, {}) m, released at ({}°, {}°); {}",
            crate::scene::summary::significant(p.mass1),
            crate::scene::summary::significant(p.mass2),
            crate::scene::summary::significant(p.length1),
            crate::scene::summary::significant(p.length2),
            crate::scene::summary::significant(p.theta1_deg),
            crate::scene::summary::significant(p.theta2_deg),
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
        let sol = integrate(&system, x0, &self.integrator, Vec::new(), &mut ctx.progress)?;

        // Energy error relative to the potential-energy scale of the problem.
        let e0 = system.energy(&x0);
        let scale = (p.mass1 + p.mass2) * p.gravity * p.length1 + p.mass2 * p.gravity * p.length2;
        let mut csv = CsvWriter::create(
            &ctx.output("csv"),
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
        let (mut th1, mut th2, mut path, mut err) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut drift: f64 = 0.0;
        for (&t, x) in sol.t.iter().zip(&sol.x) {
            let e = system.energy(x);
            let rel = (e - e0) / scale;
            drift = drift.max(rel.abs());
            csv.row(&[t, x[0], x[1], x[2], x[3], e, rel])?;
            th1.push((t, x[0]));
            th2.push((t, x[1]));
            path.push((
                p.length1 * x[0].sin() + p.length2 * x[1].sin(),
                -p.length1 * x[0].cos() - p.length2 * x[1].cos(),
            ));
            err.push((t, rel));
        }
        let csv = csv.finish()?;

        let svg = ctx.output("svg");
        let mut fig = Figure::new();
        fig.panels.push(
            Panel::new("Double pendulum: angles", "t [s]", "angle [rad]")
                .with(Series::line("θ₁", th1))
                .with(Series::line("θ₂", th2)),
        );
        fig.panels
            .push(Panel::new("Lower bob path", "x [m]", "y [m]").with(Series::line("bob 2", path)));
        fig.panels.push(
            Panel::new("Energy error", "t [s]", "(E − E₀)/E_scale [-]")
                .with(Series::line(self.integrator.method.name(), err)),
        );
        fig.save(&svg)?;

        let mut out = RunSummary {
            integration: Some(integration_summary(&self.integrator, &sol, &[])),
            ..RunSummary::default()
        };
        out.metrics.push(Metric::new(
            "max |E - E0| / ((m1 + m2) g l1 + m2 g l2)",
            drift,
            "",
        ));
        out.outputs = vec![csv, svg];
        Ok(out)
    }
}

/// The generated `double_pendulum` model as an [`OdeSystem`], state
/// `(θ₁, θ₂, θ̇₁, θ̇₂)`.
#[derive(Debug, Clone, Copy)]
pub struct DoublePendulumSystem {
    /// Parameters in the order of [`generated::P_NAMES`]: `m1, m2, l1, l2, g`.
    p: SVector<f64, 5>,
}

impl DoublePendulumSystem {
    /// The system for the given parameters.
    pub fn new(p: &DoublePendulumParams) -> Self {
        DoublePendulumSystem {
            p: SVector::<f64, 5>::from([p.mass1, p.mass2, p.length1, p.length2, p.gravity]),
        }
    }

    /// Total energy `T + V`, J.
    pub fn energy(&self, x: &Vector4<f64>) -> f64 {
        generated::energy(x, &self.p)
    }
}

impl OdeSystem<4> for DoublePendulumSystem {
    fn rhs(&self, _t: f64, x: &Vector4<f64>) -> Vector4<f64> {
        generated::rhs(x, &self.p)
    }

    /// `∂ẋ/∂x = [[0, I], [M⁻¹G]]` from the generated mass matrix and
    /// Jacobian terms `G`.
    fn jacobian(&self, t: f64, x: &Vector4<f64>) -> SMatrix<f64, 4, 4> {
        let (mass, forcing) = generated::dynamics(x, &self.p);
        let lu = mass.lu();
        let solved = lu
            .solve(&forcing)
            .and_then(|qdd| lu.solve(&generated::jacobian_terms(x, &qdd, &self.p)));
        match solved {
            Some(lower) => {
                let mut j = SMatrix::<f64, 4, 4>::zeros();
                j[(0, 2)] = 1.0;
                j[(1, 3)] = 1.0;
                j.fixed_view_mut::<2, 4>(2, 0).copy_from(&lower);
                j
            }
            None => finite_difference_jacobian(|x| self.rhs(t, x), x),
        }
    }

    fn time_derivative(&self, _t: f64, _x: &Vector4<f64>) -> Vector4<f64> {
        Vector4::zeros()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_orders_match_the_adapter() {
        assert_eq!(generated::P_NAMES, ["m1", "m2", "l1", "l2", "g"]);
        assert_eq!(
            generated::X_NAMES,
            ["theta1", "theta2", "theta1dot", "theta2dot"]
        );
    }

    #[test]
    fn jacobian_matches_finite_difference() {
        let p = DoublePendulumParams {
            mass1: 1.3,
            mass2: 0.7,
            length1: 0.9,
            length2: 1.4,
            gravity: 9.81,
            theta1_deg: 0.0,
            theta2_deg: 0.0,
            omega1: 0.0,
            omega2: 0.0,
        };
        let sys = DoublePendulumSystem::new(&p);
        let x = Vector4::new(0.4, -1.1, 0.8, -0.5);
        let j = sys.jacobian(0.0, &x);
        let fd = finite_difference_jacobian(|x| sys.rhs(0.0, x), &x);
        assert!((j - fd).abs().max() < 1e-5, "{j} vs {fd}");
        assert_eq!((j[(0, 2)], j[(1, 3)], j[(0, 0)]), (1.0, 1.0, 0.0));
    }
}
