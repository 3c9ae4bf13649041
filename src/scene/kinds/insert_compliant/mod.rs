//! Scene kind `insert_compliant`: a steel peg pushed into a round hole with
//! Hertz contacts at filleted edges (the compliant planar peg, sections 2–3; see
//! `docs/compliant.md`). Writes the time series (t, x, z, θ, depth, contact
//! forces, pressures and penetrations, energy terms) as CSV and plots it.
//!
//! ```toml
//! kind = "insert_compliant"
//! [insert_compliant]
//! hole_diameter = 0.05      # D, m
//! clearance_ratio = 0.002   # c = (D - 2r)/D
//! peg_length = 0.1          # m; solid cylinder: mass, inertia
//! density = 7850.0          # kg/m^3
//! # com_height = 0.05       # l_c, m (default peg_length / 2)
//! peg_fillet = 0.0002       # m (default 0.2 mm)
//! hole_fillet = 0.0002      # m (default 0.2 mm)
//! friction = 0.1            # Coulomb mu
//! slip_velocity = 1e-5      # v_s of the regularized friction law, m/s
//! friction_law = "regularized" # "regularized" | "elastic" (Hertz–Mindlin capped by Coulomb)
//! tangential_damping = 1e-4 # tau_t of the elastic law's tangential springs, s
//! contacts = "all"          # "all" | "lean"
//! contact_damping = 0.0     # Hunt–Crossley alpha, s/m (default 0: elastic)
//! axial_force = 5.0         # f1, N (into the hole)
//! radial_force = 0.0        # f2, N
//! torque = -0.002           # M, N m
//! initial_tilt = 0.01       # rad; two-point start, or 0 for centred upright
//! initial_depth = 0.005     # m, for initial_tilt = 0
//! target_depth = 0.03       # m; the run stops there
//! [insert_compliant.peg_material]
//! youngs_modulus = 210e9    # Pa
//! poisson_ratio = 0.3
//! [insert_compliant.hole_material]
//! youngs_modulus = 210e9
//! poisson_ratio = 0.3
//! [integrator]
//! method = "dopri5"
//! t_end = 0.2
//! ```

use serde::Deserialize;

pub(crate) mod model_errors;
pub mod output;
pub mod ranges;
pub mod replay;
pub mod sensitivities;
pub(crate) mod start;

use model_errors::{tilt_error, to_scene_error};
use output::write_outputs;

use crate::compliant_peg::{
    CompliantParams, CompliantSpec, CompliantSystem, ContactSet, ElasticSystem, FrictionLaw, Load,
    PegHoleGeometry, PegState, Sample,
};
use crate::error::{RunError, SceneError, SceneErrors};
use crate::hertz::Material;
use crate::integrate::{Direction, Event};
use crate::scene::context::RunContext;
use crate::scene::document::Document;
use crate::scene::integrator::DefaultMethod;
use crate::scene::integrator::IntegratorSpec;
use crate::scene::kind::{Kind, Scene, Written};
use crate::scene::shared::material::{MaterialSpec, steel};
use crate::scene::shared::replay::ReplayTable;
use crate::scene::simulate::{integrate_watching, integration_summary};
use crate::scene::summary::RunSummary;
use crate::scene::validate::Checker;
use crate::system::OdeSystem;
use nalgebra::SVector;

/// Registry entry.
pub const KIND: Kind = Kind {
    name: "insert_compliant",
    about: "compliant planar peg: insertion with Hertz contacts and friction",
    parse,
    ranges: &[ranges::INSERT_COMPLIANT],
};

fn parse(doc: &Document<'_>) -> Result<Box<dyn Written>, SceneErrors> {
    let s: InsertCompliantScene = doc.body()?;
    let built = s.build()?;
    let sensitivities = match &s.sensitivities {
        Some(t) => sensitivities::check(t, &built)?,
        None => Vec::new(),
    };
    let (integrator, method_reason) = s.integrator.resolved(DefaultMethod::STIFF_CONTACT);
    Ok(Box::new(Ready {
        scene: s,
        built,
        integrator,
        method_reason,
        sensitivities,
    }))
}

fn default_fillet() -> f64 {
    crate::compliant_peg::DEFAULT_FILLET
}
fn default_slip() -> f64 {
    1e-5
}

fn default_tangential_damping() -> f64 {
    crate::compliant_peg::params::TANGENTIAL_DAMPING
}

/// Which contacts to generate.
#[derive(Debug, Clone, Copy, Deserialize, Default, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum ContactsSpec {
    /// All four contacts.
    #[default]
    All,
    /// The two of a lean with θ > 0.
    Lean,
}

/// The tangential friction law.
#[derive(Debug, Clone, Copy, Deserialize, Default, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum FrictionLawSpec {
    /// Regularized Coulomb (velocity scale `slip_velocity`).
    #[default]
    Regularized,
    /// Hertz–Mindlin tangential compliance capped by Coulomb (sticks
    /// without creep; all four contacts).
    Elastic,
}

/// The `[insert_compliant]` table (SI units).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InsertParams {
    /// Hole diameter D, m.
    pub hole_diameter: f64,
    /// Clearance ratio c = (D − 2r)/D (r the peg radius).
    pub clearance_ratio: f64,
    /// Peg length, m (a solid cylinder: sets mass and inertia).
    pub peg_length: f64,
    /// Peg density, kg/m³.
    pub density: f64,
    /// Height l_c of the centre of mass above the bottom face, m (default `peg_length / 2`).
    pub com_height: Option<f64>,
    #[serde(default = "default_fillet")]
    /// Fillet radius of the peg's bottom edge, m (default 0.2 mm).
    pub peg_fillet: f64,
    #[serde(default = "default_fillet")]
    /// Fillet radius of the hole's edge, m (default 0.2 mm).
    pub hole_fillet: f64,
    /// Coulomb friction coefficient μ.
    pub friction: f64,
    #[serde(default = "default_slip")]
    /// Slip velocity v_s of the regularized friction law, m/s (default 1e-5).
    pub slip_velocity: f64,
    #[serde(default)]
    /// The friction law (default regularized).
    pub friction_law: FrictionLawSpec,
    #[serde(default = "default_tangential_damping")]
    /// Damping time τ_t of the elastic law's tangential springs, s
    /// (default 1e-4).
    pub tangential_damping: f64,
    #[serde(default)]
    /// Which contacts to generate (default all four).
    pub contacts: ContactsSpec,
    #[serde(default)]
    /// Hunt–Crossley damping α, s/m (default 0: elastic).
    pub contact_damping: f64,
    /// Axial force f1 into the hole, N.
    pub axial_force: f64,
    #[serde(default)]
    /// Radial force f2, N (default 0).
    pub radial_force: f64,
    #[serde(default)]
    /// Applied moment M, N·m (default 0).
    pub torque: f64,
    /// Initial tilt, rad: a two-point start, or 0 for a centred upright start.
    pub initial_tilt: f64,
    #[serde(default)]
    /// Initial depth for `initial_tilt = 0`, m (default 0).
    pub initial_depth: f64,
    /// Depth at which the run stops, m.
    pub target_depth: f64,
    #[serde(default = "steel")]
    /// Peg material (default steel: 210 GPa, 0.3).
    pub peg_material: MaterialSpec,
    #[serde(default = "steel")]
    /// Hole material (default steel).
    pub hole_material: MaterialSpec,
}

/// An `insert_compliant` scene as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InsertCompliantScene {
    /// The `[insert_compliant]` table.
    pub insert_compliant: InsertParams,
    /// The `[integrator]` table.
    pub integrator: IntegratorSpec,
    /// The `[replay]` table (optional).
    #[serde(default)]
    pub replay: ReplayTable,
    /// The `[sensitivities]` table (optional): derivatives of the run's
    /// metrics with respect to the named fields.
    #[serde(default)]
    pub sensitivities: Option<sensitivities::SensitivitiesTable>,
}

/// What the scene builds from its tables.
#[derive(Debug, Clone, Copy)]
pub struct Built {
    /// Checked model parameters.
    pub params: CompliantParams,
    /// Applied loads.
    pub load: Load,
    /// Initial state.
    pub initial: PegState,
}

#[derive(Debug)]
struct Ready {
    scene: InsertCompliantScene,
    built: Built,
    /// The `[integrator]` table with the method resolved.
    integrator: IntegratorSpec,
    /// Why that method runs.
    method_reason: &'static str,
    /// The fields of the `[sensitivities]` table (indices into
    /// [`sensitivities::fields::FIELDS`]), empty without one.
    sensitivities: Vec<usize>,
}

impl InsertCompliantScene {
    /// Validates every field and builds the model parameters, loads and
    /// initial state.
    pub fn build(&self) -> Result<Built, SceneErrors> {
        let p = &self.insert_compliant;
        let f = |k: &str| format!("insert_compliant.{k}");
        let mut c = Checker::default();
        let d = c.positive(&f("hole_diameter"), p.hole_diameter);
        let cr = c.finite(&f("clearance_ratio"), p.clearance_ratio);
        let len = c.positive(&f("peg_length"), p.peg_length);
        c.positive(&f("density"), p.density);
        ranges::HOLE_DIAMETER.check(&mut c, d);
        ranges::PEG_LENGTH.check(&mut c, len);
        ranges::DENSITY.check(&mut c, p.density);
        c.finite(&f("axial_force"), p.axial_force);
        c.finite(&f("radial_force"), p.radial_force);
        c.finite(&f("torque"), p.torque);
        c.non_negative(&f("initial_tilt"), p.initial_tilt);
        c.non_negative(&f("initial_depth"), p.initial_depth);
        c.positive(&f("target_depth"), p.target_depth);
        if let Some(lc) = p.com_height {
            c.in_range(&f("com_height"), lc, 0.0, len);
        }
        c.extend(self.integrator.check("integrator"));
        let r = 0.5 * d * (1.0 - cr);
        ranges::check_compliant(
            &mut c,
            "insert_compliant",
            &ranges::CompliantFields {
                hole_diameter: d,
                clearance_ratio: cr,
                peg_length: len,
                peg_fillet: p.peg_fillet,
                hole_fillet: p.hole_fillet,
                youngs_modulus: [
                    p.peg_material.youngs_modulus,
                    p.hole_material.youngs_modulus,
                ],
                poisson_ratio: [p.peg_material.poisson_ratio, p.hole_material.poisson_ratio],
                load: p.axial_force.abs() + p.radial_force.abs() + p.torque.abs() / r,
                initial_depth: p.initial_depth,
                target_depth: p.target_depth,
            },
        );
        c.finish()?;
        let mass = p.density * std::f64::consts::PI * r * r * len;
        let spec = CompliantSpec {
            geometry: PegHoleGeometry {
                hole_diameter: d,
                peg_radius: r,
                peg_fillet: p.peg_fillet,
                hole_fillet: p.hole_fillet,
            },
            peg: Material {
                youngs_modulus: p.peg_material.youngs_modulus,
                poisson_ratio: p.peg_material.poisson_ratio,
            },
            hole: Material {
                youngs_modulus: p.hole_material.youngs_modulus,
                poisson_ratio: p.hole_material.poisson_ratio,
            },
            mass,
            inertia: mass * (3.0 * r * r + len * len) / 12.0,
            com_height: p.com_height.unwrap_or(0.5 * len),
            friction: p.friction,
            slip_velocity: p.slip_velocity,
            reference_tilt: 0.0,
            damping: p.contact_damping,
            tangential_damping: p.tangential_damping,
            friction_law: match p.friction_law {
                FrictionLawSpec::Regularized => FrictionLaw::Regularized,
                FrictionLawSpec::Elastic => FrictionLaw::Elastic,
            },
            contacts: match p.contacts {
                ContactsSpec::All => ContactSet::All,
                ContactsSpec::Lean => ContactSet::Lean,
            },
        };
        let params = CompliantParams::try_new(spec).map_err(|e| to_scene_error(e, p))?;
        let initial = if p.initial_tilt > 0.0 {
            PegState::two_point(&params, p.initial_tilt, 0.0)
                .map_err(|e| tilt_error(e, &params, p))?
        } else {
            PegState::centred(&params, p.initial_depth)
        };
        let depth = initial.depth(&params);
        if p.initial_tilt > 0.0 && depth >= len {
            // The two-point depth grows like c D / theta: a tilt this small
            // starts the peg deeper than it is long.
            return Err(SceneErrors::from(SceneError::invalid(
                f("initial_tilt"),
                p.initial_tilt,
                format!(
                    "the two-point start at this tilt lies {} m deep (about c D / tilt), beyond \
                     insert_compliant.peg_length = {} m; a larger tilt starts higher",
                    crate::scene::numbers::significant(depth),
                    crate::scene::numbers::significant(len)
                ),
            )));
        }
        if p.target_depth <= depth {
            let from = if p.initial_tilt > 0.0 {
                "the two-point start of insert_compliant.initial_tilt"
            } else {
                "insert_compliant.initial_depth"
            };
            return Err(SceneErrors::from(SceneError::invalid(
                f("target_depth"),
                p.target_depth,
                format!(
                    "must exceed the initial depth {} m ({from})",
                    crate::scene::numbers::significant(depth)
                ),
            )));
        }
        let load = Load {
            axial: p.axial_force,
            radial: p.radial_force,
            torque: p.torque,
        };
        start::overlap(&params, &load, &initial, p)?;
        Ok(Built {
            params,
            load,
            initial,
        })
    }
}

impl Written for Ready {
    fn work(&self) -> Vec<crate::scene::limits::WorkItem> {
        let mut work = self.scene.integrator.work("integrator");
        if !self.sensitivities.is_empty() {
            work.extend(sensitivities::work(
                &self.scene.insert_compliant,
                &self.built,
                &self.integrator,
                &self.sensitivities,
            ));
        }
        work
    }

    fn build(self: Box<Self>) -> Result<Box<dyn Scene>, SceneErrors> {
        Ok(self)
    }
}

impl Scene for Ready {
    fn time_scales(&self) -> Option<crate::scene::TimeScales> {
        let scales = start::time_scales(&self.built, &self.scene.insert_compliant);
        Some(crate::scene::TimeScales::new(&self.integrator, scales))
    }

    fn describe(&self) -> String {
        let p = &self.scene.insert_compliant;
        format!(
            "compliant peg-in-hole D = {} m, c = {}, mu = {}, f1 = {} N, f2 = {} N, M = {} N m, \
             start tilt {} rad, k_edge = {:.3e} N/m^1.5, {} friction; {} ({})",
            crate::scene::numbers::significant(p.hole_diameter),
            crate::scene::numbers::significant(p.clearance_ratio),
            crate::scene::numbers::significant(p.friction),
            crate::scene::numbers::significant(p.axial_force),
            crate::scene::numbers::significant(p.radial_force),
            crate::scene::numbers::significant(p.torque),
            crate::scene::numbers::significant(p.initial_tilt),
            self.built.params.pair.edge.stiffness(),
            match self.built.params.spec.friction_law {
                FrictionLaw::Regularized => "regularized",
                FrictionLaw::Elastic => "elastic",
            },
            self.integrator.describe(),
            self.method_reason
        )
    }

    fn run(&self, ctx: &mut RunContext) -> Result<RunSummary, RunError> {
        let Built {
            params,
            load,
            initial,
        } = self.built;
        let (lc, target) = (
            params.spec.com_height,
            self.scene.insert_compliant.target_depth,
        );
        // Terminal event: the bottom centre reaches the target depth
        // (state components z and theta come first in both laws' states).
        fn inserted<'a, const N: usize>(lc: f64, target: f64) -> Event<'a, N> {
            Event::new(move |_t, y: &SVector<f64, N>| y[1] + lc * y[2].cos() - target)
                .direction(Direction::Rising)
                .terminal()
        }
        match params.spec.friction_law {
            FrictionLaw::Regularized => {
                let sys = CompliantSystem::new(&params, &load);
                self.run_system(ctx, &sys, initial.to_vector(), inserted(lc, target), |y| {
                    sys.sample(y)
                })
            }
            FrictionLaw::Elastic => {
                let sys = ElasticSystem::new(&params, &load);
                self.run_system(
                    ctx,
                    &sys,
                    initial.to_vector_elastic(),
                    inserted(lc, target),
                    |y| sys.sample(y),
                )
            }
        }
    }
}

impl Ready {
    /// Integrates `sys` from `y0` until `inserted` fires or the end time,
    /// and writes the outputs of `sample` at every output time.
    fn run_system<const N: usize>(
        &self,
        ctx: &mut RunContext,
        sys: &impl OdeSystem<N>,
        y0: SVector<f64, N>,
        inserted: Event<N>,
        sample: impl Fn(&SVector<f64, N>) -> Sample,
    ) -> Result<RunSummary, RunError> {
        // The peaks over every accepted step's end: an impact between two
        // output times is not missed.
        let mut peaks = (0.0_f64, 0.0_f64);
        let sol = integrate_watching(
            sys,
            y0,
            &self.integrator,
            vec![inserted],
            &mut ctx.progress,
            |_, y: &SVector<f64, N>| {
                let s = sample(y);
                peaks.0 = peaks.0.max(s.f_edge).max(s.f_wall);
                peaks.1 = peaks.1.max(s.p0_edge).max(s.p0_wall);
            },
        )?;
        let mut out = RunSummary {
            integration: Some(integration_summary(&self.integrator, &sol, &["inserted"])),
            ..RunSummary::default()
        };
        write_outputs(ctx, &sample, &sol, peaks, &mut out)?;
        if !self.sensitivities.is_empty() {
            let notes = sensitivities::run(
                ctx,
                &self.scene.insert_compliant,
                &self.built,
                &self.integrator,
                (
                    &self.sensitivities,
                    sensitivities::ErrorControl::of(self.scene.sensitivities.as_ref()),
                ),
            )?;
            out.metrics.extend(notes);
        }
        if self.scene.replay.wanted(ctx) {
            replay::write(
                ctx,
                &self.scene.insert_compliant,
                &self.built,
                &sol,
                &sample,
            )?;
        }
        Ok(out)
    }
}
