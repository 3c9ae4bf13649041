//! The time scales of a scene, estimated from its parameters before the
//! run, and what they say when a run fails to step or runs slowly: the
//! fastest one bounds the step an explicit method can take, and a step
//! that fails far below every one points at the tolerances instead.
//!
//! A kind lists its scales ([`crate::scene::Scene::time_scales`]), each
//! with the fields that set it: a contact's natural period
//! `2π √(m / k_eff)` with `k_eff = (3/2) k^{2/3} F^{1/3}` the Hertz law
//! `F = k δ^{3/2}` linearized at the load `F` it carries, a wrist's period
//! `2π √(m / K)`, a load's `√(m L / F)` (the time it takes to move the
//! body by its own size), a regularized friction's `m v_s / (μ F)`.

use std::f64::consts::TAU;

use crate::scene::integrator::IntegratorSpec;
use crate::scene::numbers::significant;

/// One time scale of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct TimeScale {
    /// What it is, with its formula, e.g. `the contact's natural period
    /// 2π √(m/k_eff)`.
    pub what: String,
    /// The scene fields that set it, with their values, e.g.
    /// `peg.contact_stiffness = 1e15 N/m^1.5`.
    pub fields: String,
    /// Its length (s).
    pub period: f64,
}

impl TimeScale {
    /// A time scale `period` (s) of `what`, set by `fields`.
    pub fn new(what: impl Into<String>, fields: impl Into<String>, period: f64) -> Self {
        TimeScale {
            what: what.into(),
            fields: fields.into(),
            period,
        }
    }

    /// The natural period `2π √(m / k)` (s) of mass `m` on stiffness `k`.
    pub fn period_of(m: f64, k: f64) -> f64 {
        TAU * (m / k).sqrt()
    }

    /// The stiffness `dF/dδ = (3/2) k^{2/3} F^{1/3}` of the Hertz law
    /// `F = k δ^{3/2}` at load `F`.
    pub fn hertz_stiffness(k: f64, load: f64) -> f64 {
        1.5 * k.powf(2.0 / 3.0) * load.cbrt()
    }

    /// The time scale in words: `what = 2e-9 s (fields)`.
    pub fn describe(&self) -> String {
        format!(
            "{} = {} s ({})",
            self.what,
            significant(self.period),
            self.fields
        )
    }
}

/// The time scales of a scene with its integration span and tolerance.
#[derive(Debug, Clone, PartialEq)]
pub struct TimeScales {
    /// The scales (finite, positive ones are used).
    pub scales: Vec<TimeScale>,
    /// `integrator.t0`, `integrator.t_end` (s).
    pub span: (f64, f64),
    /// `integrator.atol`.
    pub atol: f64,
    /// `integrator.rtol`.
    pub rtol: f64,
}

/// A step that fails below this fraction of the fastest time scale failed
/// on the error test, not on the dynamics: the tolerance asks for more
/// digits than the state has.
const TOLERANCE_BOUND: f64 = 1e-6;

/// Steps that ran out their budget this far below the fastest time scale
/// on average were set by the error test: an explicit method needs some
/// tens of steps per period, not thousands (a wrist insertion at
/// `atol = 1e-40` averaged 1/1140 of its fastest scale, at `1e-10` about as
/// long as it).
const BUDGET_TOLERANCE_BOUND: f64 = 1e-3;

/// A time scale within this many smallest steps of f64's resolution at
/// the run's times cannot be followed: an explicit method needs some tens
/// of steps per period.
const RESOLUTION_STEPS: f64 = 1e3;

impl TimeScales {
    /// The scales of a scene integrated as `spec` says.
    pub fn new(spec: &IntegratorSpec, scales: Vec<TimeScale>) -> Self {
        TimeScales {
            scales,
            span: (spec.t0, spec.t_end),
            atol: spec.atol,
            rtol: spec.rtol,
        }
    }

    /// The shortest finite, positive scale.
    pub fn fastest(&self) -> Option<&TimeScale> {
        self.scales
            .iter()
            .filter(|s| s.period.is_finite() && s.period > 0.0)
            .min_by(|a, b| a.period.total_cmp(&b.period))
    }

    /// The smallest step f64 resolves at the run's times, `16 ε max(|t0|,
    /// |t_end|)` (the integrators' step floor).
    pub fn resolution(&self) -> f64 {
        16.0 * f64::EPSILON * self.span.0.abs().max(self.span.1.abs())
    }

    /// The likely cause of a step that became too small (`h`, s) at time
    /// `t`: the fastest time scale when it is within `RESOLUTION_STEPS`
    /// smallest steps, the tolerance when the step failed far below every
    /// scale, else the fastest scale as the one that sets the steps.
    pub fn step_failure_cause(&self, t: f64, h: f64) -> String {
        let floor = self.resolution().max(16.0 * f64::EPSILON * t.abs());
        let Some(fast) = self.fastest() else {
            return format!(
                "the step fell below f64's resolution at these times (16 eps t = {} s); an \
                 extreme scene value (a stiffness, load or size over many decades) or \
                 integrator.atol = {} far below the state's scale",
                significant(floor),
                significant(self.atol)
            );
        };
        if fast.period < RESOLUTION_STEPS * floor {
            format!(
                "{} is too short to follow: f64 resolves steps of {} s at t_end = {} s, {} it; \
                 change {} (or shorten the run: the resolution is 16 eps t)",
                fast.describe(),
                significant(floor),
                significant(self.span.1),
                share(floor / fast.period),
                fast.fields
            )
        } else if h < TOLERANCE_BOUND * fast.period {
            format!(
                "the tolerance: the step failed at {} s, {} the fastest time scale ({}), \
                 so the error test asks for more digits than f64 holds; integrator.atol = {} \
                 is likely far below the state's scale (components that start at zero need \
                 an absolute tolerance of at least 1e-15 of their scale)",
                significant(h),
                share(h / fast.period),
                fast.describe(),
                significant(self.atol)
            )
        } else {
            format!(
                "{}, which sets the step; change {}",
                fast.describe(),
                fast.fields
            )
        }
    }

    /// What makes a run slow whose steps were `mean` (s) on average: the
    /// tolerance when the mean step is far below every scale
    /// (`BUDGET_TOLERANCE_BOUND`: an explicit method needs some tens of
    /// steps per period, not thousands), else the fastest scale, which
    /// sets the step.
    pub fn slow_cause(&self, mean: f64) -> String {
        let tolerances = format!(
            "integrator.rtol = {} and integrator.atol = {}",
            significant(self.rtol),
            significant(self.atol)
        );
        let Some(fast) = self.fastest() else {
            return format!(
                "steps of {} s on average: {tolerances} (or an extreme scene value) set them",
                significant(mean)
            );
        };
        if mean < BUDGET_TOLERANCE_BOUND * fast.period {
            format!(
                "the tolerance: steps of {} s on average are {} the fastest time scale ({}), so \
                 the error test, not the dynamics, sets them; {tolerances} likely ask for more \
                 digits than the run needs",
                significant(mean),
                share(mean / fast.period),
                fast.describe()
            )
        } else {
            format!(
                "the fastest time scale of the scene, {}, which sets the step; change {}",
                fast.describe(),
                fast.fields
            )
        }
    }

    /// The likely cause of a step budget that ran out at time `t` after
    /// steps of `mean` (s) on average: the tolerance when the mean step is
    /// far below every scale (`BUDGET_TOLERANCE_BOUND`), else
    /// the fastest scale, which sets the steps the run needs, about
    /// `(t_end - t0) / mean` of them.
    pub fn budget_cause(&self, t: f64, mean: f64) -> String {
        let needed = (self.span.1 - self.span.0) / mean;
        let Some(fast) = self.fastest() else {
            return format!(
                "steps of {} s on average, about {} for the whole run; integrator.atol = {} far \
                 below the state's scale, or an extreme scene value",
                significant(mean),
                significant(needed.round()),
                significant(self.atol)
            );
        };
        if mean < BUDGET_TOLERANCE_BOUND * fast.period {
            format!(
                "the tolerance: the steps to t = {} s were {} s on average, {} the fastest time \
                 scale ({}), so the error test asks for more digits than f64 holds; \
                 integrator.atol = {} is likely far below the state's scale (components that \
                 start at zero need an absolute tolerance of at least 1e-15 of their scale)",
                significant(t),
                significant(mean),
                share(mean / fast.period),
                fast.describe(),
                significant(self.atol)
            )
        } else {
            format!(
                "{}, which sets the steps: at {} s on average the run needs about {} of them; \
                 raise integrator.max_steps, or change {}",
                fast.describe(),
                significant(mean),
                significant(needed.round()),
                fast.fields
            )
        }
    }
}

/// The ratio `r` of a step to a time scale in words: `1/10000 of`,
/// `17 times`.
fn share(r: f64) -> String {
    if r > 0.0 && r < 1.0 {
        format!("1/{} of", significant((1.0 / r).round()))
    } else {
        format!("{} times", significant(r))
    }
}
