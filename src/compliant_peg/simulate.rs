//! Dynamic insertion of the compliant peg, classified: inserted, jammed,
//! wedged, stalled, backed out, or unfinished. This is the entry point of
//! the jamming/wedging sweep (`src/jamming`).
//!
//! ```text
//! pub fn simulate_insertion(params: &CompliantParams, load: &Load, initial: &PegState,
//!                           opts: &InsertionOptions) -> Result<InsertionRun, IntegrateError>
//! ```
//!
//! Classification (the integration runs in windows of `opts.window`
//! seconds, each with terminal events):
//! - **Inserted** — the bottom face reaches `opts.target_depth`.
//! - **Exited** — the bottom face rises above the hole's edge fillet
//!   (depth < `ρ_h`): the loads pull the peg out.
//! - A window in which the depth advances less than `opts.stall_distance`
//!   is a **stall**, classified at its end:
//!   - **Wedged** — two-point contact (edge and wall forces both positive)
//!     and the line joining the two contact points lies inside both friction
//!     cones (angle to each contact normal `≤ atan μ`): the two contact
//!     forces can balance each other whatever the applied load (the paper's
//!     §4.2, Whitney's wedging geometry).
//!   - **Jammed** — any other stall in contact: the contact forces, inside
//!     their friction cones, balance the applied load (the paper's §4.1).
//!   - **Stalled** — no contact force at all (the applied load does not
//!     push the peg in, e.g. zero axial force).
//! - **Unfinished** — `opts.t_max` reached while the peg still moves.
//!
//! With `opts.settle` a stuck run is classified before its window ends,
//! once it has settled (see [`Settle`]).
//!
//! With the elastic friction law (`params.spec.friction_law`) a stuck peg
//! does not creep; the run integrates its 12 states and reports the first 8.
//!
//! With the regularized friction law a stuck peg creeps at a speed of the
//! order of `v_s`; `stall_distance` must exceed `v_s · window` times the
//! friction utilisation to see the stall (defaults: `v_s = 1e-5 m/s` in
//! scenes, window 20 ms, stall distance 2 µm).

use super::elastic::{ElasticSystem, N_STATE_ELASTIC};
use super::initial::PegState;
use super::params::{CompliantParams, FrictionLaw, Load};
use super::system::{CompliantSystem, N_STATE, Sample};
use crate::integrate::{
    Direction, Event, IntegrateError, Method, Options, Solver, Stats, StopReason,
};
use crate::system::OdeSystem;
use nalgebra::SVector;

/// Options of [`simulate_insertion`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InsertionOptions {
    /// Depth of the bottom face at which the insertion counts as done (m).
    pub target_depth: f64,
    /// Longest simulated time (s).
    pub t_max: f64,
    /// Length of a classification window (s).
    pub window: f64,
    /// Depth progress per window below which the peg counts as stuck (m).
    pub stall_distance: f64,
    /// Relative and absolute tolerances of the integrator.
    pub rtol: f64,
    /// Absolute tolerance (state units: m, rad, m/s, J).
    pub atol: f64,
    /// The integrator: `Dopri5` (the default; explicit, steps limited by
    /// the contact frequency and the friction time constant, reliable) or
    /// `Rodas3` (linearly implicit with the generated exact Jacobian: steps
    /// far longer than the contact period where the motion is smooth).
    pub integrator: Method,
    /// Early stop of a stuck run before its window ends (`None`: only
    /// the window rule).
    pub settle: Option<Settle>,
}

/// The early-stop rule: a stuck run is classified as soon as it has
/// settled, not only at the end of its classification window.
///
/// Every `interval` seconds the run counts as *settled* when, over that
/// interval, (a) the depth advanced less than `stall_distance · interval /
/// window` (the window rule's mean speed), (b) at its end every speed
/// `|ẋ|`, `|ż|`, `r|θ̇|` is below `stall_distance / window`, and (c) the
/// edge and wall normal forces each changed by less than `force_rtol`
/// times the larger of their two values (forces below `1e-9 · |f₁|`
/// count as zero). A settled run is classified like a stall at the end
/// of a window (wedged / jammed / stalled). Inserted and exited runs end
/// at their events as before.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settle {
    /// Time between checks (s), shorter than the window.
    pub interval: f64,
    /// Relative change of the contact forces over one interval.
    pub force_rtol: f64,
}

impl Settle {
    /// Checks every tenth of `window`, forces steady to 1e-2.
    pub fn for_window(window: f64) -> Settle {
        Settle {
            interval: 0.1 * window,
            force_rtol: 1e-2,
        }
    }
}

impl Default for InsertionOptions {
    fn default() -> Self {
        InsertionOptions {
            target_depth: 0.02,
            t_max: 1.0,
            window: 0.02,
            stall_distance: 2e-6,
            rtol: 1e-6,
            atol: 1e-10,
            integrator: Method::Dopri5,
            settle: None,
        }
    }
}

/// How an insertion ended (an expected outcome, not an error).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum InsertionOutcome {
    /// The target depth was reached at time `t`.
    Inserted {
        /// Time, s.
        t: f64,
    },
    /// Stuck in two-point contact with the contact line inside both
    /// friction cones.
    Wedged {
        /// Time of the classification, s.
        t: f64,
        /// Depth of the bottom face, m.
        depth: f64,
        /// Tilt θ, rad.
        theta: f64,
        /// Normal force at the hole edge, N.
        f_edge: f64,
        /// Normal force at the wall, N.
        f_wall: f64,
    },
    /// Stuck in contact, the contact forces balancing the applied load.
    Jammed {
        /// Time of the classification, s.
        t: f64,
        /// Depth of the bottom face, m.
        depth: f64,
        /// Tilt θ, rad.
        theta: f64,
        /// Normal force at the hole edge, N.
        f_edge: f64,
        /// Normal force at the wall, N.
        f_wall: f64,
    },
    /// Not moving and not in contact.
    Stalled {
        /// Time of the classification, s.
        t: f64,
        /// Depth of the bottom face, m.
        depth: f64,
    },
    /// The peg left the hole at time `t`.
    Exited {
        /// Time, s.
        t: f64,
    },
    /// Still moving at `t_max`.
    Unfinished {
        /// Time (`t_max`), s.
        t: f64,
        /// Depth of the bottom face, m.
        depth: f64,
    },
    /// The integrator could not continue (step size underflow, non-finite
    /// values, step budget).
    Failed {
        /// Why the integrator stopped.
        reason: StopReason,
    },
}

/// The outcome with the final state and the integrator's work.
#[derive(Clone, Debug)]
pub struct InsertionRun {
    /// How the insertion ended.
    pub outcome: InsertionOutcome,
    /// Time and state at the end.
    pub t: f64,
    /// State at the end (the elastic law's first 8 components:
    /// coordinates, velocities, work, dissipation).
    pub y: SVector<f64, N_STATE>,
    /// Contact and energy quantities at the end.
    pub last: Sample,
    /// Integrator counters summed over all windows.
    pub stats: Stats,
}

/// Whether the segment between the two contact points of a two-point state
/// lies inside both friction cones (see the module documentation).
pub fn contact_line_in_cones(params: &CompliantParams, y: &SVector<f64, N_STATE>) -> bool {
    let g = &params.spec.geometry;
    let (x, z, theta) = (y[0], y[1], y[2]);
    // Mirror a negative lean onto a positive one.
    let (x, theta) = if theta < 0.0 {
        (-x, -theta)
    } else {
        (x, theta)
    };
    let (s, c) = theta.sin_cos();
    let half_d = 0.5 * g.hole_diameter;
    // Edge contact point on the left edge fillet, normal e_r on the peg.
    let (ax, az) = (
        -(half_d + g.hole_fillet) + g.hole_fillet * c,
        g.hole_fillet - g.hole_fillet * s,
    );
    // Wall contact point on the right wall, normal (−1, 0) on the peg.
    let lc = params.spec.com_height;
    let bz = z + (lc - g.peg_fillet) * c - (g.peg_radius - g.peg_fillet) * s;
    let (bx, _) = (half_d, x);
    let (dx, dz) = (bx - ax, bz - az);
    let len = dx.hypot(dz);
    let cone = params.spec.friction.atan();
    // Angle between A→B and n_A = (cos θ, −sin θ); between B→A and n_B = (−1, 0).
    let angle_a = ((dx * c - dz * s) / len).clamp(-1.0, 1.0).acos();
    let angle_b = (dx / len).clamp(-1.0, 1.0).acos();
    angle_a <= cone && angle_b <= cone
}

/// Simulates the insertion of the peg from `initial` under the constant
/// `load`, and classifies how it ends (see the module documentation).
///
/// # Errors
/// [`IntegrateError`] for invalid options (tolerances, times) or a
/// non-finite initial state.
pub fn simulate_insertion(
    params: &CompliantParams,
    load: &Load,
    initial: &PegState,
    opts: &InsertionOptions,
) -> Result<InsertionRun, IntegrateError> {
    match params.spec.friction_law {
        FrictionLaw::Regularized => {
            let sys = CompliantSystem::new(params, load);
            run(&sys, params, load, initial.to_vector(), opts)
        }
        FrictionLaw::Elastic => {
            let sys = ElasticSystem::new(params, load);
            run(&sys, params, load, initial.to_vector_elastic(), opts)
        }
    }
}

/// A compliant-peg system of `N` states whose first 8 are those of
/// [`CompliantSystem`].
trait PegSystem<const N: usize>: OdeSystem<N> {
    fn sample_of(&self, y: &SVector<f64, N>) -> Sample;
}

impl PegSystem<N_STATE> for CompliantSystem {
    fn sample_of(&self, y: &SVector<f64, N_STATE>) -> Sample {
        self.sample(y)
    }
}

impl PegSystem<N_STATE_ELASTIC> for ElasticSystem {
    fn sample_of(&self, y: &SVector<f64, N_STATE_ELASTIC>) -> Sample {
        self.sample(y)
    }
}

fn first8<const N: usize>(y: &SVector<f64, N>) -> SVector<f64, N_STATE> {
    SVector::from_fn(|i, _| y[i])
}

fn run<const N: usize, S: PegSystem<N>>(
    sys: &S,
    params: &CompliantParams,
    load: &Load,
    y0: SVector<f64, N>,
    opts: &InsertionOptions,
) -> Result<InsertionRun, IntegrateError> {
    let lc = params.spec.com_height;
    let exit_depth = params.spec.geometry.hole_fillet;
    let target = opts.target_depth;
    let depth = move |y: &SVector<f64, N>| y[1] + lc * y[2].cos();
    let mut stats = Stats::default();
    let (mut t, mut y) = (0.0, y0);
    let finish = |outcome, t, y: SVector<f64, N>, stats| InsertionRun {
        outcome,
        t,
        y: first8(&y),
        last: sys.sample_of(&y),
        stats,
    };
    let method = opts.integrator;
    let chunk = opts
        .settle
        .map_or(opts.window, |s| s.interval.min(opts.window));
    let r = params.spec.geometry.peg_radius;
    let force_floor = 1e-9 * load.axial.abs();
    let v_max = opts.stall_distance / opts.window;
    // Start of the current classification window: time and depth.
    let (mut t_w, mut d_w) = (t, depth(&y));
    let mut last = sys.sample_of(&y);
    while t < opts.t_max {
        let window_end = (t_w + opts.window).min(opts.t_max);
        let t_end = (t + chunk).min(window_end);
        let mut options = Options::with_tolerances(opts.rtol, opts.atol);
        options.store = false;
        let mut solver = Solver::new(method, options)
            .with_event(
                Event::new(move |_, y| depth(y) - target)
                    .direction(Direction::Rising)
                    .terminal(),
            )
            .with_event(
                Event::new(move |_, y| depth(y) - exit_depth)
                    .direction(Direction::Falling)
                    .terminal(),
            );
        let sol = solver.solve(sys, t, y, t_end)?;
        stats += &sol.stats;
        let d0 = depth(&y);
        (t, y) = (sol.t_final, sol.x_final);
        match sol.stop {
            StopReason::Event { index: 0, t } => {
                return Ok(finish(InsertionOutcome::Inserted { t }, t, y, stats));
            }
            StopReason::Event { t, .. } => {
                return Ok(finish(InsertionOutcome::Exited { t }, t, y, stats));
            }
            StopReason::ReachedEnd => {}
            reason => return Ok(finish(InsertionOutcome::Failed { reason }, t, y, stats)),
        }
        let d1 = depth(&y);
        let now = sys.sample_of(&y);
        let window_done = t >= window_end;
        let stuck = if window_done {
            d1 - d_w < opts.stall_distance
        } else {
            let steady = |a: f64, b: f64, rtol: f64| {
                let (a, b) = (a.max(force_floor), b.max(force_floor));
                (a - b).abs() <= rtol * a.max(b)
            };
            opts.settle.is_some_and(|st| {
                d1 - d0 < opts.stall_distance * (chunk / opts.window)
                    && y[3].abs() < v_max
                    && y[4].abs() < v_max
                    && (r * y[5]).abs() < v_max
                    && steady(now.f_edge, last.f_edge, st.force_rtol)
                    && steady(now.f_wall, last.f_wall, st.force_rtol)
            })
        };
        last = now;
        if stuck {
            let s = now;
            let (f_edge, f_wall, theta) = (s.f_edge, s.f_wall, y[2]);
            let outcome =
                if f_edge > 0.0 && f_wall > 0.0 && contact_line_in_cones(params, &first8(&y)) {
                    InsertionOutcome::Wedged {
                        t,
                        depth: d1,
                        theta,
                        f_edge,
                        f_wall,
                    }
                } else if f_edge > 0.0 || f_wall > 0.0 {
                    InsertionOutcome::Jammed {
                        t,
                        depth: d1,
                        theta,
                        f_edge,
                        f_wall,
                    }
                } else {
                    InsertionOutcome::Stalled { t, depth: d1 }
                };
            return Ok(finish(outcome, t, y, stats));
        }
        if window_done {
            (t_w, d_w) = (t, d1);
        }
    }
    let d = depth(&y);
    Ok(finish(
        InsertionOutcome::Unfinished { t, depth: d },
        t,
        y,
        stats,
    ))
}
