//! The cost of design sensitivities against the plain run they extend:
//! `scenes/insert_rcc_sensitivities.toml` (robot insertion through a
//! compliant wrist, 8 design fields, Dormand–Prince at rtol 1e-8 with the
//! error controlled on the state), timed as
//!
//! - `insert_rcc_sensitivities/plain`: the metrics' values of the plain
//!   run (`metric_values`: the run with the scene's terminal events, the
//!   windowed peaks and two-point onset located);
//! - `insert_rcc_sensitivities/8_fields`: the same run carrying the 8
//!   columns `∂y/∂q` and the metrics' derivatives (`compute`).
//!
//! The ratio of the two is the cost of the derivatives in plain runs;
//! central differences would take 16 plain runs for the same 8 fields.
//! Before timing, each prints its steps and evaluations.

use criterion::Criterion;
use pegdyn::scene::integrator::DefaultMethod;
use pegdyn::scene::kinds::insert_rcc::sensitivities::{compute, metric_values};
use pegdyn::scene::shared::compliant_peg_3d::design::FIELDS;
use pegdyn::scene::shared::compliant_peg_3d::insertion::RccScene;
use std::hint::black_box;
use std::time::Duration;

/// The shipped sensitivity scene and the slots of its fields.
fn scene() -> (RccScene, Vec<usize>) {
    let text = include_str!("../scenes/insert_rcc_sensitivities.toml");
    let mut doc: toml::Table = toml::from_str(text).expect("the shipped scene is TOML");
    doc.remove("kind");
    doc.remove("description");
    let scene: RccScene = doc
        .try_into()
        .expect("the shipped scene is an insert_rcc scene");
    let chosen = scene
        .sensitivities
        .as_ref()
        .expect("the shipped scene has a [sensitivities] table")
        .parameters
        .iter()
        .map(|name| {
            FIELDS
                .iter()
                .position(|f| f == name)
                .expect("the shipped fields exist")
        })
        .collect();
    (scene, chosen)
}

/// Benches the plain run and the sensitivity run of the shipped scene.
pub fn bench(c: &mut Criterion) {
    let (scene, chosen) = scene();
    let built = scene.build().expect("the shipped scene builds");
    let (spec, _) = scene.integrator.resolved(DefaultMethod::STIFF_CONTACT);
    let (rows, work) = compute(&scene, &built, &spec, &chosen).expect("the run");
    let work = work.expect("the run ends with derivatives");
    println!(
        "insert_rcc_sensitivities/8_fields: {} rows, {} steps, {} evaluations of the variational \
         system",
        rows.len(),
        work.steps,
        work.rhs_calls
    );
    let mut group = c.benchmark_group("insert_rcc_sensitivities");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(100))
        .measurement_time(Duration::from_secs(8));
    group.bench_function("plain", |b| {
        b.iter(|| metric_values(black_box(&scene), &built, &spec).expect("the run"))
    });
    group.bench_function("8_fields", |b| {
        b.iter(|| compute(black_box(&scene), &built, &spec, &chosen).expect("the run"))
    });
    group.finish();
}
