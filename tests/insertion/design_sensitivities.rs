//! Forward sensitivities of a robot insertion in its design fields: every
//! metric's derivative (seat time, final depth, peak contact and wrist
//! forces, onset of two-point contact in time and depth) along every
//! field, against Richardson-extrapolated central differences of the
//! metric's value over runs with the field moved, on a short insertion
//! (the tip 0.2 mm above the mouth with a 3° angular error, seated just
//! past the onset of two-point contact).

use pegdyn::scene::integrator::DefaultMethod;
use pegdyn::scene::kinds::insert_rcc::sensitivities::{compute, metric_values};
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

/// The metrics' values of plain runs of `s`.
fn plain(s: &RccScene) -> Vec<(&'static str, f64)> {
    let built = s.build().expect("valid");
    let (spec, _) = s.integrator.resolved(DefaultMethod::STIFF_CONTACT);
    metric_values(s, &built, &spec)
        .expect("runs")
        .expect("ends")
}

#[test]
fn the_seat_time_s_derivative_matches_differences_of_runs_along_every_field() {
    let s = short();
    let all: Vec<usize> = (0..FIELDS.len()).collect();
    let base = rows(&s, &all);
    let q = values(&s);
    let seat_time = |k: usize, v: f64| {
        let mut moved = s.clone();
        *slot(&mut moved, k) = v;
        plain(&moved)
            .iter()
            .find(|(m, _)| *m == "seat_time_s")
            .map(|(_, v)| *v)
            .expect("the moved run seats")
    };
    let mut checked = Vec::new();
    for r in base.iter().filter(|r| r.metric == "seat_time_s") {
        assert!(r.flag.is_empty(), "{}: flagged {}", r.parameter, r.flag);
        let k = FIELDS.iter().position(|f| *f == r.parameter).expect("a field");
        let h = if q[k] == 0.0 { 1e-6 } else { 1e-4 * q[k].abs() };
        let central = |h: f64| (seat_time(k, q[k] + h) - seat_time(k, q[k] - h)) / (2.0 * h);
        let (d1, d2) = (central(h), central(0.5 * h));
        let fd = (4.0 * d2 - d1) / 3.0;
        let der = r.derivative.expect("unflagged");
        if fd == 0.0 {
            // The field does not reach the seat time (the mouth's fillet,
            // for a start in the bore): both exactly zero.
            assert_eq!(der, 0.0, "seat time along {}", r.parameter);
            continue;
        }
        // A derivative the differences resolve: their two steps agree to
        // 10⁻⁶ (the others are below the runs' tolerance over the step).
        if (d1 - d2).abs() > 1e-6 * fd.abs() {
            eprintln!(
                "{}: differences unresolved ({d1:e}, {d2:e}), sensitivity {der:e}",
                r.parameter
            );
            continue;
        }
        let e = (der - fd).abs() / fd.abs();
        eprintln!("{}: sensitivity {der:.10e}, difference {fd:.10e}, {e:.1e}", r.parameter);
        assert!(
            e <= 1e-5,
            "seat time along {}: sensitivity {der:e}, difference {fd:e}",
            r.parameter
        );
        checked.push(r.parameter);
    }
    assert!(checked.len() >= 8, "only {checked:?} resolved");
}
