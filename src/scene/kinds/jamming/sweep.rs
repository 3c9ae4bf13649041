//! The optional `[sweep]` table of the `jamming` scene: the dynamic check of
//! the jamming diagram (`crate::jamming::dynamic`).
//!
//! ```toml
//! [sweep]
//! r_m = 0.0125           # peg radius, m
//! c = 0.01               # clearance ratio
//! mu = 0.3               # friction coefficient
//! l_m = 0.01             # insertion depth (two-point contact must exist), m
//! fz_n = 20.0            # axial force F_z, N
//! peg_length_m = 0.1     # steel cylinder length (mass, inertia), m
//! fx_over_fz_max = 4.5   # grid: F_x/F_z from −max to max
//! m_over_rfz_max = 6.0   # grid: M/(r F_z) from −max to max
//! n = 13                 # grid points per axis (≥ 3)
//! t_max_s = 0.2          # longest simulated time per run, s
//! advance_m = 0.001      # advance of the bottom face that counts as inserted, m
//! window_s = 0.05        # classification window: < 2 µm advance in it = stuck, s
//! method = "rodas4"      # optional: "rodas4" (default) | "rodas3" | "dopri5"
//! rtol = 1e-4            # optional (default 1e-4): relative tolerance of every run
//! atol = 1e-8            # optional (default 1e-8): absolute tolerance (m, rad, m/s, rad/s)
//! early_stop = true      # optional (default true): classify a stuck run once
//!                        # it has settled (compliant_peg::Settle), not at its window's end
//! friction_law = "regularized"  # optional: "regularized" (default) | "elastic"
//!                        # (Hertz–Mindlin capped by Coulomb: sticks without creep)
//! contact_damping = 1.5  # optional (default 0: elastic): Hunt–Crossley alpha, s/m
//!                        # (restitution about 0.9 at 0.1 m/s)
//! ```
//!
//! Without `method` every run uses RODAS4 with the generated exact
//! Jacobian: the contacts (Hertz periods of about a millisecond) and the
//! regularized friction law (time constant `m v_s / (μ f)`, microseconds)
//! make the runs stiff, and an explicit method's steps are bounded by that
//! time constant however smooth the motion (see docs/BENCHMARKS.md).
//!
//! Writes `<out>/<name>.sweep.csv` (`fx_over_fz,m_over_rfz,class,lean_plus,
//! lean_minus,margin_exact,margin_whitney,margin_exact_d_dr,
//! margin_exact_d_dc,margin_exact_d_dmu,margin_exact_d_dl`: the margins of
//! the grid point to both parallelograms, and the derivatives of the margin
//! to the exact one along the peg radius, the clearance ratio, the friction
//! and the requested depth, [`crate::jamming::sweep_margin`]; empty where
//! two edges are equally near) and `<out>/<name>.sweep.svg` (simulated
//! classes as markers, exact parallelogram solid, Whitney's dashed).

use std::sync::Mutex;

use serde::de::Error as _;
use serde::{Deserialize, Deserializer};

use super::figure::{X_LABEL, Y_LABEL, parallelogram_series};
use crate::error::{RunError, SceneError, SceneErrors};
use crate::integrate::MethodKind;
use crate::jamming::PegHole;
use crate::jamming::diagram::whitney_parallelogram;
use crate::jamming::dynamic::{self, DynamicPoint, SweepSetup, SweepSpec};
use crate::jamming::sweep::{self, RunClass};
use crate::output::csv::format_f64;
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series, Style};
use crate::scene::context::RunContext;
use crate::scene::summary::Metric;
use crate::scene::validate::Checker;

/// The `[sweep]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepParams {
    /// Peg radius r, m.
    pub r_m: f64,
    /// Clearance ratio.
    pub c: f64,
    /// Friction coefficient.
    pub mu: f64,
    /// Insertion depth, m.
    pub l_m: f64,
    /// Axial force F_z, N.
    pub fz_n: f64,
    /// Peg length, m.
    pub peg_length_m: f64,
    /// Grid half-width in F_x/F_z.
    pub fx_over_fz_max: f64,
    /// Grid half-height in M/(r F_z).
    pub m_over_rfz_max: f64,
    /// Grid points per axis.
    pub n: usize,
    /// Longest simulated time per run, s.
    pub t_max_s: f64,
    /// Advance that counts as inserted, m.
    pub advance_m: f64,
    /// Classification window, s.
    pub window_s: f64,
    /// Integrator of the runs (default RODAS4; `rodas4`, `rodas3` or
    /// `dopri5`).
    #[serde(default, deserialize_with = "sweep_method")]
    pub method: Option<MethodKind>,
    /// Relative tolerance of every run (default 1e-4: the shipped sweep's
    /// classes are the same at 1e-3, 1e-4, 1e-5 and 1e-6).
    #[serde(default = "default_rtol")]
    pub rtol: f64,
    /// Absolute tolerance of every run (default 1e-8; m, rad, m/s, rad/s).
    #[serde(default = "default_atol")]
    pub atol: f64,
    /// Early stop of settled runs (default true).
    #[serde(default = "yes")]
    pub early_stop: bool,
    /// Friction law of the contacts (default regularized).
    #[serde(default)]
    pub friction_law: SweepFrictionLaw,
    /// Hunt–Crossley damping `α` of the contacts, s/m (default 0: elastic
    /// contacts; see [`SweepSpec::contact_damping`]).
    #[serde(default)]
    pub contact_damping: f64,
}

/// `sweep.friction_law`: the tangential law at the contacts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SweepFrictionLaw {
    /// Regularized Coulomb with `v_s = 1e-5 m/s`.
    #[default]
    Regularized,
    /// Hertz–Mindlin tangential compliance capped by Coulomb.
    Elastic,
}

fn default_rtol() -> f64 {
    1e-4
}

fn default_atol() -> f64 {
    1e-8
}

fn yes() -> bool {
    true
}

/// The spellings `sweep.method` accepts (the adaptive methods of
/// [`MethodKind`]: an RK4 run would need a step).
const SWEEP_METHODS: &[&str] = &["rodas4", "rodas3", "dopri5"];

/// `sweep.method`: one of [`SWEEP_METHODS`], by [`MethodKind::from_name`].
fn sweep_method<'de, D: Deserializer<'de>>(d: D) -> Result<Option<MethodKind>, D::Error> {
    let name = String::deserialize(d)?;
    SWEEP_METHODS
        .contains(&name.as_str())
        .then(|| MethodKind::from_name(&name))
        .flatten()
        .map(Some)
        .ok_or_else(|| D::Error::unknown_variant(&name, SWEEP_METHODS))
}

impl SweepParams {
    /// The integrator of the runs: as named, else RODAS4.
    pub fn method(&self) -> MethodKind {
        self.method.unwrap_or(MethodKind::Rodas4)
    }

    /// Why the runs use [`Self::method`], for the run summary.
    pub fn method_reason(&self) -> &'static str {
        match self.method {
            Some(_) => "named by the scene",
            None => "default for compliant contact: stiff Hertz contacts and regularized friction",
        }
    }

    /// Checks every field and builds the model; errors name `sweep.<field>`.
    pub fn prepare(&self) -> Result<SweepSetup, SceneErrors> {
        use super::ranges as r;
        let mut c = Checker::default();
        let [r_m, cr, mu, l_m, peg_length, damping, ..] = r::SWEEP else {
            return Err(SceneErrors::from(SceneError::invalid(
                "sweep",
                "",
                "no ranges",
            )));
        };
        r_m.require(&mut c, self.r_m);
        cr.require(&mut c, self.c);
        mu.require(&mut c, self.mu);
        l_m.require(&mut c, self.l_m);
        peg_length.require(&mut c, self.peg_length_m);
        damping.require(&mut c, self.contact_damping);
        r::FZ.require(&mut c, self.fz_n);
        r::FX_MAX.require(&mut c, self.fx_over_fz_max);
        r::M_MAX.require(&mut c, self.m_over_rfz_max);
        let t_max = r::T_MAX.require(&mut c, self.t_max_s);
        r::ADVANCE.require(&mut c, self.advance_m);
        r::WINDOW
            .within(f64::NAN, if t_max.is_finite() { t_max } else { f64::NAN })
            .require(&mut c, self.window_s);
        r::N.check(&mut c, self.n as f64);
        crate::scene::integrator::check_tolerances(&mut c, "sweep", self.rtol, self.atol);
        r::ATOL.check(&mut c, self.atol);
        let method = self.method();
        let integrator = c.check(
            method.with_step(None).ok_or_else(|| {
                SceneError::invalid(
                    "sweep.method",
                    method.name(),
                    "must be an adaptive method (rodas4, rodas3 or dopri5)",
                )
            }),
            crate::integrate::Method::Rodas4,
        );
        c.finish()?;
        let peg = PegHole::try_new(self.r_m, self.c, self.mu)
            .map_err(|e| SceneError::invalid(format!("sweep.{}", e.field), e.value, e.reason))?;
        let refused = |e: crate::hertz::HertzError| self.refusal(e);
        let spec = SweepSpec {
            peg,
            depth: self.l_m,
            fz: self.fz_n,
            peg_length: self.peg_length_m,
            t_max: self.t_max_s,
            advance: self.advance_m,
            window: self.window_s,
            integrator,
            rtol: self.rtol,
            atol: self.atol,
            early_stop: self.early_stop,
            contact_damping: self.contact_damping,
        };
        let law = match self.friction_law {
            SweepFrictionLaw::Regularized => crate::compliant_peg::FrictionLaw::Regularized,
            SweepFrictionLaw::Elastic => crate::compliant_peg::FrictionLaw::Elastic,
        };
        SweepSetup::new(spec)
            .and_then(|s| s.with_friction_law(law))
            .map_err(refused)
    }

    /// The compliant model's refusal of the sweep, named by the `[sweep]`
    /// field (and its value as written) that the model's field comes from.
    fn refusal(&self, e: crate::hertz::HertzError) -> SceneErrors {
        use crate::hertz::HertzError;
        let (field, value) = match &e {
            HertzError::Invalid { field, .. } => match field.as_str() {
                "damping" => ("contact_damping", self.contact_damping),
                "friction" => ("mu", self.mu),
                "peg_radius" | "hole_diameter" => ("r_m", self.r_m),
                "mass" | "inertia" | "com_height" => ("peg_length_m", self.peg_length_m),
                // The depth, and the tilt of the two-point lean at it.
                _ => ("l_m", self.l_m),
            },
            // A contact that is no point contact at the start: the lean of
            // the requested depth.
            _ => ("l_m", self.l_m),
        };
        SceneErrors::from(SceneError::invalid(
            format!("sweep.{field}"),
            value,
            format!("the compliant model refused the sweep: {e}"),
        ))
    }
}

/// Runs the sweep with a progress line and writes its CSV and SVG; returns
/// the comparison metrics.
pub fn run(
    params: &SweepParams,
    setup: &SweepSetup,
    ctx: &mut RunContext,
) -> Result<Vec<Metric>, RunError> {
    let (grid, points) = {
        let progress = Mutex::new(&mut ctx.progress);
        let report = |done: usize, total: usize| {
            if let Ok(mut p) = progress.lock() {
                p.update_count(done, total, "sweep run");
            }
        };
        dynamic::run(
            setup,
            params.fx_over_fz_max,
            params.m_over_rfz_max,
            params.n,
            report,
        )?
    };
    ctx.progress.finish();
    ctx.progress.check_interrupt()?;
    let whitney = whitney_parallelogram(&setup.spec.peg, setup.depth)?;

    let header = [
        "fx_over_fz",
        "m_over_rfz",
        "class",
        "lean_plus",
        "lean_minus",
        "margin_exact",
        "margin_whitney",
        "margin_exact_d_dr",
        "margin_exact_d_dc",
        "margin_exact_d_dmu",
        "margin_exact_d_dl",
    ];
    let mut w = ctx.table(Part::Sub("sweep"), &header)?;
    for p in &points {
        let q = p.point.ratio;
        let m = setup.margin_gradient(q);
        // `+ 0.0`: a zero derivative is written `0` whatever its sign.
        let d = |k: usize| {
            m.gradient
                .map_or_else(String::new, |g| format_f64(g.to_array()[k] + 0.0))
        };
        let cells = [
            format_f64(q[0]),
            format_f64(q[1]),
            p.point.class.name().to_string(),
            p.lean_plus.name().to_string(),
            p.lean_minus.name().to_string(),
            format_f64(setup.diagram.margin(q)),
            format_f64(whitney.margin(q)),
            d(0),
            d(1),
            d(2),
            d(3),
        ];
        w.row_cells(&cells.each_ref().map(String::as_str))?;
    }
    w.finish()?;
    ctx.figure(Part::Sub("sweep"), &figure(setup, &whitney, &points))?;

    let plain: Vec<_> = points.iter().map(|p| p.point).collect();
    let exact = sweep::check(&setup.diagram, &plain, grid.resolution());
    let small = sweep::check(&whitney, &plain, grid.resolution());
    let tolerances = format!(
        "sweep.method = {}, sweep.rtol = {}, sweep.atol = {}",
        params.method().name(),
        crate::scene::numbers::significant(params.rtol),
        crate::scene::numbers::significant(params.atol)
    );
    Ok(super::comparison::comparison(
        points.len(),
        &exact,
        &small,
        &tolerances,
    ))
}

fn figure(
    setup: &SweepSetup,
    whitney: &crate::jamming::diagram::Parallelogram,
    points: &[DynamicPoint],
) -> Figure {
    let title = format!(
        "dynamic sweep, c = {}, mu = {}, l = {:.2} mm, theta = {:.4} rad",
        setup.spec.peg.c(),
        setup.spec.peg.mu(),
        setup.depth * 1e3,
        setup.theta
    );
    let mut panel = Panel::new(&title, X_LABEL, Y_LABEL);
    let classes = [
        (RunClass::Inserted, 2),
        (RunClass::Jammed, 1),
        (RunClass::Wedged, 4),
        (RunClass::Other, 7),
        (RunClass::Failed, 3),
    ];
    for (class, colour) in classes {
        let pts: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.point.class == class)
            .map(|p| (p.point.ratio[0], p.point.ratio[1]))
            .collect();
        if !pts.is_empty() {
            panel.series.push(
                Series::line(format!("simulated: {}", class.name()), pts)
                    .styled(Style::Markers)
                    .colored(colour),
            );
        }
    }
    panel.series.push(parallelogram_series(
        "exact (quasi-static)",
        &setup.diagram,
        Style::Solid,
        0,
    ));
    panel.series.push(parallelogram_series(
        "Whitney (small angle)",
        whitney,
        Style::Dashed,
        0,
    ));
    let mut fig = Figure::new();
    fig.panels.push(panel);
    fig.panel_height = 600;
    fig
}
