//! What a scene run reports: how the integration(s) ended and what they
//! cost ([`IntegrationSummary`]), scene-specific numbers ([`Metric`]), and
//! the files written (from the run's sink). `pegdyn run` prints it with [`std::fmt::Display`].

use std::fmt;
use std::path::PathBuf;

use crate::scene::integrator::Method;
use crate::scene::numbers::significant;

/// A scalar result of a run worth printing (e.g. energy drift).
#[derive(Debug, Clone, PartialEq)]
pub struct Metric {
    /// What it is, e.g. `"max |E - E0| / (m g L)"`.
    pub name: String,
    /// Its value.
    pub value: f64,
    /// Its unit (`""` for dimensionless).
    pub unit: &'static str,
    /// What the value stands for when it is a code (e.g. an outcome's
    /// name): printed first, the value after it as the code, so that
    /// `outcome = seated (code 0)` does not read as "zero seated".
    pub text: Option<String>,
}

impl Metric {
    /// A metric.
    pub fn new(name: impl Into<String>, value: f64, unit: &'static str) -> Self {
        Metric {
            name: name.into(),
            value,
            unit,
            text: None,
        }
    }

    /// A statement without a number (value NaN), printed as
    /// `name: text`, e.g. a check that could not be made.
    pub fn note(name: impl Into<String>, text: impl Into<String>) -> Self {
        Metric {
            text: Some(text.into()),
            ..Metric::new(name, f64::NAN, "")
        }
    }

    /// A coded metric: `code` stands for `text`, printed as
    /// `name = text (code c)`.
    pub fn coded(name: impl Into<String>, code: f64, text: impl Into<String>) -> Self {
        Metric {
            text: Some(text.into()),
            ..Metric::new(name, code, "")
        }
    }
}

/// The relative energy-balance drift above which a run's summary warns
/// that the run is not to be trusted: a conservative balance drifts by
/// about the integrator's tolerance, so a drift of this size is a force
/// the model did not derive from its energy (a contact lost or counted
/// twice), not integration error.
pub const ENERGY_DRIFT_WARNING: f64 = 1e-3;

/// A warning note when the relative energy-balance drift `drift` (the
/// value of the run's `max |E - E0| / ...` metric) exceeds
/// [`ENERGY_DRIFT_WARNING`] or is not a number; `None` otherwise.
pub fn energy_drift_warning(drift: f64) -> Option<Metric> {
    (drift.is_nan() || drift > ENERGY_DRIFT_WARNING).then(|| {
        Metric::note(
            "WARNING",
            format!(
                "the energy balance drifted by {} (relative), above {}: the forces did not \
                 conserve the model's energy, so the run is not physical; do not use its results",
                significant(drift),
                significant(ENERGY_DRIFT_WARNING)
            ),
        )
    })
}

/// How an integration ended and what it cost.
#[derive(Debug, Clone, PartialEq)]
pub struct IntegrationSummary {
    /// Integration method used.
    pub method: Method,
    /// Time the integration stopped at, s.
    pub t_end: f64,
    /// Why it stopped, e.g. `reached t_end` or `event `contact_lost` at t = 0.3 s`.
    pub stop: String,
    /// Whether that is a planned end (end time or terminal event); the CLI
    /// exits with 1 otherwise, after writing what was computed.
    pub success: bool,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (adaptive methods).
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub rhs_calls: usize,
    /// Every event that fired, in time order; a terminal event is last.
    /// (`pegdyn run` prints only [`IntegrationSummary::stop`].)
    pub events: Vec<EventRecord>,
    /// Why the run stopped short, when its steps were the reason:
    /// [`crate::scene::LoadedScene::run`] adds the likely cause to
    /// [`IntegrationSummary::stop`].
    pub step_failure: Option<StepFailure>,
}

/// A run stopped by its steps: one too small to take, or too many of them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepFailure {
    /// The step became too small at time `t` (s): the rejected step `h` (s).
    TooSmall {
        /// Time of the last accepted step, s.
        t: f64,
        /// The rejected step, s.
        h: f64,
    },
    /// The step budget ran out at time `t` (s) after steps of `mean` (s) on
    /// average (the time covered over the steps attempted).
    Budget {
        /// Time of the last accepted step, s.
        t: f64,
        /// The mean step, s.
        mean: f64,
    },
}

/// One event that fired during an integration.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRecord {
    /// The scene's name for it (`#index` when the scene names none).
    pub name: String,
    /// Located time, s.
    pub t: f64,
    /// Whether it ended the integration.
    pub terminal: bool,
    /// Named numbers describing it: for an integrator event `direction`
    /// (+1 when the event function rose through zero, −1 when it fell) and
    /// the state there, `x[0]`, `x[1]`, … in the scene's state order.
    pub details: Vec<(String, f64)>,
}

impl IntegrationSummary {
    /// Appends a later integration (e.g. the next contact phase): counters
    /// add up, events are appended, the end time, stop reason and success are the later one's.
    pub fn merge(&mut self, later: IntegrationSummary) {
        self.steps += later.steps;
        self.rejected += later.rejected;
        self.rhs_calls += later.rhs_calls;
        self.events.extend(later.events);
        self.t_end = later.t_end;
        self.stop = later.stop;
        self.success = later.success;
        self.method = later.method;
        self.step_failure = later.step_failure;
    }
}

/// What a run reports back.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RunSummary {
    /// The time integration, if the scene integrates in time (a parameter
    /// sweep of static equilibria does not).
    pub integration: Option<IntegrationSummary>,
    /// Scene-specific results.
    pub metrics: Vec<Metric>,
    /// Files written, in the order they were completed: filled in by
    /// [`crate::scene::LoadedScene::run`] from the run's sink (empty for a
    /// run in memory).
    pub outputs: Vec<PathBuf>,
}

impl RunSummary {
    /// `false` when the integration stopped unplanned.
    pub fn success(&self) -> bool {
        self.integration.as_ref().is_none_or(|i| i.success)
    }
}

impl fmt::Display for RunSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(i) = &self.integration {
            writeln!(f, "  stopped at t = {} s: {}", significant(i.t_end), i.stop)?;
            writeln!(
                f,
                "  {}: {} steps ({} rejected), {} rhs calls",
                i.method.name(),
                i.steps,
                i.rejected,
                i.rhs_calls
            )?;
        }
        for m in &self.metrics {
            let sep = if m.unit.is_empty() { "" } else { " " };
            let v = format_metric(m.value);
            match &m.text {
                Some(text) if m.value.is_nan() => writeln!(f, "  {}: {text}", m.name)?,
                Some(text) => writeln!(f, "  {} = {text} (code {v})", m.name)?,
                None => writeln!(f, "  {} = {v}{sep}{}", m.name, m.unit)?,
            }
        }
        for p in &self.outputs {
            writeln!(f, "  wrote {}", p.display())?;
        }
        Ok(())
    }
}

/// Integers (counts) as integers, `[1e-3, 1e6)` with six decimals, the
/// rest with four significant digits in scientific notation; zero as `0`
/// whatever its sign (an empty sum is `-0.0`).
pub fn format_metric(v: f64) -> String {
    if v == 0.0 {
        "0".to_owned()
    } else if v.fract() == 0.0 && v.abs() < 1e15 {
        format!("{v:.0}")
    } else if (1e-3..1e6).contains(&v.abs()) {
        format!("{v:.6}")
    } else {
        format!("{v:.3e}")
    }
}
