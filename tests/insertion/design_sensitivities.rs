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
        let k = FIELDS
            .iter()
            .position(|f| *f == r.parameter)
            .expect("a field");
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
        eprintln!(
            "{}: sensitivity {der:.10e}, difference {fd:.10e}, {e:.1e}",
            r.parameter
        );
        assert!(
            e <= 1e-5,
            "seat time along {}: sensitivity {der:e}, difference {fd:e}",
            r.parameter
        );
        checked.push(r.parameter);
    }
    assert!(checked.len() >= 8, "only {checked:?} resolved");
}

/// The short insertion's text with a `[sensitivities]` table naming
/// `fields`, and `extra` lines after `speed`.
fn scene_text(fields: &[&str], extra: &str) -> String {
    let mut text = include_str!("../../scenes/insert_rcc.toml").to_string();
    for (k, v) in [
        ("start_height", "-1e-3"),
        ("seat_depth", "0.002"),
        ("t_end", "0.3"),
    ] {
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("{k} ")))
            .expect("a shipped line")
            .to_string();
        text = text.replacen(&line, &format!("{k} = {v}"), 1);
    }
    let text = text.replacen("speed = 0.01 ", &format!("{extra}\nspeed = 0.01 "), 1);
    let names: Vec<String> = fields.iter().map(|f| format!("\"{f}\"")).collect();
    format!(
        "{text}\n[sensitivities]\nparameters = [{}]\n",
        names.join(", ")
    )
}

/// One row of the CSV: metric, parameter, flag, derivative cell.
type CsvRow = (String, String, String, String);

/// Runs `text` into a fresh directory: the summary's notes, the CSV's
/// rows (metric, parameter, flag, derivative cell) and whether the tornado
/// plot was written.
fn run_scene(text: &str) -> (Vec<String>, Vec<CsvRow>, bool) {
    use pegdyn::output::sink::Sink;
    use pegdyn::scene::{self, Progress, RunContext};
    let dir = std::env::temp_dir().join(format!(
        "pegdyn-rcc-sens-{}-{}",
        std::process::id(),
        text.len()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let loaded = scene::parse_named(text, "rcc").unwrap_or_else(|e| panic!("{e}"));
    let mut ctx = RunContext::new(Sink::directory(&dir, "rcc"), Progress::silent());
    let summary = loaded.run(&mut ctx).unwrap_or_else(|e| panic!("{e}"));
    let notes = summary
        .metrics
        .iter()
        .map(|m| format!("{m:?}"))
        .collect::<Vec<_>>();
    let csv = std::fs::read_to_string(dir.join("rcc.sensitivities.csv")).expect("the CSV");
    let rows = csv
        .lines()
        .skip(1)
        .map(|l| {
            let c: Vec<&str> = l.splitn(6, ',').collect();
            let cell = |k: usize| c.get(k).unwrap_or(&"").trim_matches('"').to_string();
            (cell(0), cell(1), cell(5), cell(3))
        })
        .collect();
    let svg = dir.join("rcc.sensitivities.svg").is_file();
    let _ = std::fs::remove_dir_all(&dir);
    (notes, rows, svg)
}

#[test]
fn the_table_writes_its_csv_tornado_and_ranking_and_refuses_unknown_fields() {
    let fields = ["peg.friction", "robot.lateral_error", "robot.speed"];
    let (notes, rows, svg) = run_scene(&scene_text(&fields, ""));
    // Every metric of the run along every field, unflagged here.
    for metric in ["seat_time_s", "final_depth_m", "peak_contact_force_N"] {
        for f in fields {
            let r = rows
                .iter()
                .find(|r| r.0 == metric && r.1 == f)
                .unwrap_or_else(|| panic!("{metric} / {f}: {rows:?}"));
            assert!(r.2.is_empty(), "{r:?}");
            assert!(r.3.parse::<f64>().is_ok(), "{r:?}");
        }
    }
    assert!(svg, "the tornado plot");
    assert!(
        notes
            .iter()
            .any(|n| n.contains("elasticities of seat_time_s") && n.contains("speed")),
        "{notes:?}"
    );
    // Under a force-controlled descent the speed moves nothing: a zero,
    // flagged.
    let (_, rows, _) = run_scene(&scene_text(&fields, "axial_force = 15.0"));
    let speed: Vec<_> = rows.iter().filter(|r| r.1 == "robot.speed").collect();
    assert!(!speed.is_empty());
    for r in speed {
        assert_eq!(r.2, "not used by this model", "{r:?}");
        assert_eq!(r.3.parse::<f64>().ok(), Some(0.0), "{r:?}");
    }
    // An unknown name is refused on the table's field, listing the valid
    // ones.
    let err = match pegdyn::scene::parse_named(&scene_text(&["peg.length"], ""), "rcc") {
        Ok(_) => panic!("an unknown field is accepted"),
        Err(e) => e.to_string(),
    };
    assert!(
        err.contains("sensitivities.parameters") && err.contains("wrist.lateral_stiffness"),
        "{err}"
    );
}
