//! Whole runs: the Fig. 9 table and the rigid forward alignment
//! (`scenes/align_forward.toml`; rigid three-point peg), the compliant
//! insertion scene (compliant planar peg) and each integrator on a reference problem. Bench ids:
//! `<scene>/<method>/<tolerance or step>`. Each integration prints its
//! achieved error against a tight reference once, before timing, so that
//! the time is read next to the accuracy it buys.

use criterion::Criterion;
use nalgebra::{SVector, Vector2};
use pegdyn::compliant_peg::{CompliantSystem, Load, PegState};
use pegdyn::integrate::{Direction, Event, Method, Options, Solution, Solver};
use pegdyn::reference_problems::{Pendulum, StiffLinear, VanDerPol};
use pegdyn::rigid_peg::prescribed::{fig9_rows, gamma_grid, reactions, reactions_hand};
use pegdyn::rigid_peg::{Loads, PegParams, RigidError};
use pegdyn::system::OdeSystem;
use std::hint::black_box;

use super::cases::{align_forward_scene, insertion_scene};
use pegdyn::integrate::OutputMode;
use pegdyn::rigid_peg::forward::ForwardModel;
use pegdyn::rigid_peg::trajectory::{Trajectory, simulate};
use pegdyn::scene::integrator::IntegratorSpec;

/// The signature of `reactions` and `reactions_hand`.
type Reactions = fn(
    &PegParams,
    &Loads,
    Vector2<f64>,
    Vector2<f64>,
    Vector2<f64>,
) -> Result<pegdyn::rigid_peg::prescribed::Reactions, RigidError>;

/// Integrates without storing the trajectory; `events` are made by
/// `event` (a fresh terminal event per run, if any).
fn solve<const N: usize, S: OdeSystem<N>>(
    sys: &S,
    y0: SVector<f64, N>,
    t_end: f64,
    method: Method,
    rtol: f64,
    event: Option<&dyn Fn() -> Event<'static, N>>,
) -> Solution<N> {
    let mut o = Options::with_tolerances(rtol, rtol * 1e-4);
    o.store = false;
    o.max_steps = 50_000_000;
    let mut solver = Solver::new(method, o);
    if let Some(e) = event {
        solver = solver.with_event(e());
    }
    solver.solve(sys, 0.0, y0, t_end).expect("valid options")
}

/// `rtol1e-8` or `h1e-2`: the id suffix of a method at a tolerance.
fn label(method: Method, rtol: f64) -> String {
    match method {
        Method::Rk4 { h } => format!("{}/h{h:e}", method.name()),
        _ => format!("{}/rtol{rtol:e}", method.name()),
    }
}

/// Benches `sys` with each `(method, rtol)`, printing the error of the
/// final state (max norm) against a DOPRI5 run at rtol 1e-12.
fn integrations<const N: usize, S: OdeSystem<N>>(
    c: &mut Criterion,
    scene: &str,
    sys: &S,
    (y0, t_end): (SVector<f64, N>, f64),
    runs: &[(Method, f64)],
    event: Option<&dyn Fn() -> Event<'static, N>>,
) {
    let reference = solve(sys, y0, t_end, Method::Dopri5, 1e-12, event);
    for &(method, rtol) in runs {
        let id = format!("{scene}/{}", label(method, rtol));
        let sol = solve(sys, y0, t_end, method, rtol, event);
        let err = (sol.x_final - reference.x_final).amax();
        println!(
            "{id}: error {err:.2e} at t = {:.4}, {} steps, {} rhs, {} jacobian calls",
            sol.t_final, sol.stats.steps, sol.stats.rhs_calls, sol.stats.jacobian_calls
        );
        c.bench_function(&id, |b| {
            b.iter(|| solve(sys, black_box(y0), t_end, method, rtol, event))
        });
    }
}

/// The rigid forward alignment as the scene runs it: `simulate` with the
/// scene's output times and span, `atol / rtol` as in the scene (1e-2).
fn rigid_run(
    model: &ForwardModel,
    x0: nalgebra::Vector4<f64>,
    spec: &IntegratorSpec,
    method: Method,
    rtol: f64,
) -> Trajectory {
    let mut o = Options::with_tolerances(rtol, rtol * spec.atol / spec.rtol);
    o.output = OutputMode::AtTimes(spec.output_times().collect());
    simulate(model, x0, spec.t0, spec.t_end, method, &o).expect("valid scene")
}

/// `scenes/align_forward.toml` (Fig. 9 peg, f = 0.2, released at γ = 0.3
/// rad with ψ̇ = 10 1/s under M_γ = −0.15 N·m; it stops at the lift-off of
/// K at t ≈ 0.013 s). Prints, before timing, the stop event, the error of
/// its time and of the state there against DOPRI5 at rtol 1e-13, and the
/// work (the rigid `PegSystem` has no analytic Jacobian: each RODAS3
/// Jacobian is a forward difference costing 5 right-hand sides, not
/// counted in `rhs`).
fn rigid_forward(c: &mut Criterion) {
    let (scene, model) = align_forward_scene();
    let x0 = scene.initial_state();
    let spec = &scene.integrator;
    let reference = rigid_run(&model, x0, spec, Method::Dopri5, 1e-13);
    let (t_ref, x_ref) = reference.stop.point().expect("reference stops at an event");
    for (method, rtol) in [
        (Method::Dopri5, 1e-6),
        (Method::Dopri5, 1e-10),
        (Method::Rk4 { h: 1e-4 }, 1e-6),
        (Method::Rodas3, 1e-6),
    ] {
        let id = format!("align_forward/{}", label(method, rtol));
        let tr = rigid_run(&model, x0, spec, method, rtol);
        let same = tr.stop.name() == reference.stop.name();
        let (dt, dx) = match (tr.stop.point(), same) {
            (Some((t, x)), true) => (
                (t - t_ref).abs(),
                x.zip(x_ref).map_or(f64::NAN, |(x, y)| (x - y).amax()),
            ),
            _ => (f64::NAN, f64::NAN),
        };
        println!(
            "{id}: stop `{}` (reference `{}`{}), event time error {dt:.2e} s, state error there {dx:.2e}, \
             {} steps, {} rhs, {} jacobian, {} event calls",
            tr.stop.name(),
            reference.stop.name(),
            if same { "" } else { ": DIFFERENT EVENT" },
            tr.stats.steps,
            tr.stats.rhs_calls,
            tr.stats.jacobian_calls,
            tr.stats.event_calls
        );
        c.bench_function(&id, |b| {
            b.iter(|| rigid_run(&model, black_box(x0), spec, method, rtol))
        });
    }
}

/// Registers the whole-run benches.
pub fn bench(c: &mut Criterion) {
    rigid_forward(c);

    // Fig. 9: 400 γ (geometric from γ0(1 + 1e-6) to 0.5 rad) × ψ̇ ∈ {0, 10}.
    let peg = PegParams::fig9();
    let g0 = peg.gamma0();
    let gammas = gamma_grid(g0, g0 * 1.000_001, 0.5, 400);
    c.bench_function("fig9/rows/400x2", |b| {
        b.iter(|| fig9_rows(black_box(&peg), &gammas, -2.0, &[0.0, 10.0]).expect("fig9"))
    });
    // The same 800 reactions through the generated model (what fig9_rows
    // uses) and through the hand-derived one.
    let all_reactions = |f: Reactions| {
        let mut sum = 0.0;
        for psidot in [0.0, 10.0] {
            for &gamma in &gammas {
                let q = Vector2::new(black_box(gamma), 0.0);
                let r = f(
                    &peg,
                    &Loads::default(),
                    q,
                    Vector2::new(-2.0, psidot),
                    Vector2::zeros(),
                );
                sum += r.expect("three-point range").normal[1];
            }
        }
        sum
    };
    c.bench_function("fig9/reactions/generated/400x2", |b| {
        b.iter(|| all_reactions(reactions))
    });
    c.bench_function("fig9/reactions/hand/400x2", |b| {
        b.iter(|| all_reactions(reactions_hand))
    });

    // The compliant insertion scene, to the target depth 0.03 m (event).
    let (params, load, start) = insertion_scene();
    let sys = CompliantSystem::new(&params, &load);
    let lc = params.spec.com_height;
    let inserted = move || {
        Event::new(move |_t, y: &SVector<f64, 8>| y[1] + lc * y[2].cos() - 0.03)
            .direction(Direction::Rising)
            .terminal()
    };
    integrations(
        c,
        "insert_compliant",
        &sys,
        (start.to_vector(), 0.3),
        &[
            (Method::Dopri5, 1e-8),
            (Method::Dopri5, 1e-6),
            (Method::Rodas3, 1e-6),
        ],
        Some(&inserted),
    );

    // A jammed peg (stiff: the peg rests on its contacts, μ·f_B balancing
    // the load): pushed sideways against the wall with 50 N, 2 N down.
    let jam = CompliantSystem::new(
        &params,
        &Load {
            axial: 2.0,
            radial: 50.0,
            torque: 0.0,
        },
    );
    let mut side = PegState::centred(&params, 0.02);
    side.x = 0.025 - params.spec.geometry.peg_radius + 2e-7;
    integrations(
        c,
        "jammed",
        &jam,
        (side.to_vector(), 0.5),
        &[(Method::Dopri5, 1e-6), (Method::Rodas3, 1e-6)],
        None,
    );

    // Reference problems: the pendulum over ~5 periods (non-stiff), the
    // stiff linear system and Van der Pol at μ = 100 (stiff).
    let pendulum = Pendulum { g_over_l: 9.81 };
    integrations(
        c,
        "pendulum",
        &pendulum,
        (Vector2::new(1.0, 0.0), 10.0),
        &[
            (Method::Rk4 { h: 1e-2 }, 1e-6),
            (Method::Dopri5, 1e-8),
            (Method::Rodas3, 1e-6),
        ],
        None,
    );
    integrations(
        c,
        "stiff_linear",
        &StiffLinear::standard(),
        (Vector2::new(1.0, 0.0), 5.0),
        &[(Method::Dopri5, 1e-6), (Method::Rodas3, 1e-6)],
        None,
    );
    integrations(
        c,
        "van_der_pol_mu100",
        &VanDerPol { mu: 100.0 },
        (Vector2::new(2.0, 0.0), 100.0),
        &[(Method::Dopri5, 1e-6), (Method::Rodas3, 1e-6)],
        None,
    );
}
