//! Scene kind `align_forward`: forward dynamics of the rigid peg leaning on
//! the hole edge at K, B1, B2 (`src/rigid_peg/forward.rs`,
//! `docs/rigid-peg.md`), released at γ(0) with rates γ̇(0), ψ̇(0) under
//! gravity, constant moments M_γ, M_ψ and an assembly force, until a
//! contact event (γ0 reached, lift-off, stick, Painlevé) or `t_end`.
//!
//! ```toml
//! kind = "align_forward"
//! [peg]                      # as in the fig9 kind (SI units)
//! hole_diameter = 0.050
//! peg_diameter = 0.04995
//! height = 0.070
//! mass = 1.0
//! gravity = 9.81
//! friction = 0.2
//! [initial]
//! gamma = 0.3                # rad, gamma0 < gamma < pi/2
//! psi = 0.0                  # rad
//! gammadot = 0.0             # 1/s
//! psidot = 10.0              # 1/s
//! [loads]
//! m_gamma = -0.1             # N m (negative aligns)
//! m_psi = 0.0                # N m about the hole axis
//! force = [0.0, 0.0, 0.0]    # N, fixed frame, at the centre of mass
//! [friction]
//! law = "coulomb"            # or "regularized" (then v_s is used)
//! v_stop = 1e-6              # m/s, rest threshold (coulomb)
//! v_s = 1e-4                 # m/s, regularization scale
//! [integrator]
//! method = "dopri5"
//! t_end = 0.5
//! ```
//!
//! Writes `<out>/<name>.csv` (`t,gamma,psi,gammadot,psidot,N_K,N_B1,N_B2`,
//! SI units) and `<out>/<name>.svg` (reactions and γ against t).

use nalgebra::Vector4;
use serde::Deserialize;

use crate::error::{RunError, SceneError, SceneErrors};
use crate::integrate::{Options, OutputMode};
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series};
use crate::rigid_peg::forward::{ForwardModel, FrictionLaw};
use crate::rigid_peg::stop::ForwardStop;
use crate::rigid_peg::trajectory::{Restart, simulate_with_progress};
use crate::rigid_peg::{Loads, RigidError};
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::shared::rigid_peg::{self, PegTable};
use crate::scene::simulate::solver_config;
use crate::scene::summary::{EventRecord, IntegrationSummary, Metric, RunSummary};
use crate::scene::validate::Checker;

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "align_forward",
    about: "rigid three-point peg on the hole edge: forward dynamics until a contact event",
    parse,
    ranges: &[rigid_peg::PEG, rigid_peg::ALIGN_FORWARD],
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: AlignForwardScene = doc.body()?;
    s.check()?;
    Ok(Box::new(s))
}

/// The `[initial]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InitialTable {
    /// γ(0), rad.
    pub gamma: f64,
    /// ψ(0), rad.
    #[serde(default)]
    pub psi: f64,
    /// γ̇(0), 1/s.
    #[serde(default)]
    pub gammadot: f64,
    /// ψ̇(0), 1/s.
    #[serde(default)]
    pub psidot: f64,
}

/// The `[loads]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadsTable {
    /// M_γ, N·m (generalized force conjugate to γ; negative aligns).
    #[serde(default)]
    pub m_gamma: f64,
    /// M_ψ, N·m (moment about the hole axis).
    #[serde(default)]
    pub m_psi: f64,
    /// Assembly force at the centre of mass, fixed frame, N.
    #[serde(default)]
    pub force: [f64; 3],
}

/// Friction law named in `[friction] law`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum LawName {
    /// Exact Coulomb with stick detection.
    #[default]
    Coulomb,
    /// Regularized with scale `v_s`.
    Regularized,
}

/// The `[friction]` table.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionTable {
    /// Friction law.
    #[serde(default)]
    pub law: LawName,
    /// Rest threshold of the RMS contact sliding speed, m/s.
    #[serde(default = "default_v_stop")]
    pub v_stop: f64,
    /// Regularization velocity scale, m/s.
    #[serde(default = "default_v_s")]
    pub v_s: f64,
}

/// The restarts from rest (`restart_from_rest`, with the new direction û
/// in (γ, ψ)) and, for a planned stop other than the end time, the stop
/// itself (terminal, named as [`ForwardStop::name`]).
fn events(restarts: &[Restart], stop: &ForwardStop, t_stop: f64) -> Vec<EventRecord> {
    let mut out: Vec<EventRecord> = restarts
        .iter()
        .map(|r| EventRecord {
            name: "restart_from_rest".into(),
            t: r.t,
            terminal: false,
            details: vec![
                ("direction_gamma".into(), r.direction[0]),
                ("direction_psi".into(), r.direction[1]),
            ],
        })
        .collect();
    if stop.is_success() && !matches!(stop, ForwardStop::ReachedEnd { .. }) {
        out.push(EventRecord {
            name: stop.name(),
            t: t_stop,
            terminal: true,
            details: Vec::new(),
        });
    }
    out
}

fn default_v_stop() -> f64 {
    crate::rigid_peg::forward::DEFAULT_V_STOP
}
fn default_v_s() -> f64 {
    1e-4
}

impl Default for FrictionTable {
    fn default() -> Self {
        FrictionTable {
            law: LawName::Coulomb,
            v_stop: default_v_stop(),
            v_s: default_v_s(),
        }
    }
}

/// An `align_forward` scene.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AlignForwardScene {
    /// Peg, hole, friction coefficient.
    pub peg: PegTable,
    /// Initial state.
    pub initial: InitialTable,
    /// Constant loads.
    #[serde(default = "no_loads")]
    pub loads: LoadsTable,
    /// Friction law.
    #[serde(default)]
    pub friction: FrictionTable,
    /// Integration settings.
    pub integrator: IntegratorSpec,
}

fn no_loads() -> LoadsTable {
    LoadsTable {
        m_gamma: 0.0,
        m_psi: 0.0,
        force: [0.0; 3],
    }
}

impl AlignForwardScene {
    /// Validates every field, reporting all problems.
    pub fn check(&self) -> Result<(), SceneErrors> {
        let mut c = Checker::default();
        self.peg.check_into(&mut c);
        let i = &self.initial;
        c.finite("initial.gamma", i.gamma);
        c.finite("initial.psi", i.psi);
        c.finite("initial.gammadot", i.gammadot);
        c.finite("initial.psidot", i.psidot);
        let l = &self.loads;
        c.finite("loads.m_gamma", l.m_gamma);
        c.finite("loads.m_psi", l.m_psi);
        for (k, v) in l.force.iter().enumerate() {
            c.finite(&format!("loads.force[{k}]"), *v);
        }
        c.positive("friction.v_stop", self.friction.v_stop);
        c.positive("friction.v_s", self.friction.v_s);
        {
            use crate::scene::shared::rigid_peg::{check_load, check_rate};
            let (p, m) = (&self.peg, self.peg.mass);
            check_rate(
                &mut c,
                "initial.psidot",
                i.psidot,
                0.5 * p.peg_diameter,
                "d/2",
            );
            check_rate(&mut c, "initial.gammadot", i.gammadot, p.height, "H");
            let lever = p.height.max(p.hole_diameter);
            check_load(&mut c, "loads.m_gamma", l.m_gamma, m * lever, "N m");
            check_load(&mut c, "loads.m_psi", l.m_psi, m * lever, "N m");
            for (k, v) in l.force.iter().enumerate() {
                check_load(&mut c, &format!("loads.force[{k}]"), *v, m, "N");
            }
        }
        c.extend(self.integrator.check("integrator"));
        if c.is_ok() {
            let g0 = self.peg.params().gamma0();
            if !(i.gamma > g0 && i.gamma < std::f64::consts::FRAC_PI_2) {
                c.push(SceneError::invalid(
                    "initial.gamma",
                    i.gamma,
                    format!("must lie above gamma0 = arccos(d/D) = {g0} rad and below pi/2 (three-point contact)"),
                ));
            }
        }
        c.finish()
    }

    /// The forward model of the scene: peg, loads and friction law.
    ///
    /// # Errors
    /// [`RigidError::Param`] for invalid parameters, loads or friction
    /// settings (a scene that passed [`AlignForwardScene::check`] has none).
    pub fn forward_model(&self) -> Result<ForwardModel, RigidError> {
        let l = &self.loads;
        let loads = Loads {
            m_gamma: l.m_gamma,
            m_psi: l.m_psi,
            force: l.force,
        };
        let law = match self.friction.law {
            LawName::Coulomb => FrictionLaw::Coulomb,
            LawName::Regularized => FrictionLaw::Regularized {
                v_s: self.friction.v_s,
            },
        };
        ForwardModel::new(self.peg.params(), loads)?
            .with_friction(law)?
            .with_v_stop(self.friction.v_stop)
    }

    /// The initial state x(0) = (γ, ψ, γ̇, ψ̇) (rad, rad, 1/s, 1/s).
    pub fn initial_state(&self) -> Vector4<f64> {
        let i = &self.initial;
        Vector4::new(i.gamma, i.psi, i.gammadot, i.psidot)
    }
}

impl Written for AlignForwardScene {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        self.integrator.work("integrator")
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        Ok(self)
    }
}

impl Scene for AlignForwardScene {
    fn describe(&self) -> String {
        let (p, i, l) = (self.peg.params(), &self.initial, &self.loads);
        format!(
            "rigid peg forward dynamics: D = {} m, d = {} m, H = {} m, f = {}, gamma(0) = {} rad, psidot(0) = {} 1/s, M_gamma = {} N m, M_psi = {} N m; {}",
            crate::scene::numbers::significant(p.hole_diameter),
            crate::scene::numbers::significant(p.peg_diameter),
            crate::scene::numbers::significant(p.height),
            crate::scene::numbers::significant(p.friction),
            crate::scene::numbers::significant(i.gamma),
            crate::scene::numbers::significant(i.psidot),
            crate::scene::numbers::significant(l.m_gamma),
            crate::scene::numbers::significant(l.m_psi),
            self.integrator.describe()
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let model = self.forward_model()?;
        let spec = &self.integrator;
        let (method, mut options): (_, Options) =
            solver_config(spec, &crate::generated::rigid_peg::X_NAMES)?;
        options.output = OutputMode::AtTimes(spec.try_output_times()?);
        let x0 = self.initial_state();
        ctx.progress.set_span(spec.t0, spec.t_end);
        let interrupt = ctx.progress.interrupt().clone();
        let progress = &mut ctx.progress;
        let tr = simulate_with_progress(
            &model,
            x0,
            (spec.t0, spec.t_end),
            method,
            &options,
            &mut |t| progress.update(t),
            Some(&interrupt),
        )?;
        ctx.progress.check_interrupt()?;
        let header = [
            "t", "gamma", "psi", "gammadot", "psidot", "N_K", "N_B1", "N_B2",
        ];
        let mut w = ctx.table(Part::Main, &header)?;
        for r in &tr.rows {
            let [nk, nb1, nb2] = r.normal;
            w.row(&[r.t, r.x[0], r.x[1], r.x[2], r.x[3], nk, nb1, nb2])?;
        }
        w.finish()?;

        let series =
            |k: usize| -> Vec<(f64, f64)> { tr.rows.iter().map(|r| (r.t, r.normal[k])).collect() };
        let mut reactions = Panel::new(
            "Normal reactions at the contacts (rigid peg, three points)",
            "t [s]",
            "N [N]",
        );
        for (k, name) in ["N_K", "N_B1", "N_B2"].iter().enumerate() {
            reactions = reactions.with(Series::line(*name, series(k)));
        }
        let gamma: Vec<(f64, f64)> = tr.rows.iter().map(|r| (r.t, r.x[0])).collect();
        let g0 = model.params.gamma0();
        let angle = Panel::new("Nutation angle", "t [s]", "gamma [rad]")
            .with(Series::line("gamma", gamma))
            .with(Series::line(
                "gamma0",
                vec![
                    (spec.t0, g0),
                    (tr.rows.last().map_or(spec.t_end, |r| r.t), g0),
                ],
            ));
        let mut fig = Figure::new();
        fig.panels = vec![reactions, angle];
        ctx.figure(Part::Main, &fig)?;

        let t_final = tr.rows.last().map_or(spec.t0, |r| r.t);
        let integration = IntegrationSummary {
            method: spec
                .resolved(crate::scene::integrator::DefaultMethod::NON_STIFF)
                .0
                .method,
            t_end: t_final,
            stop: match (&tr.stop, &tr.non_finite) {
                (crate::rigid_peg::stop::ForwardStop::Integrator(r), nf) => {
                    crate::scene::simulate::describe_stop_at(r, nf.as_ref(), &[])
                }
                (s, _) => s.to_string(),
            },
            success: tr.stop.is_success(),
            steps: tr.stats.steps,
            rejected: tr.stats.rejected,
            rhs_calls: tr.stats.rhs_calls,
            events: events(&tr.restarts, &tr.stop, t_final),
            step_failure: match tr.stop {
                crate::rigid_peg::stop::ForwardStop::Integrator(
                    crate::integrate::StopReason::StepSizeTooSmall { t, h },
                ) => Some(crate::scene::summary::StepFailure::TooSmall { t, h }),
                _ => None,
            },
        };
        let mut metrics = vec![
            Metric::new(format!("event `{}` at t", tr.stop.name()), t_final, "s"),
            Metric::new("restarts from rest", tr.restarts.len() as f64, ""),
        ];
        if let Some(r) = tr.rows.last() {
            metrics.push(Metric::new("gamma at stop", r.x[0], "rad"));
            metrics.push(Metric::new("gamma0", g0, "rad"));
        }
        Ok(RunSummary {
            integration: Some(integration),
            metrics,
            ..RunSummary::default()
        })
    }
}
