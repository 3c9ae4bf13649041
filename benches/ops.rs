//! Per-operation cost on this machine, for the op-count floor of
//! `docs/BENCHMARKS.md`: each bench applies one operation to every element
//! of a seeded 256-element array (independent operations, so this measures
//! throughput, as straight-line generated code with many independent
//! subexpressions can reach). Ids `ops/<op>`; ns per operation = time / 256.
//! The compiler may vectorize add/mul/div/sqrt (SSE2, 2 lanes) as it may in
//! generated code; library calls (sin, tanh, powf) stay scalar.

use criterion::{Criterion, Throughput};
use std::hint::black_box;

use super::cases::Rng;

/// Elements per iteration.
pub const LEN: usize = 256;

/// Registers the `ops` group.
pub fn bench(c: &mut Criterion) {
    let mut rng = Rng(1);
    let a: Vec<f64> = (0..LEN).map(|_| rng.uniform(0.5, 2.0)).collect();
    let b: Vec<f64> = (0..LEN).map(|_| rng.uniform(0.5, 2.0)).collect();
    let mut out = vec![0.0; LEN];
    let mut group = c.benchmark_group("ops");
    group.throughput(Throughput::Elements(LEN as u64));
    let mut op = |name: &str, f: fn(f64, f64) -> f64| {
        group.bench_function(name, |bench| {
            bench.iter(|| {
                let (a, b) = (black_box(&a), black_box(&b));
                for ((o, &x), &y) in out.iter_mut().zip(a).zip(b) {
                    *o = f(x, y);
                }
                black_box(&mut out);
            })
        });
    };
    op("add", |x, y| x + y);
    op("mul", |x, y| x * y);
    op("div", |x, y| x / y);
    op("sqrt", |x, _| x.sqrt());
    op("sin", |x, _| x.sin());
    op("tanh", |x, _| x.tanh());
    op("powf", |x, y| x.powf(y));
    op("branch", |x, y| if x > y { x } else { 0.0 });
    group.finish();
}
