//! Scene kind `drop_3d`: the compliant 3-D peg released leaning on the
//! mouth (the rigid three-point configuration at tilt `γ`, lowered until
//! the fillets touch), spinning about the hole's axis, under gravity and a
//! constant follower moment that turns its axis towards the hole's. Every
//! contact transition (a pair gaining or losing a point) is located as an
//! event and listed.
//!
//! ```toml
//! kind = "drop_3d"
//! [peg]                       # see docs/insertion.md for every field
//! hole_diameter = 0.050
//! clearance_ratio = 0.001
//! length = 0.070
//! rim_fillet = 0.001
//! mouth_fillet = 0.001
//! bore_depth = 0.1
//! density = 7850.0
//! friction = 0.2
//! [drop]
//! gamma = 0.3                 # rad, > gamma0 = arccos(d/D)
//! azimuth_deg = 0.0           # direction of the tilt
//! spin_rate = 10.0            # rad/s about the hole's axis
//! aligning_moment = 0.15      # N m, turns the axis towards the hole's
//! [integrator]
//! method = "dopri5"
//! t_end = 0.05
//! output_interval = 1e-4
//! ```
//!
//! Writes `<name>.csv` (time series, see [`output`]),
//! `<name>.events.csv`, `<name>.svg` (forces and contact state against
//! time), `<name>.views.svg` (side and top views at each transition) and
//! the replay page `<name>.html` (`docs/replay.md`; `[replay] page = false`
//! or `pegdyn run --no-replay` turns it off).

use serde::Deserialize;

use crate::compliant_peg_3d::insertion::{Insertion, N_STATE, lean_pose};
use crate::compliant_peg_3d::outcome::{CountCache, transition_events};
use crate::compliant_peg_3d::{Peg3dParams, pose_state};
use crate::error::{RunError, SceneError, SceneErrors};
use crate::integrate::EventHit;
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series};
use crate::replay::{
    self,
    peg3d::{Meaning, Run3d},
};
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::integrator::DefaultMethod;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::ranges::FieldRange;
use crate::scene::shared::compliant_peg_3d::insertion::RunPeaks;
use crate::scene::shared::compliant_peg_3d::tables::PegTable;
use crate::scene::shared::compliant_peg_3d::{output, ranges};
use crate::scene::shared::replay::{self as shared_replay, ReplayTable};
use crate::scene::simulate::{integrate_watching, integration_summary};
use crate::scene::summary::{Metric, RunSummary};
use crate::scene::validate::Checker;
use crate::system::ModelError;
use nalgebra::{SVector, Vector3};

/// How many contact transitions the summary lists and the views draw (the
/// events table has them all).
const LISTED: usize = 12;

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "drop_3d",
    about: "compliant 3-D peg released leaning on the mouth, spinning, under an aligning moment",
    parse,
    ranges: &[ranges::PEG, DROP],
};

/// `drop.gamma`.
pub const GAMMA: FieldRange = FieldRange::new(
    "drop.gamma",
    0.0,
    1.2,
    "rad",
    "a lean from upright to about 69 degrees; it must also admit the rigid three-point lean, gamma > gamma0 = arccos(d/D)",
);
/// `drop.azimuth_deg`.
pub const AZIMUTH: FieldRange = FieldRange::new(
    "drop.azimuth_deg",
    -360.0,
    360.0,
    "deg",
    "a direction, at most one turn either way",
);
/// `drop.spin_rate`.
pub const SPIN_RATE: FieldRange = FieldRange::new(
    "drop.spin_rate",
    -1e3,
    1e3,
    "rad/s",
    "a spin of up to about 160 turns per second",
);
/// `drop.aligning_moment`.
pub const ALIGNING_MOMENT: FieldRange = FieldRange::new(
    "drop.aligning_moment",
    -1e3,
    1e3,
    "N m",
    "a hand's to a machine's aligning moment, up to a kilonewton metre",
);
/// The `[drop]` table.
pub const DROP: &[FieldRange] = &[GAMMA, AZIMUTH, SPIN_RATE, ALIGNING_MOMENT];

/// The `[drop]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DropTable {
    /// Tilt `γ` at release (rad).
    pub gamma: f64,
    /// Azimuth of the tilt (degrees, default 0).
    #[serde(default)]
    pub azimuth_deg: f64,
    /// Angular velocity about the hole's axis at release (rad/s).
    pub spin_rate: f64,
    /// Follower aligning moment `M₀` (N·m).
    pub aligning_moment: f64,
}

/// A `drop_3d` scene as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DropScene {
    /// The `[peg]` table.
    pub peg: PegTable,
    /// The `[drop]` table.
    pub drop: DropTable,
    /// The `[integrator]` table.
    pub integrator: IntegratorSpec,
    /// The `[replay]` table (optional).
    #[serde(default)]
    pub replay: ReplayTable,
}

#[derive(Debug)]
struct Ready {
    scene: DropScene,
    params: Peg3dParams,
    start: SVector<f64, N_STATE>,
    integrator: IntegratorSpec,
    method_reason: &'static str,
}

impl DropScene {
    /// Validates every table and builds the peg and its start: the rigid
    /// three-point lean at `drop.gamma` lowered onto the fillets
    /// ([`lean_pose`]), spinning at `drop.spin_rate` about the hole's axis.
    ///
    /// # Errors
    /// Every invalid field, named; `drop.gamma` where no lean exists or the
    /// lean overlaps the block.
    pub fn build(&self) -> Result<(Peg3dParams, SVector<f64, N_STATE>), SceneErrors> {
        let mut c = Checker::default();
        let params = self.peg.build(&mut c);
        let d = &self.drop;
        GAMMA.require(&mut c, d.gamma);
        AZIMUTH.require(&mut c, d.azimuth_deg);
        SPIN_RATE.require(&mut c, d.spin_rate);
        ALIGNING_MOMENT.require(&mut c, d.aligning_moment);
        c.extend(self.integrator.check("integrator"));
        c.finish()?;
        let (p, q) = lean_pose(&params, d.gamma, d.azimuth_deg.to_radians()).map_err(|e| {
            SceneErrors::from(SceneError::invalid("drop.gamma", d.gamma, e.to_string()))
        })?;
        let omega_body = q.inverse() * Vector3::new(0.0, 0.0, d.spin_rate);
        let ys = pose_state(p, q, Vector3::zeros(), omega_body);
        let mut start = SVector::<f64, N_STATE>::zeros();
        start.fixed_rows_mut::<15>(0).copy_from(&ys);
        let sys = Insertion::new(params, None, d.aligning_moment);
        if let Some(o) = crate::scene::shared::compliant_peg_3d::start::overlap(&sys, &start) {
            return Err(SceneErrors::from(SceneError::invalid(
                "drop.gamma",
                d.gamma,
                format!(
                    "{}: the lean at this tilt, lowered until the fillets touch, overlaps by more \
                     than it touches (lifting it {} m clears it)",
                    o.describe(),
                    crate::scene::numbers::significant(o.lift)
                ),
            )));
        }
        Ok((params, start))
    }
}

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: DropScene = doc.body()?;
    let (params, start) = s.build()?;
    let (integrator, method_reason) = s.integrator.resolved(DefaultMethod::NON_STIFF);
    Ok(Box::new(Ready {
        scene: s,
        params,
        start,
        integrator,
        method_reason,
    }))
}

impl Written for Ready {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        self.scene.integrator.work("integrator")
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        Ok(self)
    }
}

impl Scene for Ready {
    fn time_scales(&self) -> Option<crate::scene::TimeScales> {
        use crate::scene::shared::compliant_peg_3d::timescales;
        let m0 = self.scene.drop.aligning_moment;
        // The moment presses the rim into the mouth with about M / r.
        let push = m0 / self.params.peg_radius();
        let mut scales = timescales::peg(
            &self.params,
            timescales::load(&self.params, push),
            "the peg's weight plus drop.aligning_moment / r",
        );
        scales.extend(timescales::aligning(&self.params, m0));
        let spin = self.scene.drop.spin_rate;
        if spin != 0.0 {
            scales.push(crate::scene::TimeScale::new(
                "a turn at the spin rate, 2 pi / rate",
                format!("drop.spin_rate = {} rad/s", crate::scene::significant(spin)),
                std::f64::consts::TAU / spin.abs(),
            ));
        }
        Some(crate::scene::TimeScales::new(&self.integrator, scales))
    }

    fn describe(&self) -> String {
        let d = &self.scene.drop;
        format!(
            "compliant 3-D peg dropped leaning on the mouth: D = {} m, c = {}, gamma = {} rad, \
             spin {} rad/s, aligning moment {} N m, mu = {}; {} ({})",
            crate::scene::numbers::significant(self.params.hole_diameter),
            crate::scene::numbers::significant(self.scene.peg.clearance_ratio),
            crate::scene::numbers::significant(d.gamma),
            crate::scene::numbers::significant(d.spin_rate),
            crate::scene::numbers::significant(d.aligning_moment),
            crate::scene::numbers::significant(self.params.friction),
            self.integrator.describe(),
            self.method_reason
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let sys = Insertion::new(self.params, None, self.scene.drop.aligning_moment);
        // The counts share the run's search: at a step's end they take
        // the contacts its last right-hand side found there.
        let cache = CountCache::new(&sys);
        let (events, what) = transition_events(&cache);
        let mut steps = RunPeaks::default();
        let sol = integrate_watching(
            &sys,
            self.start,
            &self.integrator,
            events,
            &mut ctx.progress,
            |t, y: &SVector<f64, N_STATE>| steps.include(&sys, t, y),
        )?;
        if let Some(ModelError::Hertz(e)) = sol.model_error.clone() {
            return Err(
                crate::scene::shared::compliant_peg_3d::start::hertz_refusal(
                    &self.params,
                    sol.t_final,
                    e,
                ),
            );
        }
        let names: Vec<String> = what
            .iter()
            .map(|(i, k)| format!("{} {k}", crate::compliant_peg_3d::Pair::ALL[*i].name()))
            .collect();
        let name_refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let mut out = RunSummary {
            integration: Some(integration_summary(&self.integrator, &sol, &name_refs)),
            ..RunSummary::default()
        };
        let samples = output::samples(&sys, &sol)?;
        let peaks = output::write_series(ctx, &sys, &samples, &sol.events, &steps)?;
        let rows = output::transitions(&sys, &sol, &what);
        output::write_events(ctx, &sys, &rows)?;
        let mut fig = Figure::new();
        fig.panels.push(output::forces_panel(&samples));
        fig.panels.push(output::timeline(&samples));
        fig.panels
            .push(Panel::new("Tilt", "t [s]", "γ [rad]").with(Series::line(
                "γ",
                samples.rows.iter().map(|(t, _, s)| (*t, s.tilt)).collect(),
            )));
        ctx.figure(Part::Main, &fig)?;
        crate::scene::shared::compliant_peg_3d::views::write_views(
            ctx,
            &sys,
            (sol.t.first().copied().unwrap_or(0.0), &self.start),
            &rows,
            (sol.t_final, &sol.x_final),
            LISTED,
        )?;
        out.metrics = output::metrics(&peaks);
        out.metrics.retain(|m| !m.name.contains("wrist"));
        out.metrics
            .push(Metric::new("contact transitions", rows.len() as f64, ""));
        if rows.len() > LISTED {
            let events = ctx.sink().path(Part::Sub("events"), "csv");
            let file = events
                .file_name()
                .map_or_else(String::new, |f| f.to_string_lossy().into_owned());
            out.metrics.push(Metric::new(
                format!(
                    "transitions listed below (the first {LISTED} of {}; every one is in {file})",
                    rows.len()
                ),
                LISTED as f64,
                "",
            ));
        }
        for r in rows.iter().take(LISTED) {
            out.metrics
                .push(Metric::new(format!("{} ({})", r.what, r.state), r.t, "s"));
        }
        if self.scene.replay.wanted(ctx) {
            let meaning =
                |e: &EventHit<N_STATE>| what.get(e.index).map(|w| Meaning::Transition(*w));
            let page = replay::peg3d::page(&Run3d {
                title: ctx.name(),
                subtitle: "compliant 3-D peg released leaning on the mouth, spinning, under an \
                           aligning moment"
                    .into(),
                system: &sys,
                solution: &sol,
                meaning: &meaning,
            })?;
            shared_replay::write(ctx, &page)?;
        }
        Ok(out)
    }
}
