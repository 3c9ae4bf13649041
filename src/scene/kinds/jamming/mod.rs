//! Scene kind `jamming`: the quasi-static jamming diagram and wedging angle
//! of the compliant-contact paper's §4 over lists of clearance ratios, friction coefficients and
//! insertion depths (`src/jamming`, `docs/jamming.md`).
//!
//! ```toml
//! kind = "jamming"
//! [jamming]
//! r_m = 0.0125                 # peg radius r, m
//! c = [0.002, 0.01]            # clearance ratios (D − d)/D, each in (0, 1)
//! mu = [0.1, 0.3]              # friction coefficients, each > 0
//! l_m = [0.001, 0.005, 0.01]   # insertion depths l, m, each > 0
//! ```
//!
//! Writes `<out>/<name>.corners.csv` (`l_m,c,mu,kind,fx_over_fz,m_over_rfz`:
//! every corner of Whitney's small-angle parallelogram and of the exact
//! finite-angle one; no exact rows where two-point contact is impossible),
//! `<out>/<name>.wedging.csv` (`c,mu,theta_wedge_rad`; `inf` where wedging is
//! impossible at any tilt), `<out>/<name>.sensitivities.csv`
//! (`l_m,c,mu,kind,quantity,value,d_dr,d_dc,d_dmu,d_dl`: the corners P₁ and
//! Q, the two-point line and the tilt of each parallelogram, and the
//! wedging angles (`l_m` empty), with their generated derivatives,
//! `crate::jamming::sensitivities`) and `<out>/<name>.svg` (the diagrams,
//! Fig. 6 style). An optional `[sweep]` table adds the dynamic check of one
//! diagram ([`sweep`]).

pub(crate) mod comparison;
pub(crate) mod figure;
pub mod ranges;
pub mod sweep;

use serde::Deserialize;

use crate::error::{RunError, SceneError, SceneErrors};
use crate::jamming::dynamic::SweepSetup;
use crate::jamming::table;
use crate::output::csv::format_f64;
use crate::output::names::Part;
use crate::output::plot::Figure;
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::limits::try_with_capacity;
use crate::scene::summary::{Metric, RunSummary};
use crate::scene::validate::Checker;
use sweep::SweepParams;

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "jamming",
    about: "jamming diagram (Whitney and exact) and wedging angle over c, mu, depth lists",
    parse,
    ranges: &[ranges::JAMMING, ranges::SWEEP],
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: JammingScene = doc.body()?;
    s.check()?;
    Ok(Box::new(s))
}

/// The `[jamming]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JammingParams {
    /// Peg radius r, m.
    pub r_m: f64,
    /// Clearance ratios c = (D − d)/D.
    pub c: Vec<f64>,
    /// Friction coefficients μ.
    pub mu: Vec<f64>,
    /// Insertion depths l, m.
    pub l_m: Vec<f64>,
}

/// A `jamming` scene.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JammingScene {
    /// Geometry, friction and depths.
    pub jamming: JammingParams,
    /// Optional dynamic sweep.
    #[serde(default)]
    pub sweep: Option<SweepParams>,
    /// The sweep's model, built by `parse` after the checks.
    #[serde(skip)]
    setup: Option<SweepSetup>,
}

fn check_list(
    c: &mut Checker,
    field: &str,
    values: &[f64],
    ok: impl Fn(f64) -> bool,
    reason: &str,
) {
    if values.is_empty() {
        c.push(SceneError::invalid(
            field,
            values,
            "must list at least one value",
        ));
    }
    for (i, &v) in values.iter().enumerate() {
        let name = format!("{field}[{i}]");
        if !v.is_finite() {
            c.push(SceneError::invalid(name, v, "must be a finite number"));
        } else if !ok(v) {
            c.push(SceneError::invalid(name, v, reason));
        }
    }
}

impl JammingScene {
    /// Validates every field, reporting all problems.
    pub fn check(&self) -> Result<(), SceneErrors> {
        let p = &self.jamming;
        let mut c = Checker::default();
        c.positive("jamming.r_m", p.r_m);
        let open_unit = |v: f64| v > 0.0 && v < 1.0;
        check_list(&mut c, "jamming.c", &p.c, open_unit, "must lie in (0, 1)");
        check_list(&mut c, "jamming.mu", &p.mu, |v| v > 0.0, "must be positive");
        check_list(
            &mut c,
            "jamming.l_m",
            &p.l_m,
            |v| v > 0.0,
            "must be positive",
        );
        let [r_m, c_range, mu, l_m] = ranges::JAMMING else {
            return c.finish();
        };
        r_m.check(&mut c, p.r_m);
        for (range, field, values) in [
            (c_range, "c", &p.c),
            (mu, "mu", &p.mu),
            (l_m, "l_m", &p.l_m),
        ] {
            for (i, &v) in values.iter().enumerate() {
                range.check_as(&mut c, &format!("jamming.{field}[{i}]"), v);
            }
            c.distinct(&format!("jamming.{field}"), values);
        }
        c.finish()
    }
}

impl Written for JammingScene {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        use crate::scene::limits::WorkItem;
        let mut work = vec![WorkItem::new(
            "jamming.c",
            "max_grid_points",
            self.jamming.c.len() as f64
                * self.jamming.mu.len() as f64
                * self.jamming.l_m.len() as f64,
            256.0,
        )];
        if let Some(s) = &self.sweep {
            let n = s.n as f64;
            work.push(WorkItem::new("sweep.n", "max_runs", n * n, 256.0).with_value(n));
        }
        work
    }

    fn build(mut self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        if let Some(sweep) = &self.sweep {
            self.setup = Some(sweep.prepare()?);
        }
        Ok(self)
    }
}

impl Scene for JammingScene {
    fn describe(&self) -> String {
        let p = &self.jamming;
        let mut text = format!(
            "jamming diagram and wedging angle, r = {} m, c = {:?}, mu = {:?}, l = {:?} m",
            p.r_m, p.c, p.mu, p.l_m
        );
        if let Some(s) = &self.sweep {
            text.push_str(&format!(
                "; dynamic sweep {n} x {n} at c = {}, mu = {}, l = {} m, {} ({}), {} friction, {}",
                s.c,
                s.mu,
                s.l_m,
                s.method().name(),
                s.method_reason(),
                match s.friction_law {
                    sweep::SweepFrictionLaw::Regularized => "regularized",
                    sweep::SweepFrictionLaw::Elastic => "elastic",
                },
                if s.contact_damping > 0.0 {
                    format!("contact damping alpha = {} s/m", s.contact_damping)
                } else {
                    "elastic contacts".to_owned()
                },
                n = s.n
            ));
        }
        text
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let p = &self.jamming;
        // The tables' rows (eight corners per point) and the sweep's runs,
        // reserved first: with limits raised past the machine a typed
        // error, not an aborted process.
        let points = p.c.len() * p.mu.len() * p.l_m.len();
        drop(try_with_capacity::<table::CornerRow>(
            points.saturating_mul(8),
            "grid points",
            "max_grid_points",
        )?);
        if let Some(s) = &self.sweep {
            drop(try_with_capacity::<crate::jamming::dynamic::DynamicPoint>(
                s.n.saturating_mul(s.n).saturating_mul(2),
                "sweep runs",
                "max_runs",
            )?);
        }
        let corners = table::corner_rows(p.r_m, &p.c, &p.mu, &p.l_m)?;
        let wedging = table::wedging_rows(p.r_m, &p.c, &p.mu)?;

        let header = ["l_m", "c", "mu", "kind", "fx_over_fz", "m_over_rfz"];
        let mut w = ctx.table(Part::Sub("corners"), &header)?;
        for row in &corners {
            let cells = [
                format_f64(row.l),
                format_f64(row.c),
                format_f64(row.mu),
                row.kind.name().to_string(),
                format_f64(row.corner[0]),
                format_f64(row.corner[1]),
            ];
            w.row_cells(&cells.each_ref().map(String::as_str))?;
        }
        w.finish()?;

        let mut w = ctx.table(Part::Sub("wedging"), &["c", "mu", "theta_wedge_rad"])?;
        // `inf`: no tilt wedges the peg (documented above), not an overflow.
        w.allow_infinite("theta_wedge_rad");
        for row in &wedging {
            let theta = row.theta.map_or_else(|| "inf".to_string(), format_f64);
            w.row_cells(&[&format_f64(row.c), &format_f64(row.mu), &theta])?;
        }
        w.finish()?;

        drop(try_with_capacity::<table::SensitivityRow>(
            points.saturating_mul(2 * table::QUANTITIES.len()),
            "grid points",
            "max_grid_points",
        )?);
        let derivatives = table::sensitivity_rows(p.r_m, &p.c, &p.mu, &p.l_m)?;
        let header = [
            "l_m", "c", "mu", "kind", "quantity", "value", "d_dr", "d_dc", "d_dmu", "d_dl",
        ];
        let mut w = ctx.table(Part::Sub("sensitivities"), &header)?;
        for row in &derivatives {
            let g = &row.gradient;
            let cells = [
                row.l.map_or_else(String::new, format_f64),
                format_f64(row.c),
                format_f64(row.mu),
                row.kind.to_string(),
                row.quantity.to_string(),
                format_f64(row.value),
                format_f64(g.r),
                format_f64(g.c),
                format_f64(g.mu),
                format_f64(g.l),
            ];
            w.row_cells(&cells.each_ref().map(String::as_str))?;
        }
        w.finish()?;

        let mut fig = Figure::new();
        fig.panels = figure::panels(&corners);
        ctx.figure(Part::Main, &fig)?;

        let impossible = p.c.len() * p.mu.len() * p.l_m.len() * 8 - corners.len();
        let mut metrics = vec![Metric::new(
            "exact corners left out (two-point contact impossible)",
            impossible as f64,
            "",
        )];
        if let (Some(params), Some(setup)) = (&self.sweep, &self.setup) {
            metrics.extend(sweep::run(params, setup, ctx)?);
        }
        Ok(RunSummary {
            integration: None,
            metrics,
            ..RunSummary::default()
        })
    }
}
