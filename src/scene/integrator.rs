//! The `[integrator]` table shared by all scene kinds: which method, its
//! tolerances or step, the time span and the output sampling interval.
//!
//! ```toml
//! [integrator]
//! method = "dopri5"        # "auto" (default) | "dopri5" | "rk4" | "rodas3" (alias "rosenbrock") | "rodas4"
//! rtol = 1e-9              # relative tolerance (adaptive methods)
//! atol = 1e-12             # absolute tolerance, > 0 (adaptive methods)
//! atol_scale = { wx = 50.0 } # named state components' atol is atol times this, > 0
//! h = 1e-3                 # fixed step, s (rk4 only; required there)
//! t0 = 0.0                 # start time, s (default 0)
//! t_end = 10.0             # end time, s
//! output_interval = 0.01   # sampling of the CSV/SVG output, s
//! max_steps = 1000000      # step budget (default 10^6)
//! ```

use serde::de::Error as _;
use serde::{Deserialize, Deserializer};

use crate::integrate::MethodKind;

use crate::error::{SceneError, SceneErrors};
use crate::scene::limits::{ReserveError, WorkItem, sample_count, try_with_capacity};
use crate::scene::validate::Checker;

/// The output times of an [`IntegratorSpec`]: `t0 + i dt` for
/// `i = 0, …, n`, then `t_end` if the span is not a whole number of
/// intervals. An iterator, so that the times are never held all at once
/// unless the caller collects them.
#[derive(Debug, Clone)]
pub struct OutputTimes {
    t0: f64,
    dt: f64,
    t_end: f64,
    next: u64,
    n: u64,
    extra: bool,
}

impl Iterator for OutputTimes {
    type Item = f64;

    fn next(&mut self) -> Option<f64> {
        if self.next <= self.n {
            let t = self.t0 + self.next as f64 * self.dt;
            self.next += 1;
            Some(t)
        } else if self.extra {
            self.extra = false;
            Some(self.t_end)
        } else {
            None
        }
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self
            .n
            .saturating_add(1)
            .saturating_sub(self.next)
            .saturating_add(u64::from(self.extra));
        let left = usize::try_from(left).unwrap_or(usize::MAX);
        (left, Some(left))
    }
}

/// Integration method selected by `integrator.method`: a method of the
/// integrators' one vocabulary ([`MethodKind`], same names, the alias
/// `"rosenbrock"` for `"rodas3"` included) or `"auto"`.
///
/// Without `method` (or with `"auto"`) the scene kind chooses: the
/// compliant-contact scenes RODAS4 (their Hertz contacts and regularized
/// friction are stiff), every other kind DOPRI5; the run summary names
/// the method used and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Chosen by the scene kind (see the type's documentation).
    #[default]
    Auto,
    /// The method named in the scene file.
    Named(MethodKind),
}

/// Every spelling `integrator.method` accepts, for the error message.
const METHOD_NAMES: &[&str] = &["auto", "rk4", "dopri5", "rodas3", "rosenbrock", "rodas4"];

impl Method {
    /// Name as written in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Method::Auto => "auto",
            Method::Named(m) => m.name(),
        }
    }

    /// The method called `name` in a scene file ([`MethodKind::from_name`]
    /// or `"auto"`).
    pub fn from_name(name: &str) -> Option<Method> {
        match name {
            "auto" => Some(Method::Auto),
            _ => MethodKind::from_name(name).map(Method::Named),
        }
    }

    /// The named method, `None` for [`Method::Auto`].
    pub fn kind(self) -> Option<MethodKind> {
        match self {
            Method::Auto => None,
            Method::Named(m) => Some(m),
        }
    }

    /// Whether the method chooses its own step from `rtol`/`atol` (`auto`
    /// always resolves to an adaptive method).
    pub fn is_adaptive(self) -> bool {
        self.kind().is_none_or(MethodKind::is_adaptive)
    }
}

impl From<MethodKind> for Method {
    fn from(m: MethodKind) -> Method {
        Method::Named(m)
    }
}

impl<'de> Deserialize<'de> for Method {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Method, D::Error> {
        let name = String::deserialize(d)?;
        Method::from_name(&name).ok_or_else(|| D::Error::unknown_variant(&name, METHOD_NAMES))
    }
}

/// How a scene kind resolves [`Method::Auto`]: the method and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DefaultMethod {
    /// The method used when the scene names none.
    pub method: Method,
    /// Why, for the run summary.
    pub reason: &'static str,
}

impl DefaultMethod {
    /// The default of non-stiff scene kinds.
    pub const NON_STIFF: DefaultMethod = DefaultMethod {
        method: Method::Named(MethodKind::Dopri5),
        reason: "default for non-stiff scenes",
    };
    /// The default of compliant-contact scene kinds.
    pub const STIFF_CONTACT: DefaultMethod = DefaultMethod {
        method: Method::Named(MethodKind::Rodas4),
        reason: "default for compliant contact: stiff Hertz contacts and regularized friction",
    };
}

/// The `[integrator]` table as written; call [`IntegratorSpec::check`].
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct IntegratorSpec {
    /// Integration method ([`Method::Auto`] when not written).
    #[serde(default)]
    pub method: Method,
    /// Relative tolerance, dimensionless (adaptive methods).
    #[serde(default = "default_rtol")]
    pub rtol: f64,
    /// Absolute tolerance, in the state's units (adaptive methods).
    #[serde(default = "default_atol")]
    pub atol: f64,
    /// Factors on `atol` for state components by name (the kind's state
    /// names, e.g. `wx` for the 3-D peg's angular velocity, rad/s), for
    /// components whose units or scale differ from the rest: the absolute
    /// tolerance of a named component is `atol` times its factor, so that
    /// it follows `atol` when that is tightened; the others keep `atol`.
    /// Empty by default.
    #[serde(default)]
    pub atol_scale: std::collections::BTreeMap<String, f64>,
    /// Fixed step size, s (required for `rk4`; initial step hint otherwise).
    pub h: Option<f64>,
    /// Start time, s.
    #[serde(default)]
    pub t0: f64,
    /// End time, s.
    pub t_end: f64,
    /// Output sampling interval, s (default: 1/1000 of the span).
    pub output_interval: Option<f64>,
    /// Maximum number of steps before giving up.
    #[serde(default = "default_max_steps")]
    pub max_steps: usize,
}

/// Smallest accepted relative tolerance: ten times f64's rounding unit
/// u = 2^-53 ≈ 1.1e-16, below which no step can meet the error test.
pub const MIN_RTOL: f64 = 1e-15;

/// Checks an adaptive method's tolerances `<table>.rtol` in
/// `[MIN_RTOL, 1)` and `<table>.atol > 0`, pushing each violation to `c`.
pub(crate) fn check_tolerances(c: &mut Checker, table: &str, rtol: f64, atol: f64) {
    let f = |k: &str| format!("{table}.{k}");
    let rtol = c.positive(&f("rtol"), rtol);
    if rtol >= 1.0 {
        c.push(SceneError::invalid(f("rtol"), rtol, "must be less than 1"));
    } else if rtol > 0.0 && rtol < MIN_RTOL {
        c.push(SceneError::invalid(
            f("rtol"),
            rtol,
            "must be at least 1e-15: a relative error below f64's rounding unit (1.1e-16) cannot be met, and the step control shrinks the step without end",
        ));
    }
    c.positive(&f("atol"), atol);
}

fn default_rtol() -> f64 {
    1e-8
}
fn default_atol() -> f64 {
    1e-10
}
fn default_max_steps() -> usize {
    1_000_000
}

impl IntegratorSpec {
    /// The absolute tolerance of each leading component of a state whose
    /// components are called `names`: `atol` times the factor of
    /// `atol_scale` where it names the component, `atol` before the last
    /// one it names; empty when it names none.
    ///
    /// # Errors
    /// [`SceneError::Invalid`] naming `<table>.atol_scale.<name>` for a
    /// name that is not one of `names`, with the names there are.
    pub fn component_atol(&self, table: &str, names: &[&str]) -> Result<Vec<f64>, SceneError> {
        let mut atol = Vec::new();
        for (name, &value) in &self.atol_scale {
            let Some(i) = names.iter().position(|n| n == name) else {
                let known = if names.is_empty() {
                    "this scene kind's state has no named components".to_string()
                } else {
                    format!("the state's components are {}", names.join(", "))
                };
                return Err(SceneError::invalid(
                    format!("{table}.atol_scale.{name}"),
                    value,
                    format!("names no state component: {known}"),
                ));
            };
            if atol.len() <= i {
                atol.resize(i + 1, self.atol);
            }
            atol[i] = self.atol * value;
        }
        Ok(atol)
    }

    /// The integrators' [`Options`](crate::integrate::Options) with this
    /// table's tolerances: `rtol`, `atol` and, for a state whose
    /// components are called `names`, the components' tolerances of
    /// [`IntegratorSpec::component_atol`]; every other option at its
    /// default.
    ///
    /// # Errors
    /// As [`IntegratorSpec::component_atol`].
    pub fn tolerances(
        &self,
        table: &str,
        names: &[&str],
    ) -> Result<crate::integrate::Options, SceneError> {
        Ok(crate::integrate::Options {
            component_atol: self.component_atol(table, names)?,
            ..crate::integrate::Options::with_tolerances(self.rtol, self.atol)
        })
    }

    /// The spec with [`Method::Auto`] replaced by `default`'s method, and
    /// why that method runs (named by the scene, or `default`'s reason).
    pub fn resolved(&self, default: DefaultMethod) -> (IntegratorSpec, &'static str) {
        let mut spec = self.clone();
        if spec.method == Method::Auto {
            spec.method = default.method;
            (spec, default.reason)
        } else {
            (spec, "named by the scene")
        }
    }

    /// Validates the table; `table` is its dotted name (`"integrator"`).
    pub fn check(&self, table: &str) -> Result<(), SceneErrors> {
        let f = |k: &str| format!("{table}.{k}");
        let mut c = Checker::default();
        let t0 = c.finite(&f("t0"), self.t0);
        let t_end = c.greater_than(&f("t_end"), self.t_end, &f("t0"), t0);
        let span = t_end - t0;
        if self.method.is_adaptive() {
            check_tolerances(&mut c, table, self.rtol, self.atol);
            for (name, &scale) in &self.atol_scale {
                let field = f(&format!("atol_scale.{name}"));
                let scale = c.positive(&field, scale);
                let atol = scale * self.atol;
                let least = crate::integrate::MIN_ATOL;
                if scale > 0.0 && self.atol > 0.0 && !(atol.is_finite() && atol >= least) {
                    c.push(SceneError::invalid(
                        field,
                        scale,
                        format!(
                            "atol times it ({atol:e}) must be a finite number of at least \
                             {least:e} (the smallest normal f64)"
                        ),
                    ));
                }
            }
        }
        match (self.method, self.h) {
            (Method::Named(MethodKind::Rk4), None) => c.push(SceneError::Missing { field: f("h") }),
            (_, Some(h)) => {
                let h = c.positive(&f("h"), h);
                if c.is_ok() && h > span {
                    c.push(SceneError::invalid(
                        f("h"),
                        h,
                        format!("must not exceed t_end - t0 = {span:?}"),
                    ));
                }
            }
            (_, None) => {}
        }
        if let Some(dt) = self.output_interval {
            c.positive(&f("output_interval"), dt);
        }
        if self.max_steps == 0 {
            c.push(SceneError::invalid(f("max_steps"), 0, "must be at least 1"));
        }
        c.finish()
    }

    /// The output sampling interval, s.
    pub fn output_interval(&self) -> f64 {
        self.output_interval
            .unwrap_or((self.t_end - self.t0) / 1000.0)
    }

    /// Output sample times `t0, t0 + dt, ...`, ending exactly at `t_end`,
    /// generated lazily (nothing is allocated here; the number of samples
    /// is bounded by `[limits] max_output_samples`, see [`IntegratorSpec::work`]).
    pub fn output_times(&self) -> OutputTimes {
        let dt = self.output_interval();
        let n = ((self.t_end - self.t0) / dt).floor();
        // A span that is not a number of whole steps gets t_end appended.
        let last = if n >= 0.0 { n } else { 0.0 };
        let extra = self.t_end - (self.t0 + last * dt) > 1e-9 * dt;
        OutputTimes {
            t0: self.t0,
            dt,
            t_end: self.t_end,
            next: 0,
            // `as` saturates: an infinite count stays a (lazy) huge one.
            n: last as u64,
            extra,
        }
    }

    /// [`Self::output_times`] collected, the memory reserved first:
    /// a [`ReserveError`] naming `max_output_samples` rather than an
    /// aborted process when the limits were raised past the machine.
    ///
    /// # Errors
    /// The memory for the times cannot be reserved.
    pub fn try_output_times(&self) -> Result<Vec<f64>, ReserveError> {
        let count = sample_count(self.t0, self.t_end, self.output_interval());
        // `as` saturates: an infinite count asks for `usize::MAX`, refused.
        let mut times = try_with_capacity(count as usize, "output samples", "max_output_samples")?;
        times.extend(self.output_times());
        Ok(times)
    }

    /// The work this table asks for: the stored output samples (field
    /// `output_interval`, or `t_end` when the interval is the default) and
    /// the step budget (`max_steps`). `table` is the table's dotted name.
    pub fn work(&self, table: &str) -> Vec<WorkItem> {
        let samples = sample_count(self.t0, self.t_end, self.output_interval());
        let sample_field = if self.output_interval.is_some() {
            "output_interval"
        } else {
            "t_end"
        };
        vec![
            // A sample stores the time, a state of a few dozen numbers and
            // its output columns: 512 bytes is a generous bound.
            WorkItem::new(
                format!("{table}.{sample_field}"),
                "max_output_samples",
                samples,
                512.0,
            )
            .with_value(if self.output_interval.is_some() {
                self.output_interval()
            } else {
                self.t_end
            }),
            WorkItem::new(
                format!("{table}.max_steps"),
                "max_steps",
                self.max_steps as f64,
                0.0,
            )
            .with_value(self.max_steps as f64),
        ]
    }

    /// One-line description, e.g. `dopri5 rtol=1e-9 atol=1e-12, t in [0, 10] s`.
    pub fn describe(&self) -> String {
        let m = match (self.method, self.h) {
            (Method::Named(MethodKind::Rk4), Some(h)) => format!("rk4 h={h:e} s"),
            (m, _) => {
                let mut d = format!("{} rtol={:e} atol={:e}", m.name(), self.rtol, self.atol);
                for (name, scale) in &self.atol_scale {
                    d.push_str(&format!(" atol[{name}]={:e}", self.atol * scale));
                }
                d
            }
        };
        format!(
            "{m}, t in [{}, {}] s",
            crate::scene::numbers::significant(self.t0),
            crate::scene::numbers::significant(self.t_end)
        )
    }
}
