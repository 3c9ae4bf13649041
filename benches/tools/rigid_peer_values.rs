//! pegdyn's side of the peer comparison `benches/peers/rigid_peg.py` (not a
//! test, not a bench: the Python script runs it and compares).
//!
//! ```sh
//! cargo run --release -p pegdyn-benches --bin rigid_peer_values -- values     < inputs.txt
//! cargo run --release -p pegdyn-benches --bin rigid_peer_values -- time 200000 9 < one_input.txt
//! cargo run --release -p pegdyn-benches --bin rigid_peer_values -- integrate 9 1e-6 1e-8 1e-10
//! ```
//!
//! An input line holds 25 numbers: x = (γ, ψ, γ̇, ψ̇), p = (D, d, H, m, g,
//! f, γ0), loads = (M_γ, M_ψ, F_x, F_y, F_z), t (9 friction-direction
//! components), the inputs of `pegdyn::generated::rigid_peg::forward`.
//!
//! - `values`: per input line one JSON line with `a` (5×5, row-major), `b`,
//!   `u` (A⁻¹b by LU) and `xdot`, the right-hand side of
//!   `rigid_peg::forward::PegSystem` (exact Coulomb; friction directions from the
//!   state, so `t` is not used) for the peg and loads of the line (`null`
//!   where it is not defined).
//! - `time CALLS REPEATS`: ns per call (median of REPEATS loops of CALLS
//!   calls, inputs and outputs through `black_box`) of `forward`, of
//!   `forward` plus the 5×5 LU solve, and of `PegSystem::rhs`.
//! - `integrate REPEATS RTOL...`: `scenes/align_forward.toml` without events
//!   (`PegSystem`, exact Coulomb) from its initial state to t = 12 ms (before
//!   its lift-off of K at 12.98 ms) by DOPRI5 at each rtol (atol = 1e-2 rtol,
//!   as `benches/tools/work_precision`), plus a reference at rtol 1e-14: final
//!   state, counters and median wall time (ms) per line.

use std::hint::black_box;
use std::io::Read;
use std::process::ExitCode;
use std::time::Instant;

use nalgebra::{SMatrix, SVector, Vector4};
use pegdyn::generated::rigid_peg;
use pegdyn::integrate::{Method, Options, Solver};
use pegdyn::rigid_peg::forward::{ForwardModel, PegSystem};
use pegdyn::rigid_peg::{Loads, PegParams};
use pegdyn::scene::document::Document;
use pegdyn::scene::kinds::align_forward::AlignForwardScene;
use pegdyn::system::OdeSystem;

/// The inputs of `rigid_peg::forward`.
struct Input {
    x: SVector<f64, 4>,
    p: SVector<f64, 7>,
    loads: SVector<f64, 5>,
    t: SVector<f64, 9>,
}

impl Input {
    fn parse(line: &str) -> Result<Input, String> {
        let v: Vec<f64> = line
            .split_whitespace()
            .map(|w| w.parse::<f64>().map_err(|e| format!("{w:?}: {e}")))
            .collect::<Result<_, _>>()?;
        if v.len() != 25 {
            return Err(format!("expected 25 numbers, got {}", v.len()));
        }
        Ok(Input {
            x: SVector::from_column_slice(&v[0..4]),
            p: SVector::from_column_slice(&v[4..11]),
            loads: SVector::from_column_slice(&v[11..16]),
            t: SVector::from_column_slice(&v[16..25]),
        })
    }

    /// The forward model of the line's peg and loads (γ0 recomputed).
    fn model(&self) -> Option<ForwardModel> {
        let p = PegParams {
            hole_diameter: self.p[0],
            peg_diameter: self.p[1],
            height: self.p[2],
            mass: self.p[3],
            gravity: self.p[4],
            friction: self.p[5],
        };
        let l = &self.loads;
        let loads = Loads {
            m_gamma: l[0],
            m_psi: l[1],
            force: [l[2], l[3], l[4]],
        };
        ForwardModel::new(p, loads).ok()
    }
}

fn json(v: impl IntoIterator<Item = f64>) -> String {
    let items: Vec<String> = v.into_iter().map(|x| format!("{x:e}")).collect();
    format!("[{}]", items.join(","))
}

fn solve(a: SMatrix<f64, 5, 5>, b: SVector<f64, 5>) -> Option<SVector<f64, 5>> {
    a.lu().solve(&b)
}

fn values(text: &str) -> Result<(), String> {
    for line in text.lines().filter(|l| !l.trim().is_empty()) {
        let i = Input::parse(line)?;
        let rigid_peg::LinearSystem { a, b } = rigid_peg::forward(&i.x, &i.p, &i.loads, &i.t);
        let row_major = (0..5).flat_map(|r| (0..5).map(move |c| (r, c)));
        let u = solve(a, b).map_or("null".to_owned(), |u| json(u.iter().copied()));
        let xdot = i
            .model()
            .map(|m| {
                PegSystem {
                    model: &m,
                    start: None,
                }
                .rhs(0.0, &i.x)
            })
            .filter(|d| d.iter().all(|v| v.is_finite()))
            .map_or("null".to_owned(), |d| json(d.iter().copied()));
        println!(
            "{{\"a\":{},\"b\":{},\"u\":{u},\"xdot\":{xdot}}}",
            json(row_major.map(|rc| a[rc])),
            json(b.iter().copied())
        );
    }
    Ok(())
}

/// Median over `repeats` loops of `calls` calls of `f`, in ns per call.
fn ns_per_call(calls: usize, repeats: usize, mut f: impl FnMut()) -> f64 {
    let mut v: Vec<f64> = (0..repeats.max(1))
        .map(|_| {
            let start = Instant::now();
            for _ in 0..calls {
                f();
            }
            start.elapsed().as_secs_f64() * 1e9 / calls as f64
        })
        .collect();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn time(text: &str, calls: usize, repeats: usize) -> Result<(), String> {
    let line = text
        .lines()
        .find(|l| !l.trim().is_empty())
        .ok_or("no input line")?;
    let i = Input::parse(line)?;
    let model = i.model().ok_or("invalid peg or loads")?;
    let system = PegSystem {
        model: &model,
        start: None,
    };
    // Warm-up.
    ns_per_call(calls, 1, || {
        black_box(rigid_peg::forward(&i.x, &i.p, &i.loads, &i.t));
    });
    let forward = ns_per_call(calls, repeats, || {
        black_box(rigid_peg::forward(
            black_box(&i.x),
            black_box(&i.p),
            black_box(&i.loads),
            black_box(&i.t),
        ));
    });
    let forward_lu = ns_per_call(calls, repeats, || {
        let rigid_peg::LinearSystem { a, b } = rigid_peg::forward(
            black_box(&i.x),
            black_box(&i.p),
            black_box(&i.loads),
            black_box(&i.t),
        );
        black_box(solve(a, b));
    });
    let rhs = ns_per_call(calls, repeats, || {
        black_box(system.rhs(0.0, black_box(&i.x)));
    });
    println!("{{\"forward_ns\":{forward:e},\"forward_lu_ns\":{forward_lu:e},\"rhs_ns\":{rhs:e}}}");
    Ok(())
}

fn integrate(repeats: usize, rtols: &[f64]) -> Result<(), String> {
    let text = include_str!("../../scenes/align_forward.toml");
    let scene: AlignForwardScene = Document::parse(text)
        .and_then(|d| d.body())
        .map_err(|e| e.to_string())?;
    let model = scene.forward_model().map_err(|e| e.to_string())?;
    let x0: Vector4<f64> = scene.initial_state();
    let t_end = 0.012;
    let system = PegSystem {
        model: &model,
        start: None,
    };
    let run = |rtol: f64| {
        let mut o = Options::with_tolerances(rtol, 1e-2 * rtol);
        o.store = false;
        o.max_steps = 20_000_000;
        Solver::new(Method::Dopri5, o).solve(&system, 0.0, x0, t_end)
    };
    println!(
        "{{\"x0\":{},\"t_end\":{t_end:e}}}",
        json(x0.iter().copied())
    );
    for &rtol in std::iter::once(&1e-14).chain(rtols) {
        let sol = run(rtol).map_err(|e| e.to_string())?;
        let mut times: Vec<f64> = (0..repeats.max(1))
            .map(|_| {
                // Batches of ≥ 5 ms, as benches/tools/work_precision.
                let start = Instant::now();
                let mut n = 0usize;
                while n == 0 || start.elapsed().as_secs_f64() < 5e-3 {
                    black_box(run(black_box(rtol)).ok());
                    n += 1;
                }
                start.elapsed().as_secs_f64() / n as f64
            })
            .collect();
        times.sort_by(f64::total_cmp);
        let s = sol.stats;
        println!(
            "{{\"rtol\":{rtol:e},\"t_final\":{:e},\"x_final\":{},\"steps\":{},\"rejected\":{},\"rhs_calls\":{},\"wall_ms\":{:e},\"stop\":\"{:?}\"}}",
            sol.t_final,
            json(sol.x_final.iter().copied()),
            s.steps,
            s.rejected,
            s.rhs_calls,
            times[times.len() / 2] * 1e3,
            sol.stop
        );
    }
    Ok(())
}

fn stdin() -> Result<String, String> {
    let mut s = String::new();
    std::io::stdin()
        .read_to_string(&mut s)
        .map_err(|e| e.to_string())?;
    Ok(s)
}

fn number<T: std::str::FromStr>(a: Option<&String>, what: &str) -> Result<T, String> {
    a.ok_or(format!("missing {what}"))?
        .parse()
        .map_err(|_| format!("bad {what}"))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("values") => stdin().and_then(|s| values(&s)),
        Some("time") => number(args.get(1), "CALLS").and_then(|c| {
            let r = number(args.get(2), "REPEATS")?;
            time(&stdin()?, c, r)
        }),
        Some("integrate") => number(args.get(1), "REPEATS").and_then(|r| {
            let rtols: Vec<f64> = args[2..]
                .iter()
                .map(|a| a.parse().map_err(|_| format!("bad rtol {a:?}")))
                .collect::<Result<_, _>>()?;
            integrate(r, &rtols)
        }),
        _ => Err(
            "usage: rigid_peer_values values | time CALLS REPEATS | integrate REPEATS RTOL..."
                .into(),
        ),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("rigid_peer_values: {e}");
            ExitCode::FAILURE
        }
    }
}
