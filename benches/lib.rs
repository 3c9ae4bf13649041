//! The one bench binary (`cargo bench`); see `benches/README.md` for the
//! commands and `docs/BENCHMARKS.md` for the results. Seeded inputs
//! (SplitMix64, seed 0). Bench ids name the model, the function and the
//! form (`generated` / `hand` / `interpreted`), or the scene, the method
//! and the tolerance.
//!
//! Short warm-up and measurement (0.3 s / 1 s, 10 samples) so that the
//! whole suite runs in a few minutes on a 2-core machine.

use criterion::{criterion_group, criterion_main};
use std::time::Duration;

#[macro_use]
mod list;
mod cases;
mod functions;
mod hand;
mod ops;
mod runs;
mod sensitivities;

criterion_group! {
    name = benches;
    config = criterion::Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    targets = functions::bench, ops::bench, runs::bench, sensitivities::bench
}
criterion_main!(benches);
