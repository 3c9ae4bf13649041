//! Scene kind `pendulum`: a simple (point-mass, massless-rod) pendulum
//! released at an angle, `θ̈ = −(g/L) sin θ`, with `θ` measured from the
//! downward vertical. A textbook check of the generator and integrators:
//! the total energy `E = ½ m L² θ̇² − m g L cos θ` must stay constant.
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

use serde::Deserialize;

use crate::error::{RunError, SceneErrors};
use crate::scene::validate::Checker;
use crate::scene::{Document, IntegratorSpec, Kind, RunContext, RunSummary, Scene};

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
    fn describe(&self) -> String {
        let p = &self.pendulum;
        format!(
            "simple pendulum L = {} m, m = {} kg, g = {} m/s², released at {}° with {} rad/s; {}",
            p.length,
            p.mass,
            p.gravity,
            p.theta0_deg,
            p.omega0,
            self.integrator.describe()
        )
    }

    fn run(&self, _ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        Err(RunError::Integration {
            t: self.integrator.t0,
            reason: "the pendulum run is not wired to the integrators yet".into(),
        })
    }
}
