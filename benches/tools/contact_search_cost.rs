//! Cost of the contact search along an insertion: the poses of a run's
//! time series (`insert_rcc.csv`: centre of mass, tilt and azimuth; the
//! spin about the axis, which the file does not hold, taken as zero),
//! each searched cold ([`Peg3d::contacts`], every pair) many times, with
//! the arcs the certified search visits per pair. Run the scene first,
//! then `cargo run --release -p pegdyn-benches --bin contact_search_cost --
//! OUT/insert_rcc.csv` and state the machine's load beside the figures.

use nalgebra::{Unit, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::{Pair, Peg3d, Peg3dParams, Search, pose_state, prune};
use std::hint::black_box;
use std::time::Instant;

/// The insertion scene's peg (`scenes/insert_rcc.toml`).
fn insertion_peg() -> Peg3dParams {
    let big_d = 0.025;
    Peg3dParams::steel(big_d * (1.0 - 0.003), 0.05, big_d, 3e-4, 5e-4, 0.03)
}

fn main() {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "insert_rcc.csv".to_owned());
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("{path}: {e} (run `pegdyn run scenes/insert_rcc.toml --out DIR` first)");
            std::process::exit(1);
        }
    };
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name);
    let (Some(ct), Some(ca), Some(cx), Some(cy), Some(cz)) = (
        col("tilt_rad"),
        col("azimuth_rad"),
        col("px_m"),
        col("py_m"),
        col("pz_m"),
    ) else {
        eprintln!("{path}: not an insert_rcc time series");
        std::process::exit(1);
    };
    let prm = insertion_peg();
    let sys = Peg3d::new(prm);
    let pv = *sys.param_vector();
    let mut states = Vec::new();
    for line in lines {
        let v: Vec<f64> = line
            .split(',')
            .map(|s| s.parse().unwrap_or(f64::NAN))
            .collect();
        let (tilt, az) = (v[ct], v[ca]);
        let axis = Unit::new_normalize(Vector3::new(-az.sin(), az.cos(), 0.0));
        let q = UnitQuaternion::from_axis_angle(&axis, tilt);
        let p = Vector3::new(v[cx], v[cy], v[cz]);
        states.push(pose_state(p, q, Vector3::zeros(), Vector3::zeros()));
    }
    let (mut arcs, mut searched, mut contacts) = ([0usize; 5], [0usize; 5], 0usize);
    let mut points = [0usize; 5];
    let mut most = [0usize; 5];
    for y in &states {
        let x = Peg3d::pose(y);
        contacts += sys.contacts(y).len();
        for pair in Pair::ALL {
            if prune::can_touch(pair, &prm, &x) {
                let mut s = Search::default();
                black_box(s.minima(pair, &x, &pv, 0.0));
                let k = pair.index();
                searched[k] += 1;
                arcs[k] += s.work.arcs;
                points[k] += s.work.points;
                most[k] = most[k].max(s.work.arcs);
                if std::env::var("SHOW").is_ok() && s.work.arcs > 100 {
                    let m = Search::default().minima(pair, &x, &pv, 0.0);
                    let gaps: Vec<f64> = m.iter().map(|&a| pair.eval(&x, a, &pv).gap).collect();
                    eprintln!(
                        "{:?} {} arcs {:?} minima {m:?} gaps {gaps:?}",
                        pair,
                        s.work.arcs,
                        x.as_slice()
                    );
                }
            }
        }
    }
    let reps = 200;
    let start = Instant::now();
    for _ in 0..reps {
        for y in &states {
            black_box(sys.contacts(black_box(y)));
        }
    }
    let per = start.elapsed().as_secs_f64() / (reps * states.len()) as f64;
    println!(
        "{} poses, {contacts} contacts: {:.3} µs per search of every pair",
        states.len(),
        per * 1e6
    );
    for pair in Pair::ALL {
        let k = pair.index();
        println!(
            "  {:<10} searched at {:>4} poses, {:.1} arcs and {:.1} point evaluations per search (most arcs {})",
            pair.name(),
            searched[k],
            arcs[k] as f64 / searched[k].max(1) as f64,
            points[k] as f64 / searched[k].max(1) as f64,
            most[k]
        );
    }
}
