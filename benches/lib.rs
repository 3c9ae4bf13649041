//! The one bench binary (`cargo bench`); see `benches/README.md` for the
//! commands. Bench ids name the model, the method and the tolerance.

use criterion::{criterion_group, criterion_main};

mod compliant;

criterion_group! {
    name = benches;
    config = criterion::Criterion::default().sample_size(10);
    targets = compliant::bench
}
criterion_main!(benches);
