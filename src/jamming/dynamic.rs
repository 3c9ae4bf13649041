//! The jamming diagram checked with dynamics: a sweep of compliant-contact
//! insertions (`compliant_peg::simulate_insertion`, the compliant planar peg) over a grid of
//! load ratios at fixed depth, classified inserted / jammed / wedged.
//!
//! Each run starts at rest in two-point contact (the paper's Fig. 5 lean)
//! at the exact two-point tilt of the requested depth, under a constant load
//! whose Whitney-frame ratios (F_x/F_z, M/(r F_z)) are the grid point
//! (converted to the model's peg-frame f₁, f₂ and moment about C by
//! [`to_paper_frame`]). The parallelogram describes a peg whose tilt
//! direction is unknown, so a grid point is *stuck* when the run from either
//! lean sticks; by mirror symmetry the other lean under ratio q is the first
//! lean under −q, so a grid symmetric about the origin needs one run per
//! point.

use super::diagram::{Parallelogram, Ratio, exact_parallelogram_at_tilt};
use super::forces::{Wrench, to_paper_frame};
use super::params::PegHole;
use super::sweep::{self, Grid, RunClass, SweepPoint};
use crate::compliant_peg::{
    CompliantParams, CompliantSpec, InsertionOptions, InsertionOutcome, Load, PegState, Settle,
    simulate_insertion,
};
use crate::hertz::HertzError;
use crate::integrate::{IntegrateError, Method};
use crate::scalar::Real;

/// What one dynamic sweep simulates (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepSpec {
    /// Peg/hole radius, clearance ratio and friction.
    pub peg: PegHole,
    /// Requested insertion depth l (m).
    pub depth: f64,
    /// Axial force F_z (N), positive into the hole.
    pub fz: f64,
    /// Peg length (m) of the steel cylinder (mass and inertia).
    pub peg_length: f64,
    /// Longest simulated time per run (s).
    pub t_max: f64,
    /// Advance of the bottom face (m) that counts as inserted.
    pub advance: f64,
    /// Classification window (s): a run whose depth advances less than
    /// 2 µm in one window counts as stuck. Near the boundary the peg starts
    /// slowly, so too short a window calls slow insertions stuck.
    pub window: f64,
    /// The integrator of every run.
    pub integrator: Method,
    /// Relative tolerance of every run's integrator.
    pub rtol: f64,
    /// Absolute tolerance of every run's integrator (m, rad, m/s, rad/s).
    pub atol: f64,
    /// Classify a stuck run as soon as it has settled
    /// ([`crate::compliant_peg::Settle::for_window`]) instead of at the end of
    /// its window.
    pub early_stop: bool,
    /// Hunt–Crossley damping `α` of the contacts (s/m, `≥ 0`; 0: elastic
    /// contacts): the normal force is `k δ^{3/2} max(0, 1 + α δ̇)`. At an
    /// impact speed `v` the restitution is about `e = √(1 − 4αv/3)`
    /// (Lankarani & Nikravesh's `α = 3(1 − e²)/(4v)`).
    pub contact_damping: f64,
}

impl SweepSpec {
    /// The reference sweep of the compliant planar peg, the `[sweep]` of
    /// `scenes/jamming.toml` with fixed integration settings: a steel
    /// cylinder 0.1 m long, r = 12.5 mm, c = 0.01, μ = 0.3, from two-point
    /// contact at l = 10 mm under F_z = 20 N; 0.3 s per run, 1 mm advance
    /// counted as inserted, 0.05 s window; elastic contacts (no
    /// Hunt–Crossley damping); RODAS4 at rtol 1e-6, atol 1e-10, no early
    /// stop. Tests and benchmarks change fields of it.
    pub fn reference() -> SweepSpec {
        SweepSpec {
            peg: PegHole::try_new(0.0125, 0.01, 0.3)
                .expect("the reference peg's radius, clearance and friction are valid"),
            depth: 0.01,
            fz: 20.0,
            peg_length: 0.1,
            t_max: 0.3,
            advance: 0.001,
            window: 0.05,
            integrator: Method::Rodas4,
            rtol: 1e-6,
            atol: 1e-10,
            early_stop: false,
            contact_damping: 0.0,
        }
    }
}

/// A prepared sweep: the compliant model, the start state and the
/// quasi-static diagram at the start state's depth and tilt.
#[derive(Debug, Clone)]
pub struct SweepSetup {
    /// The sweep's specification.
    pub spec: SweepSpec,
    /// Compliant model parameters (steel cylinder, all four contacts).
    pub params: CompliantParams,
    /// Start state (two-point contact, at rest).
    pub start: PegState,
    /// Tilt of the start state (rad).
    pub theta: f64,
    /// Whitney depth l of the start state (m): tip face to edge contact
    /// along the axis (differs from the request by the fillets).
    pub depth: f64,
    /// The exact parallelogram at (`depth`, `theta`).
    pub diagram: Parallelogram,
}

/// The model refused the setup.
pub type SetupError = HertzError;

/// Whitney's depth `l` (m) of a two-point start, at any scalar: from the
/// tip face to the edge contact along the axis, `l = (z + l_c cos θ +
/// r sin θ)/cos θ` for the centre of mass at height `z` below the top face
/// (m), `l_c` above the bottom face, peg radius `r` and tilt `theta`
/// (differs from the requested depth by the fillets).
pub fn whitney_depth<T: Real>(z: T, lc: T, r: T, theta: T) -> T {
    (z + lc * theta.cos() + r * theta.sin()) / theta.cos()
}

impl SweepSetup {
    /// Builds the model and the start state; errors name the refused field.
    pub fn new(spec: SweepSpec) -> Result<Self, SetupError> {
        let p = &spec.peg;
        let big_d = p.hole_diameter();
        let model = CompliantSpec {
            damping: spec.contact_damping,
            ..CompliantSpec::steel_cylinder(big_d, p.c(), spec.peg_length, p.mu())
        };
        let params = CompliantParams::try_new(model)?;
        let invalid = |reason| HertzError::Invalid {
            field: "depth".to_owned(),
            value: spec.depth,
            reason,
        };
        let theta = super::geometry::two_point_tilt(p, spec.depth)
            .map_err(|_| invalid("must be finite and > 0"))?
            .ok_or_else(|| invalid("two-point contact is impossible at this depth"))?;
        let start = PegState::two_point(&params, theta, 0.0)?;
        let depth = whitney_depth(start.z, params.spec.com_height, p.r(), theta);
        Ok(Self {
            spec,
            params,
            start,
            theta,
            depth,
            diagram: exact_parallelogram_at_tilt(p, depth, theta),
        })
    }

    /// The same sweep with the contacts' friction law `law` (the default
    /// is the regularized law; see [`crate::compliant_peg::FrictionLaw`]).
    pub fn with_friction_law(
        mut self,
        law: crate::compliant_peg::FrictionLaw,
    ) -> Result<Self, SetupError> {
        let mut spec = self.params.spec;
        spec.friction_law = law;
        self.params = CompliantParams::try_new(spec)?;
        Ok(self)
    }

    /// One run from the reference lean under load ratio `q`.
    pub fn run_one(&self, q: Ratio) -> Result<RunClass, IntegrateError> {
        let fz = self.spec.fz;
        let w = Wrench {
            fx: q[0] * fz,
            fz,
            m: q[1] * self.spec.peg.r() * fz,
        };
        let (f1, f2, m_c) = to_paper_frame(&w, self.theta, self.params.spec.com_height);
        let load = Load {
            axial: f1,
            radial: f2,
            torque: m_c,
        };
        let opts = InsertionOptions {
            target_depth: self.start.depth(&self.params) + self.spec.advance,
            t_max: self.spec.t_max,
            window: self.spec.window,
            integrator: self.spec.integrator,
            rtol: self.spec.rtol,
            atol: self.spec.atol,
            settle: self
                .spec
                .early_stop
                .then(|| Settle::for_window(self.spec.window)),
            ..InsertionOptions::default()
        };
        let run = simulate_insertion(&self.params, &load, &self.start, &opts)?;
        Ok(match run.outcome {
            InsertionOutcome::Inserted { .. } => RunClass::Inserted,
            InsertionOutcome::Jammed { .. } => RunClass::Jammed,
            InsertionOutcome::Wedged { .. } => RunClass::Wedged,
            InsertionOutcome::Failed { .. } => RunClass::Failed,
            _ => RunClass::Other,
        })
    }
}

/// One grid point with the runs from both leans.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicPoint {
    /// Combined class (stuck if either lean sticks).
    pub point: SweepPoint,
    /// Run from the reference lean under q.
    pub lean_plus: RunClass,
    /// Run from the other lean under q (= reference lean under −q).
    pub lean_minus: RunClass,
}

fn combine(a: RunClass, b: RunClass) -> RunClass {
    use RunClass::*;
    match (a, b) {
        (Wedged, _) | (_, Wedged) => Wedged,
        (Jammed, _) | (_, Jammed) => Jammed,
        (Failed, _) | (_, Failed) => Failed,
        (Inserted, Inserted) => Inserted,
        _ => Other,
    }
}

/// Runs the sweep over the grid `max_x`, `max_y` (symmetric about the
/// origin, `n` points per axis) in parallel; `progress(done, total)`.
pub fn run(
    setup: &SweepSetup,
    max_x: f64,
    max_y: f64,
    n: usize,
    progress: impl Fn(usize, usize) + Sync,
) -> Result<(Grid, Vec<DynamicPoint>), IntegrateError> {
    let axis = |m: f64| sweep::Axis { min: -m, max: m, n };
    let grid = Grid {
        x: axis(max_x),
        y: axis(max_y),
    };
    let raw = sweep::run(&grid, |q| setup.run_one(q), progress)?;
    // grid points x fastest: −q of index (i, j) is (n−1−i, n−1−j)
    let points = (0..raw.len())
        .map(|k| {
            let (i, j) = (k % n, k / n);
            let mirror = raw[(n - 1 - j) * n + (n - 1 - i)].class;
            let plus = raw[k].class;
            DynamicPoint {
                point: SweepPoint {
                    ratio: raw[k].ratio,
                    class: combine(plus, mirror),
                },
                lean_plus: plus,
                lean_minus: mirror,
            }
        })
        .collect();
    Ok((grid, points))
}
