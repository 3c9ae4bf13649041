//! Per-operation cost on this machine, for the op-count floor of
//! `docs/bench-methods.md`: each bench applies one operation to every element
//! of a seeded 256-element array (independent operations, so this measures
//! throughput, as straight-line generated code with many independent
//! subexpressions can reach). Ids `ops/<op>`; ns per operation = time / 256.
//! The compiler may vectorize add/mul/div/sqrt (SSE2, 2 lanes) as it may in
//! generated code; library calls (sin, powf, hypot: the transcendental calls the
//! generated code makes) stay scalar.

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, Throughput};
use std::hint::black_box;

use super::cases::Rng;

/// Elements per iteration.
pub const LEN: usize = 256;

/// Times `f` over the arrays (generic, so that `f` is inlined).
fn op(
    group: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    (a, b): (&[f64], &[f64]),
    f: impl Fn(f64, f64) -> f64,
) {
    let mut out = vec![0.0; LEN];
    group.bench_function(name, |bench| {
        bench.iter(|| {
            let (a, b) = (black_box(a), black_box(b));
            for ((o, &x), &y) in out.iter_mut().zip(a).zip(b) {
                *o = f(x, y);
            }
            black_box(&mut out);
        })
    });
}

/// Registers the `ops` group.
pub fn bench(c: &mut Criterion) {
    let mut rng = Rng(1);
    let a: Vec<f64> = (0..LEN).map(|_| rng.uniform(0.5, 2.0)).collect();
    let b: Vec<f64> = (0..LEN).map(|_| rng.uniform(0.5, 2.0)).collect();
    let ab = (a.as_slice(), b.as_slice());
    let mut group = c.benchmark_group("ops");
    group.throughput(Throughput::Elements(LEN as u64));
    op(&mut group, "add", ab, |x, y| x + y);
    op(&mut group, "mul", ab, |x, y| x * y);
    op(&mut group, "div", ab, |x, y| x / y);
    op(&mut group, "sqrt", ab, |x, _| x.sqrt());
    op(&mut group, "sin", ab, |x, _| x.sin());
    op(&mut group, "hypot", ab, |x, y| x.hypot(y));
    op(&mut group, "powf", ab, |x, y| x.powf(y));
    op(&mut group, "branch", ab, |x, y| if x > y { x } else { 0.0 });
    group.finish();
}
