//! Integration options and their validation.

use thiserror::Error;

/// Which points the integrator reports (stores in the
/// [`super::Solution`] and passes to the observer).
#[derive(Debug, Clone, PartialEq, Default)]
pub enum OutputMode {
    /// The initial point and the end of every accepted step (a terminal
    /// event replaces the end of its step by the event point).
    #[default]
    EveryStep,
    /// The given times only, interpolated with the method's dense output.
    /// Must be finite, non-decreasing and inside `[t0, t_end]`.
    AtTimes(Vec<f64>),
}

/// Smallest relative tolerance accepted: a relative error below f64's
/// rounding unit (`ε/2 ≈ 1.1e-16`) cannot be met, and the step control
/// would shrink the step towards the round-off floor on every step.
pub const MIN_RTOL: f64 = 1e-15;

/// Smallest absolute tolerance accepted: the smallest normal f64. Below,
/// the error weights `1/(atol + rtol |x|)` of a component at zero overflow
/// and every step would be rejected as non-finite.
pub const MIN_ATOL: f64 = f64::MIN_POSITIVE;

/// Largest step budget ([`Options::max_steps`]) accepted: `10⁹` attempted
/// steps are hours of work for the smallest system; a larger budget is no
/// budget.
pub const MAX_STEP_BUDGET: usize = 1_000_000_000;

/// Tolerances and limits of an integration.
///
/// The local error estimate `e` of a step is accepted when
/// `√(mean((eᵢ / (atolᵢ + rtol·max(|xᵢ|, |x̃ᵢ|)))²)) ≤ 1`, the mean over
/// every component or the first [`Options::error_components`], with
/// `atolᵢ` from [`Options::component_atol`] for the leading components and
/// [`Options::atol`] for the others.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Relative tolerance (`>= MIN_RTOL`, finite; a huge value turns the
    /// error control off, e.g. to take the `h0` steps unchanged).
    pub rtol: f64,
    /// Absolute tolerance (`>= MIN_ATOL`, finite), in state units.
    pub atol: f64,
    /// Absolute tolerances of the leading components, one per component
    /// in order (each `>= MIN_ATOL`, finite; at most the state's size),
    /// for a state whose components have different units: a rigid body's
    /// angular velocity (rad/s) beside its position (m). Empty (the
    /// default): [`Options::atol`] for every component.
    pub component_atol: Vec<f64>,
    /// Initial step; `None` chooses one from the right-hand side
    /// (Hairer, Nørsett & Wanner I, §II.4, "starting step size").
    pub h0: Option<f64>,
    /// Largest step; `None` means the whole interval.
    pub h_max: Option<f64>,
    /// Budget of attempted (accepted + rejected) steps, in
    /// `[1, MAX_STEP_BUDGET]`.
    pub max_steps: usize,
    /// Which points to report.
    pub output: OutputMode,
    /// Keep the reported points in [`super::Solution::t`] /
    /// [`super::Solution::x`]; turn off when an observer streams them.
    pub store: bool,
    /// The error norm over the first `n` components only (`None`: all;
    /// an `n` beyond the state's size means all; the starting step is
    /// estimated over every component). For a state extended
    /// with quantities that follow it, such as forward sensitivities, the
    /// step sequence is then the state's own and the extension is the
    /// exact derivative of the computed solution along it. A step whose
    /// error estimate is not finite in any component is still rejected.
    pub error_components: Option<usize>,
    /// Where the norm over every component (or the first
    /// [`Options::error_components`]) keeps failing, the first `n`
    /// components judge the step once it is shorter than
    /// [`FALLBACK_FLOOR`] round-off floors (`16 ε max(|t|, |t_end|)`),
    /// instead of the run stopping at the floor itself (`None`: no
    /// fallback). For a state extended with its forward sensitivities,
    /// their error is then bounded everywhere but across a point where
    /// their rate is unbounded though integrable (a contact splitting in
    /// two, whose points move like the square root of the pose): there
    /// the state's error is still bounded, and the sensitivities' error
    /// of the step is that of a step of about `10⁻¹¹ |t|`. Such steps are
    /// counted in [`super::Stats::fallback_steps`].
    pub fallback_components: Option<usize>,
}

/// How many round-off floors (`16 ε max(|t|, |t_end|)`, the shortest step
/// a run takes) long a step may be when [`Options::fallback_components`]
/// judges it: `10⁴`, a step of about `3.6·10⁻¹¹ |t|`.
pub const FALLBACK_FLOOR: f64 = 1e4;

impl Default for Options {
    fn default() -> Self {
        Options {
            rtol: 1e-6,
            atol: 1e-9,
            component_atol: Vec::new(),
            h0: None,
            h_max: None,
            max_steps: 1_000_000,
            output: OutputMode::EveryStep,
            store: true,
            error_components: None,
            fallback_components: None,
        }
    }
}

impl Options {
    /// Default options with the given tolerances.
    pub fn with_tolerances(rtol: f64, atol: f64) -> Self {
        Options {
            rtol,
            atol,
            ..Options::default()
        }
    }

    /// Checks every field against the interval `[t0, t_end]`.
    pub fn validate(&self, t0: f64, t_end: f64) -> Result<(), IntegrateError> {
        let positive = |name: &'static str, value: f64| {
            if value.is_finite() && value > 0.0 {
                Ok(())
            } else {
                Err(IntegrateError::InvalidOption {
                    name,
                    value,
                    reason: "must be finite and positive",
                })
            }
        };
        // An absolute tolerance, `atol` or one of `component_atol`.
        let absolute = |name: &'static str, value: f64| {
            positive(name, value)?;
            if value < MIN_ATOL {
                return Err(IntegrateError::InvalidOption {
                    name,
                    value,
                    reason: "must be at least 2.2e-308 (the smallest normal f64): below, the \
                             error weight of a component at zero overflows",
                });
            }
            Ok(())
        };
        if !(t0.is_finite() && t_end.is_finite() && t_end >= t0) {
            return Err(IntegrateError::InvalidSpan { t0, t_end });
        }
        positive("rtol", self.rtol)?;
        positive("atol", self.atol)?;
        if self.rtol < MIN_RTOL {
            return Err(IntegrateError::InvalidOption {
                name: "rtol",
                value: self.rtol,
                reason: "must be at least 1e-15: f64 cannot meet a relative error below its \
                         rounding unit (1.1e-16), and the step control would shrink the step \
                         without end",
            });
        }
        absolute("atol", self.atol)?;
        for &a in &self.component_atol {
            absolute("component_atol", a)?;
        }
        if self.max_steps > MAX_STEP_BUDGET {
            return Err(IntegrateError::InvalidOption {
                name: "max_steps",
                value: self.max_steps as f64,
                reason: "must be at most 1e9 attempted steps",
            });
        }
        if let Some(h0) = self.h0 {
            positive("h0", h0)?;
        }
        if let Some(h_max) = self.h_max {
            positive("h_max", h_max)?;
        }
        if self.error_components == Some(0) {
            return Err(IntegrateError::InvalidOption {
                name: "error_components",
                value: 0.0,
                reason: "must be at least 1 (None controls every component)",
            });
        }
        if self.fallback_components == Some(0) {
            return Err(IntegrateError::InvalidOption {
                name: "fallback_components",
                value: 0.0,
                reason: "must be at least 1 (None: no fallback)",
            });
        }
        if self.max_steps == 0 {
            return Err(IntegrateError::InvalidOption {
                name: "max_steps",
                value: 0.0,
                reason: "must be at least 1",
            });
        }
        if let OutputMode::AtTimes(times) = &self.output {
            let mut previous = t0;
            for (index, &value) in times.iter().enumerate() {
                if !(value.is_finite() && value >= previous && value <= t_end) {
                    return Err(IntegrateError::InvalidOutputTime { index, value });
                }
                previous = value;
            }
        }
        Ok(())
    }

    /// The absolute tolerance of component `i`.
    pub fn atol_of(&self, i: usize) -> f64 {
        self.component_atol.get(i).copied().unwrap_or(self.atol)
    }
}

/// Invalid input to an integrator (user input: never a panic).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum IntegrateError {
    /// An option is out of range.
    #[error("integrator option `{name}` = {value}: {reason}")]
    InvalidOption {
        /// Field name in [`Options`] (or `h` of a fixed-step method).
        name: &'static str,
        /// The offending value.
        value: f64,
        /// What the value must satisfy.
        reason: &'static str,
    },
    /// The time interval is not finite or runs backwards.
    #[error("integration interval [{t0}, {t_end}] must be finite with t_end >= t0")]
    InvalidSpan {
        /// Start time.
        t0: f64,
        /// End time.
        t_end: f64,
    },
    /// A requested output time is not finite, not sorted, or outside the
    /// interval.
    #[error("output time #{index} = {value} is not finite, not sorted, or outside [t0, t_end]")]
    InvalidOutputTime {
        /// Position in [`OutputMode::AtTimes`].
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A component of the initial state is not finite.
    #[error("initial state component {index} = {value} is not finite")]
    NonFiniteInitialState {
        /// Component index.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// The memory to store the requested output samples cannot be
    /// reserved (instead of the process aborting half-way).
    #[error(
        "cannot reserve memory to store {samples} output samples ({bytes:.3e} bytes); \
         sample less often or stream the output"
    )]
    OutOfMemory {
        /// Samples requested ([`OutputMode::AtTimes`]).
        samples: usize,
        /// Bytes asked for.
        bytes: f64,
    },
}
