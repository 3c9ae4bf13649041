//! Forward sensitivities of a robot insertion in its design fields: every
//! metric's derivative (seat time, final depth, peak contact and wrist
//! forces, onset of two-point contact in time and depth) along every
//! field, against Richardson-extrapolated central differences of the
//! metric's value over runs with the field moved, on a short insertion
//! (the tip 0.2 mm above the mouth with a 3° angular error, seated just
//! past the onset of two-point contact).

use pegdyn::scene::integrator::DefaultMethod;
use pegdyn::scene::kinds::insert_rcc::sensitivities::compute;
use pegdyn::scene::shared::compliant_peg_3d::design::{FIELDS, slot, values};
use pegdyn::scene::shared::compliant_peg_3d::insertion::RccScene;
use pegdyn::scene::shared::sensitivities::Row;

/// The short insertion: the shipped scene with `changes`.
fn scene(changes: &[(&str, &str)]) -> RccScene {
    let base = include_str!("../../scenes/insert_rcc.toml");
    let text: String = base
        .lines()
        .map(|l| {
            for (k, v) in changes {
                if l.starts_with(&format!("{k} ")) {
                    return format!("{k} = {v}");
                }
            }
            l.to_string()
        })
        .collect::<Vec<_>>()
        .join("\n");
    let mut doc: toml::Table = toml::from_str(&text).expect("TOML");
    doc.remove("kind");
    doc.remove("description");
    doc.try_into().expect("an insert_rcc scene")
}

fn short() -> RccScene {
    scene(&[
        ("start_height", "-1e-3"),
        ("seat_depth", "0.002"),
        ("rtol", "1e-8"),
        ("atol", "1e-12"),
        ("t_end", "0.3"),
    ])
}

/// The rows of `s` for the fields `chosen`.
fn rows(s: &RccScene, chosen: &[usize]) -> Vec<Row> {
    let built = s.build().expect("valid");
    let (spec, _) = s.integrator.resolved(DefaultMethod::STIFF_CONTACT);
    compute(s, &built, &spec, chosen).expect("runs").0
}

#[test]
fn every_metric_s_derivative_matches_differences_of_runs() {
    let s = short();
    let all: Vec<usize> = (0..FIELDS.len()).collect();
    let start = std::time::Instant::now();
    let base = rows(&s, &all);
    eprintln!("sensitivity run: {:?}", start.elapsed());
    for r in &base {
        eprintln!(
            "{} {}: value {:?} derivative {:?} flag {}",
            r.metric, r.parameter, r.value, r.derivative, r.flag
        );
    }
    let q = values(&s);
    let value = |k: usize, v: f64, metric: &str| {
        let mut moved = s.clone();
        *slot(&mut moved, k) = v;
        rows(&moved, &[k])
            .iter()
            .find(|r| r.metric == metric)
            .and_then(|r| r.value)
    };
    let start = std::time::Instant::now();
    let _ = rows(&s, &[0]);
    eprintln!("one field: {:?}", start.elapsed());
    for k in 0..FIELDS.len() {
        let h = if q[k] == 0.0 { 1e-6 } else { 1e-4 * q[k].abs() };
        let metrics: Vec<&Row> = base
            .iter()
            .filter(|r| r.parameter == FIELDS[k] && r.flag.is_empty())
            .collect();
        for r in metrics {
            let central = |h: f64| {
                let up = value(k, q[k] + h, r.metric)?;
                let down = value(k, q[k] - h, r.metric)?;
                Some((up - down) / (2.0 * h))
            };
            let (Some(d1), Some(d2)) = (central(h), central(0.5 * h)) else {
                panic!("{} along {}: a moved run lost the metric", r.metric, r.parameter);
            };
            let fd = (4.0 * d2 - d1) / 3.0;
            let der = r.derivative.expect("unflagged");
            eprintln!(
                "{} / {}: sensitivity {der:.9e}, difference {fd:.9e}, {d1:.9e}",
                r.metric, r.parameter
            );
        }
    }
}
