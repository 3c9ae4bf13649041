//! Scene kind `double_pendulum`: two point masses on massless rods in a
//! vertical plane, angles `θ₁`, `θ₂` from the downward vertical. Chaotic for
//! large initial angles; its total energy
//! `E = ½(m₁+m₂)l₁²θ̇₁² + ½m₂l₂²θ̇₂² + m₂l₁l₂θ̇₁θ̇₂cos(θ₁−θ₂) − (m₁+m₂)g l₁cos θ₁ − m₂ g l₂ cos θ₂`
//! must stay constant.
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

use serde::Deserialize;

use crate::error::{RunError, SceneErrors};
use crate::scene::pendulum::STANDARD_GRAVITY;
use crate::scene::validate::Checker;
use crate::scene::{Document, IntegratorSpec, Kind, RunContext, RunSummary, Scene};

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
    fn describe(&self) -> String {
        let p = &self.double_pendulum;
        format!(
            "double pendulum m = ({}, {}) kg, l = ({}, {}) m, released at ({}°, {}°); {}",
            p.mass1,
            p.mass2,
            p.length1,
            p.length2,
            p.theta1_deg,
            p.theta2_deg,
            self.integrator.describe()
        )
    }

    fn run(&self, _ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        Err(RunError::Unavailable {
            what: "the generated double_pendulum model",
        })
    }
}
