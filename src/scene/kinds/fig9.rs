//! Scene kind `fig9`: the Fig. 9 study of the rigid three-point peg — reactions of the
//! rigid peg leaning on the hole edge at K, B1, B2 under prescribed steady
//! rates γ̇ and ψ̇ (`src/rigid_peg/prescribed.rs`, `docs/rigid-peg.md`).
//!
//! ```toml
//! kind = "fig9"
//! [peg]
//! hole_diameter = 0.050   # D, m
//! peg_diameter = 0.04995  # d, m (< D)
//! height = 0.070          # H, m
//! mass = 1.0              # kg
//! gravity = 9.81          # m/s²
//! friction = 0.2          # f
//! [motion]
//! gammadot = -2.0         # 1/s; negative = alignment (towards γ0)
//! psidot = [0.0, 10.0]    # 1/s; positive = counter-clockwise from above
//! [gamma]                 # either a range ...
//! start_over_gamma0 = 1.000001   # or `start = <rad>`
//! end = 0.5               # rad
//! count = 400             # geometric in γ − γ0 (dense near γ0)
//! # values = [0.05, 0.1]  # ... or an explicit list (rad), instead of the range
//! ```
//!
//! Writes `<out>/<name>.csv` with the columns
//! `gamma,psidot,N_B1_over_mg,N_B2_over_mg,N_K_over_mg,M_gamma_over_mgD,M_psi_over_mgD,feasible`
//! and `<out>/<name>.svg` (N_B1/(m g) against γ, one curve per ψ̇,
//! infeasible stretches dashed).

use serde::Deserialize;

use crate::error::{RunError, SceneError, SceneErrors};
use crate::output::csv::format_f64;
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Scale, Series};
use crate::rigid_peg::prescribed::{Fig9Row, fig9_rows, gamma_grid};
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::limits::try_with_capacity;
use crate::scene::shared::rigid_peg::{self, PegTable, check_rate};
use crate::scene::summary::{Metric, RunSummary};
use crate::scene::validate::Checker;

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "fig9",
    about: "rigid three-point peg on the hole edge: reactions under prescribed gamma, psi rates (Fig. 9)",
    parse,
    ranges: &[rigid_peg::PEG],
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: Fig9Scene = doc.body()?;
    s.check()?;
    Ok(Box::new(s))
}

/// The `[motion]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotionTable {
    /// dγ/dt, 1/s (negative: alignment).
    pub gammadot: f64,
    /// dψ/dt values, 1/s, one curve each.
    pub psidot: Vec<f64>,
}

/// The `[gamma]` table: a range (`start` or `start_over_gamma0`, `end`,
/// `count`) or an explicit list `values`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GammaTable {
    /// First γ, rad.
    pub start: Option<f64>,
    /// First γ as a multiple of γ0 (> 1).
    pub start_over_gamma0: Option<f64>,
    /// Last γ, rad.
    pub end: Option<f64>,
    /// Number of γ values of the range (≥ 2).
    pub count: Option<usize>,
    /// Explicit γ values, rad.
    pub values: Option<Vec<f64>>,
}

/// A `fig9` scene.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Fig9Scene {
    /// Peg, hole, friction.
    pub peg: PegTable,
    /// Prescribed rates.
    pub motion: MotionTable,
    /// γ values.
    pub gamma: GammaTable,
}

impl Fig9Scene {
    /// The γ values of the scene (after [`Fig9Scene::check`]).
    pub fn gammas(&self) -> Vec<f64> {
        let g0 = self.peg.params().gamma0();
        if let Some(v) = &self.gamma.values {
            return v.clone();
        }
        let start = self
            .gamma
            .start
            .unwrap_or_else(|| g0 * self.gamma.start_over_gamma0.unwrap_or(f64::NAN));
        gamma_grid(
            g0,
            start,
            self.gamma.end.unwrap_or(f64::NAN),
            self.gamma.count.unwrap_or(2),
        )
    }

    /// The number of γ values (after [`Fig9Scene::check`]).
    fn gamma_count(&self) -> usize {
        self.gamma
            .values
            .as_ref()
            .map_or(self.gamma.count.unwrap_or(2), Vec::len)
    }

    /// Validates every field, reporting all problems.
    pub fn check(&self) -> Result<(), SceneErrors> {
        let mut c = Checker::default();
        self.peg.check_into(&mut c);
        c.finite("motion.gammadot", self.motion.gammadot);
        if self.motion.psidot.is_empty() {
            c.push(SceneError::invalid(
                "motion.psidot",
                &self.motion.psidot,
                "must list at least one rate",
            ));
        }
        let rigid = |c: &mut Checker, name: &str, rate: f64, radius: f64, r: &str| {
            check_rate(c, name, rate, radius, r);
        };
        rigid(
            &mut c,
            "motion.gammadot",
            self.motion.gammadot,
            self.peg.height,
            "H",
        );
        for (i, &w) in self.motion.psidot.iter().enumerate() {
            let name = format!("motion.psidot[{i}]");
            c.finite(&name, w);
            rigid(&mut c, &name, w, 0.5 * self.peg.peg_diameter, "d/2");
            if w == 0.0 && self.motion.gammadot == 0.0 {
                c.push(SceneError::invalid(
                    name,
                    w,
                    "with motion.gammadot = 0 nothing slides: friction has no direction",
                ));
            }
        }
        c.distinct("motion.psidot", &self.motion.psidot);
        if !c.is_ok() {
            return c.finish();
        }
        let g0 = self.peg.params().gamma0();
        let half_pi = std::f64::consts::FRAC_PI_2;
        let three_point = format!(
            "must lie above gamma0 = arccos(d/D) = {g0} rad and below pi/2 (three-point contact)"
        );
        let g = &self.gamma;
        match (&g.values, g.start, g.start_over_gamma0) {
            (Some(values), None, None) if g.end.is_none() && g.count.is_none() => {
                if values.is_empty() {
                    c.push(SceneError::invalid("gamma.values", values, "must list at least one value"));
                }
                for (i, &v) in values.iter().enumerate() {
                    if !(v > g0 && v < half_pi) {
                        c.push(SceneError::invalid(format!("gamma.values[{i}]"), v, three_point.as_str()));
                    }
                }
                c.distinct("gamma.values", values);
            }
            (None, Some(start), Some(_)) => c.push(SceneError::invalid(
                "gamma.start",
                start,
                "give either gamma.start or gamma.start_over_gamma0, not both",
            )),
            (None, start, ratio) if start.is_some() || ratio.is_some() => {
                if let Some(s) = start
                    && !(s > g0 && s < half_pi)
                {
                    c.push(SceneError::invalid("gamma.start", s, three_point.as_str()));
                }
                if let Some(r) = ratio
                    && !(r > 1.0 && g0 * r < half_pi)
                {
                    c.push(SceneError::invalid("gamma.start_over_gamma0", r, "must be > 1 (start above gamma0) and below pi/2/gamma0"));
                }
                match g.end {
                    Some(e) if e > g0 && e < half_pi => {}
                    Some(e) => c.push(SceneError::invalid("gamma.end", e, three_point.as_str())),
                    None => c.push(SceneError::Missing { field: "gamma.end".into() }),
                }
                match g.count {
                    Some(n) if n >= 2 => {}
                    Some(n) => c.push(SceneError::invalid("gamma.count", n, "must be at least 2")),
                    None => c.push(SceneError::Missing { field: "gamma.count".into() }),
                }
            }
            _ => c.push(SceneError::invalid(
                "gamma",
                "",
                "give either `values` alone or a range: `start` or `start_over_gamma0`, `end`, `count`",
            )),
        }
        c.finish()
    }
}

impl Written for Fig9Scene {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        let field = match &self.gamma.values {
            Some(_) => "gamma.values",
            None => "gamma.count",
        };
        let gammas = self.gamma_count() as f64;
        // One row of a dozen numbers per grid point, and the plot's copy.
        vec![
            crate::scene::limits::WorkItem::new(
                field,
                "max_grid_points",
                gammas * self.motion.psidot.len() as f64,
                256.0,
            )
            .with_value(gammas),
        ]
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        Ok(self)
    }
}

impl Scene for Fig9Scene {
    fn describe(&self) -> String {
        let p = self.peg.params();
        format!(
            "rigid peg on the hole edge (Fig. 9): D = {} m, d = {} m, H = {} m, f = {}, gammadot = {} 1/s, psidot = {:?} 1/s",
            crate::scene::numbers::significant(p.hole_diameter),
            crate::scene::numbers::significant(p.peg_diameter),
            crate::scene::numbers::significant(p.height),
            crate::scene::numbers::significant(p.friction),
            crate::scene::numbers::significant(self.motion.gammadot),
            self.motion.psidot
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let p = self.peg.params();
        p.validate()?;
        // The table's rows, reserved first: with limits raised past the
        // machine this is a typed error, not an aborted process.
        let points = self.gamma_count() * self.motion.psidot.len();
        drop(try_with_capacity::<Fig9Row>(
            points,
            "grid points",
            "max_grid_points",
        )?);
        let gammas = self.gammas();
        let rows = fig9_rows(&p, &gammas, self.motion.gammadot, &self.motion.psidot)?;
        let header = [
            "gamma",
            "psidot",
            "N_B1_over_mg",
            "N_B2_over_mg",
            "N_K_over_mg",
            "M_gamma_over_mgD",
            "M_psi_over_mgD",
            "feasible",
        ];
        let mut w = ctx.table(Part::Main, &header)?;
        for r in &rows {
            let cells =
                [r.gamma, r.psidot, r.n_b1, r.n_b2, r.n_k, r.m_gamma, r.m_psi].map(format_f64);
            let flag = if r.feasible { "1" } else { "0" };
            let mut refs: Vec<&str> = cells.iter().map(String::as_str).collect();
            refs.push(flag);
            w.row_cells(&refs)?;
        }
        w.finish()?;

        // One panel per reaction, linear in N/(m g) so that negative
        // (infeasible: the contact would have to pull) stretches show.
        type Pick = fn(&Fig9Row) -> f64;
        let quantities: [(&str, &str, Pick); 3] = [
            (
                "Normal reaction at B1 during alignment (rigid peg, three-point contact)",
                "N_B1 / (m g) [-]",
                |r| r.n_b1,
            ),
            ("Normal reaction at B2", "N_B2 / (m g) [-]", |r| r.n_b2),
            ("Normal reaction at K", "N_K / (m g) [-]", |r| r.n_k),
        ];
        // x = γ − γ0 on a log axis resolves the approach to γ0, where B1 and
        // B2 merge and the reactions change fastest.
        let gamma0 = p.gamma0();
        let mut panels = Vec::new();
        for (title, y_label, pick) in quantities {
            let mut panel = Panel::new(title, "gamma - gamma0 [rad]", y_label)
                .scales(Scale::Log, Scale::Linear);
            for (k, &psidot) in self.motion.psidot.iter().enumerate() {
                let curve: Vec<_> = rows.iter().filter(|r| r.psidot == psidot).collect();
                let pts: Vec<(f64, f64)> =
                    curve.iter().map(|r| (r.gamma - gamma0, pick(r))).collect();
                let ok: Vec<bool> = curve.iter().map(|r| r.feasible).collect();
                let name = format!("psidot = {psidot} 1/s");
                for s in Series::split_feasible(&name, &pts, &ok, k) {
                    panel = panel.with(s);
                }
            }
            panels.push(panel);
        }
        let mut metrics = Vec::new();
        for &psidot in &self.motion.psidot {
            let curve: Vec<_> = rows.iter().filter(|r| r.psidot == psidot).collect();
            if let Some(first) = curve.first() {
                metrics.push(Metric::new(
                    format!("N_B1/(mg) at first gamma, psidot = {psidot}"),
                    first.n_b1,
                    "",
                ));
            }
            let bad = curve.iter().filter(|r| !r.feasible).count();
            metrics.push(Metric::new(
                format!("infeasible gamma values, psidot = {psidot}"),
                bad as f64,
                "",
            ));
        }
        let mut fig = Figure::new();
        fig.panels = panels;
        ctx.figure(Part::Main, &fig)?;
        Ok(RunSummary {
            integration: None,
            metrics,
            ..RunSummary::default()
        })
    }
}
