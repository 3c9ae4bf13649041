//! Benches of the compliant peg-in-hole (paper 001): generated right-hand
//! side and Jacobian, and whole integrations of the shipped insertion scene
//! and of a jammed peg with Dormand–Prince and Rosenbrock. Each integration
//! bench prints its achieved error against a tight reference once.

use criterion::Criterion;
use nalgebra::SVector;
use pegdyn::compliant::{CompliantParams, CompliantSpec, CompliantSystem, Load, PegState};
use pegdyn::integrate::{Method, Options, Solver};
use pegdyn::system::OdeSystem;
use std::hint::black_box;

fn params() -> CompliantParams {
    CompliantParams::try_new(CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1))
        .expect("reference spec")
}

/// (name, system, initial state, end time) of the two reference runs.
fn problems(p: &CompliantParams) -> Vec<(&'static str, CompliantSystem, SVector<f64, 8>, f64)> {
    let scene = CompliantSystem::new(
        p,
        &Load {
            axial: 5.0,
            radial: 0.0,
            torque: -0.002,
        },
    );
    let tilted = PegState::two_point(p, 0.01, 0.0)
        .expect("two-point start")
        .to_vector();
    let jam = CompliantSystem::new(
        p,
        &Load {
            axial: 2.0,
            radial: 50.0,
            torque: 0.0,
        },
    );
    let mut side = PegState::centred(p, 0.02);
    side.x = 0.025 - p.spec.geometry.peg_radius + 2e-7;
    vec![
        ("insert_compliant", scene, tilted, 0.1),
        ("jammed", jam, side.to_vector(), 0.5),
    ]
}

fn solve(
    sys: &CompliantSystem,
    y0: SVector<f64, 8>,
    t_end: f64,
    method: Method,
    rtol: f64,
) -> SVector<f64, 8> {
    let mut o = Options::with_tolerances(rtol, rtol * 1e-4);
    o.store = false;
    o.max_steps = 50_000_000;
    Solver::new(method, o)
        .solve(sys, 0.0, y0, t_end)
        .map(|s| s.x_final)
        .unwrap_or(y0)
}

/// Registers the compliant benches.
pub fn bench(c: &mut Criterion) {
    let p = params();
    let probs = problems(&p);
    let (_, sys, y0, _) = &probs[0];
    c.bench_function("compliant_peg/rhs", |b| {
        b.iter(|| sys.rhs(0.0, black_box(y0)))
    });
    c.bench_function("compliant_peg/jacobian", |b| {
        b.iter(|| sys.jacobian(0.0, black_box(y0)))
    });
    for (name, sys, y0, t_end) in &probs {
        let reference = solve(sys, *y0, *t_end, Method::Dopri5, 1e-11);
        for (mname, method) in [("dopri5", Method::Dopri5), ("rodas3", Method::Rodas3)] {
            let rtol = 1e-6;
            let y = solve(sys, *y0, *t_end, method, rtol);
            let err = (y - reference).fixed_rows::<2>(0).abs().max();
            println!("{name}/{mname}/rtol{rtol:e}: position error {err:.2e} m");
            c.bench_function(&format!("{name}/{mname}/rtol{rtol:e}"), |b| {
                b.iter(|| solve(sys, black_box(*y0), *t_end, method, rtol))
            });
        }
    }
}
