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
//! ([`exact_period`]).
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

use nalgebra::{SMatrix, SVector, Vector2, Vector3};
use serde::Deserialize;

use crate::error::{RunError, SceneErrors};
use crate::generated::pendulum as generated;
use crate::integrate::{Direction, Event};
use crate::output::csv::CsvWriter;
use crate::output::plot::{Figure, Panel, Series};
use crate::scene::simulate::{integrate, integration_summary};
use crate::scene::validate::Checker;
use crate::scene::{Document, IntegratorSpec, Kind, Metric, RunContext, RunSummary, Scene};
use crate::system::{OdeSystem, finite_difference_jacobian};

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "pendulum",
    about: "simple pendulum released at an angle (textbook check)",
    parse,
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Scene>, SceneErrors> {
    let s: PendulumScene = doc.body()?;
    s.check()?;
    Ok(Box::new(s))
}

/// Standard gravity, m/s².
pub const STANDARD_GRAVITY: f64 = 9.80665;

fn standard_gravity() -> f64 {
    STANDARD_GRAVITY
}

/// The `[pendulum]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PendulumParams {
    /// Rod length `L`, m.
    pub length: f64,
    /// Bob mass `m`, kg.
    pub mass: f64,
    /// Gravitational acceleration `g`, m/s².
    #[serde(default = "standard_gravity")]
    pub gravity: f64,
    /// Initial angle from the downward vertical, degrees.
    pub theta0_deg: f64,
    /// Initial angular velocity, rad/s.
    #[serde(default)]
    pub omega0: f64,
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
        c.extend(self.integrator.check("integrator"));
        c.finish()
    }
}

impl Scene for PendulumScene {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        self.integrator.work("integrator")
    }

    fn describe(&self) -> String {
        let p = &self.pendulum;
        format!(
            "simple pendulum L = {} m, m = {} kg, g = {} m/s², released at {}° with {} rad/s; {}",
            crate::scene::summary::significant(p.length),
            crate::scene::summary::significant(p.mass),
            crate::scene::summary::significant(p.gravity),
            crate::scene::summary::significant(p.theta0_deg),
            crate::scene::summary::significant(p.omega0),
            self.integrator.describe()
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let p = &self.pendulum;
        let system = PendulumSystem::new(p);
        let x0 = Vector2::new(p.theta0_deg.to_radians(), p.omega0);
        // θ rising through zero: once per period of a libration.
        let events = vec![Event::new(|_t, x: &SVector<f64, 2>| x[0]).direction(Direction::Rising)];
        let sol = integrate(&system, x0, &self.integrator, events, &mut ctx.progress)?;

        // Energy error relative to m g L, the energy scale of the problem
        // (E0 itself may be zero).
        let e0 = system.energy(&x0);
        let scale = p.mass * p.gravity * p.length;
        let mut csv = CsvWriter::create(
            &ctx.output("csv"),
            &[
                "t_s",
                "theta_rad",
                "omega_rad_s",
                "energy_J",
                "energy_error",
            ],
        )?;
        let (mut theta, mut err) = (Vec::new(), Vec::new());
        let mut drift: f64 = 0.0;
        for (t, x) in sol.t.iter().zip(&sol.x) {
            let e = system.energy(x);
            let rel = (e - e0) / scale;
            drift = drift.max(rel.abs());
            csv.row(&[*t, x[0], x[1], e, rel])?;
            theta.push((*t, x[0]));
            err.push((*t, rel));
        }
        let csv = csv.finish()?;

        let svg = ctx.output("svg");
        let mut fig = Figure::new();
        fig.panels.push(
            Panel::new("Simple pendulum: angle", "t [s]", "θ [rad]").with(Series::line("θ", theta)),
        );
        fig.panels.push(
            Panel::new("Energy error", "t [s]", "(E − E₀)/(m g L) [-]")
                .with(Series::line(self.integrator.method.name(), err)),
        );
        fig.save(&svg)?;

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
        out.outputs = vec![csv, svg];
        Ok(out)
    }
}

/// The exact period of a librating pendulum,
/// `T = 2π √(L/g) / AGM(1, cos(θ_max/2))` (complete elliptic integral of
/// the first kind via the arithmetic-geometric mean), where the amplitude
/// follows from energy conservation, `cos θ_max = cos θ₀ − L ω₀²/(2g)`.
/// `None` when the pendulum circulates (`cos θ_max ≤ −1`) or stays at rest.
pub fn exact_period(p: &PendulumParams) -> Option<f64> {
    let cos_max =
        p.theta0_deg.to_radians().cos() - p.length * p.omega0 * p.omega0 / (2.0 * p.gravity);
    if cos_max <= -1.0 || cos_max >= 1.0 {
        return None;
    }
    let k_prime = ((1.0 + cos_max) / 2.0).sqrt();
    let (mut a, mut b) = (1.0_f64, k_prime);
    while (a - b).abs() > 1e-15 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    Some(2.0 * std::f64::consts::PI * (p.length / p.gravity).sqrt() / a)
}

/// The generated `pendulum` model as an [`OdeSystem`], state `(θ, θ̇)`.
#[derive(Debug, Clone, Copy)]
pub struct PendulumSystem {
    /// Parameters in the order of [`generated::P_NAMES`]: `m, l, g`.
    p: Vector3<f64>,
}

impl PendulumSystem {
    /// The system for the given parameters.
    pub fn new(p: &PendulumParams) -> Self {
        PendulumSystem {
            p: Vector3::new(p.mass, p.length, p.gravity),
        }
    }

    /// Total energy `T + V`, J.
    pub fn energy(&self, x: &Vector2<f64>) -> f64 {
        generated::energy(x, &self.p)
    }
}

impl OdeSystem<2> for PendulumSystem {
    fn rhs(&self, _t: f64, x: &Vector2<f64>) -> Vector2<f64> {
        generated::rhs(x, &self.p)
    }

    /// `∂ẋ/∂x = [[0, 1], [M⁻¹G]]` from the generated mass matrix and
    /// Jacobian terms `G`.
    fn jacobian(&self, t: f64, x: &Vector2<f64>) -> SMatrix<f64, 2, 2> {
        let (mass, forcing) = generated::dynamics(x, &self.p);
        let lu = mass.lu();
        let solved = lu
            .solve(&forcing)
            .and_then(|qdd| lu.solve(&generated::jacobian_terms(x, &qdd, &self.p)));
        match solved {
            Some(row) => SMatrix::<f64, 2, 2>::new(0.0, 1.0, row[(0, 0)], row[(0, 1)]),
            None => finite_difference_jacobian(|x| self.rhs(t, x), x),
        }
    }

    fn time_derivative(&self, _t: f64, _x: &Vector2<f64>) -> Vector2<f64> {
        Vector2::zeros()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(theta0_deg: f64, omega0: f64) -> PendulumParams {
        PendulumParams {
            length: 2.0,
            mass: 0.5,
            gravity: 9.81,
            theta0_deg,
            omega0,
        }
    }

    #[test]
    fn generated_parameter_order_is_m_l_g() {
        assert_eq!(generated::P_NAMES, ["m", "l", "g"]);
        assert_eq!(generated::X_NAMES, ["theta", "thetadot"]);
    }

    #[test]
    fn exact_period_limits() {
        // Small amplitude: 2π√(L/g); 90°: 1.18034060... × 2π√(L/g).
        let t0 = 2.0 * std::f64::consts::PI * (2.0f64 / 9.81).sqrt();
        let small = exact_period(&params(1e-3, 0.0)).unwrap();
        assert!((small / t0 - 1.0).abs() < 1e-7);
        let right = exact_period(&params(90.0, 0.0)).unwrap();
        assert!(
            (right / t0 - 1.180340599016096).abs() < 1e-12,
            "{}",
            right / t0
        );
        assert!(exact_period(&params(0.0, 10.0)).is_none());
    }

    #[test]
    fn jacobian_matches_finite_difference() {
        let sys = PendulumSystem::new(&params(40.0, 0.0));
        let x = Vector2::new(0.7, -0.3);
        let j = sys.jacobian(0.0, &x);
        let fd = finite_difference_jacobian(|x| sys.rhs(0.0, x), &x);
        assert!((j - fd).abs().max() < 1e-6, "{j} vs {fd}");
        assert_eq!(j[(1, 0)], -9.81 * 0.7f64.cos() / 2.0);
    }
}
