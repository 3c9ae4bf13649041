//! The contact search's large property campaign: the CI test
//! (`tests/compliant_peg_3d/search_property.rs`, 10⁵ poses) run at a
//! larger count, with the same dense reference and random poses
//! (`tests/common/search_reference.rs`, included here by `#[path]`): tilt
//! 0 to π/2 (2 % upright, 2 % below 10⁻³ rad), any azimuth and spin, one
//! pair in turn brought to a penetration between −1 mm and 10 µm, and at
//! every pose all five pairs compared. Half the chunks use the Fig. 9 peg,
//! half the insertion scene's. One thread.
//!
//! `cargo run --release -p pegdyn-benches --bin search_campaign -- POSES
//! [FIRST_SEED]` (default 10⁶ poses in chunks of 10⁴, seeds from
//! `0x5EA_1000`); prints the running tally every 10⁵ poses and the CPU
//! time; exits with status 1 on any failure.

use pegdyn::compliant_peg_3d::{Pair, Peg3dParams};
use std::time::Instant;

#[path = "../../tests/common"]
mod common {
    pub mod rng;
    pub mod search_reference;
}

use common::search_reference::{SAMPLES, TOL, Tally, campaign};

/// The Fig. 9 peg (`tests/common/peg3d.rs`).
fn fig9() -> Peg3dParams {
    Peg3dParams::steel(0.04995, 0.070, 0.050, 1e-3, 1e-3, 0.1)
}

/// The insertion scene's peg (`scenes/insert_rcc.toml`).
fn insertion_peg() -> Peg3dParams {
    let big_d = 0.025;
    Peg3dParams::steel(big_d * (1.0 - 0.003), 0.05, big_d, 3e-4, 5e-4, 0.03)
}

const CHUNK: usize = 10_000;

fn report(t: &Tally, seconds: f64) {
    println!(
        "{} poses, {} pair searches, {seconds:.1} s wall: reference contacts by pair {:?} \
         ({:?}), of them valid (compared with the contact path) {:?}, misses and other \
         failures {}, unresolved plateaus {}, library-only minima {}, \
         largest gap error {:e} m, point error {:e} m (tolerance {TOL:e}), most arcs {}, \
         reference evaluations {} ({SAMPLES} samples per circle)",
        t.poses,
        t.searches,
        t.contacts,
        Pair::ALL,
        t.valid,
        t.failed,
        t.unresolved,
        t.library_only,
        t.gap_err,
        t.point_err,
        t.max_arcs,
        t.evals
    );
}

fn main() {
    let mut args = std::env::args().skip(1);
    let parse = |a: Option<String>, default: u64| match a.map(|s| s.parse::<u64>()) {
        None => Ok(default),
        Some(Ok(v)) => Ok(v),
        Some(Err(e)) => Err(e),
    };
    let (Ok(poses), Ok(seed)) = (
        parse(args.next(), 1_000_000),
        parse(args.next(), 0x5EA_1000),
    ) else {
        eprintln!("usage: search_campaign [POSES] [FIRST_SEED]");
        std::process::exit(2);
    };
    let pegs = [fig9(), insertion_peg()];
    let start = Instant::now();
    let mut total = Tally::default();
    let chunks = (poses as usize).div_ceil(CHUNK);
    for c in 0..chunks {
        let n = CHUNK.min(poses as usize - c * CHUNK);
        let t = campaign(&pegs[c % 2], seed + c as u64, n);
        total.merge(&t);
        if total.poses % 100_000 < CHUNK || c + 1 == chunks {
            report(&total, start.elapsed().as_secs_f64());
        }
    }
    for f in &total.failures {
        println!("failure: {f}");
    }
    if total.failed > 0 || total.gap_err > TOL || total.point_err > TOL {
        std::process::exit(1);
    }
}
