//! The `[sensitivities]` table of `insert_compliant`: the derivatives in
//! `<scene>.sensitivities.csv` agree with Richardson-extrapolated central
//! differences of full scene runs (the same scene with one field changed,
//! its metric read from the same CSV); unknown names are refused naming
//! `sensitivities.parameters`; a field the model does not use is a zero
//! flagged as such; a metric at a non-differentiable point is flagged.

use std::collections::HashMap;

use crate::common::scene_text::with;
use pegdyn::output::memory::{Column, Keep};
use pegdyn::output::sink::Sink;
use pegdyn::scene::{self, Progress, RunContext};

/// A short run of the shipped scene at tight tolerances: the tilted
/// two-point start pushed in leaves two-point contact, strikes again
/// (the peak force), leaves again and is seated 0.2 mm deeper than it
/// started, at about 11 ms.
fn base() -> String {
    let text = crate::common::scene_text::shipped("insert_compliant");
    let text = with(&text, "rtol", "1e-11");
    let text = with(&text, "atol", "1e-15");
    let text = with(&text, "t_end", "0.014");
    let text = with(&text, "target_depth", "0.0106");
    format!(
        "{text}\n[sensitivities]\nparameters = [{}]\n",
        quoted(&FIELDS)
    )
}

/// The same run ended at 6 ms, before seating: its final depth.
fn unseated() -> String {
    with(&base(), "t_end", "0.006")
}

/// The fields compared with differences, with the key of their line in
/// the scene.
const FIELDS: [&str; 8] = [
    "insert_compliant.friction",
    "insert_compliant.clearance_ratio",
    "insert_compliant.axial_force",
    "insert_compliant.torque",
    "insert_compliant.initial_tilt",
    "insert_compliant.peg_fillet",
    "insert_compliant.density",
    "insert_compliant.hole_material.youngs_modulus",
];

fn quoted(names: &[&str]) -> String {
    names
        .iter()
        .map(|n| format!("\"{n}\""))
        .collect::<Vec<_>>()
        .join(", ")
}

/// One CSV row: value, derivative, elasticity (NaN for an empty cell), flag.
type Row = (f64, f64, f64, String);

/// Runs `text` in memory and reads `<scene>.sensitivities.csv` by
/// (metric, parameter).
fn run(text: &str) -> HashMap<(String, String), Row> {
    let loaded = scene::parse_named(text, "sens").unwrap_or_else(|e| panic!("{e}"));
    let mut ctx = RunContext::new(Sink::memory("sens", Keep::Tables), Progress::silent());
    loaded.run(&mut ctx).unwrap_or_else(|e| panic!("{e}"));
    let tables = ctx.into_sink().into_tables();
    let t = tables
        .iter()
        .find(|t| t.file == "sens.sensitivities.csv")
        .expect("the sensitivities table");
    let cells = |k: usize| -> Vec<String> {
        match &t.columns[k] {
            Column::Text(v) => v.clone(),
            Column::Numbers(v) => v.iter().map(|x| x.to_string()).collect(),
        }
    };
    let num = |s: &String| s.parse::<f64>().unwrap_or(f64::NAN);
    let cols: Vec<Vec<String>> = (0..6).map(cells).collect();
    (0..cols[0].len())
        .map(|i| {
            (
                (cols[0][i].clone(), cols[1][i].clone()),
                (
                    num(&cols[2][i]),
                    num(&cols[3][i]),
                    num(&cols[4][i]),
                    cols[5][i].clone(),
                ),
            )
        })
        .collect()
}

/// The scene's line key and value of `field` (`insert_compliant.x` → `x`;
/// the hole material's modulus is the second `youngs_modulus` line).
fn set(text: &str, field: &str, v: f64) -> String {
    if field == "insert_compliant.hole_material.youngs_modulus" {
        let (head, tail) = text.split_at(text.find("[insert_compliant.hole_material]").unwrap());
        return format!("{head}{}", with(tail, "youngs_modulus", &format!("{v:e}")));
    }
    let key = field.rsplit('.').next().unwrap();
    with(text, key, &format!("{v:e}"))
}

/// Below this elasticity the differences are compared with the
/// derivative of this elasticity instead of their own size (measured:
/// `∂t_2pt/∂peg_fillet`, elasticity 1.3e-3, agrees to 5e-5 of itself;
/// `∂F_peak/∂density`, elasticity 4e-8, is rounding in both).
const ELASTICITY_FLOOR: f64 = 0.1;

/// The largest relative difference between the derivatives of `metrics`
/// in the run of `text` and central differences of full runs (step
/// `1e-3 q`, Richardson-extrapolated with `h/2`), over [`FIELDS`].
fn worst_difference(text: &str, metrics: &[&str]) -> f64 {
    let rows = run(text);
    let mut worst = 0.0_f64;
    for field in FIELDS {
        let q = value_of(text, field);
        let h = 1e-3 * q.abs();
        let at = |v: f64| run(&set(text, field, v));
        let (u1, d1, u2, d2) = (at(q + h), at(q - h), at(q + 0.5 * h), at(q - 0.5 * h));
        for m in metrics {
            let key = ((*m).to_owned(), field.to_owned());
            let (value, derivative, _, flag) = &rows[&key];
            assert!(flag.is_empty(), "{m} by {field} flagged: {flag}");
            assert!(value.is_finite() && derivative.is_finite(), "{key:?}");
            let c1 = (u1[&key].0 - d1[&key].0) / (2.0 * h);
            let c2 = (u2[&key].0 - d2[&key].0) / h;
            let fd = (4.0 * c2 - c1) / 3.0;
            // Relative to the derivative, or, where the elasticity
            // q/m dm/dq is below ELASTICITY_FLOOR, to the derivative of
            // that elasticity: a field that barely moves the metric moves
            // it by less than the runs' rounding over the step.
            let floor = ELASTICITY_FLOOR * value.abs() / q.abs();
            let err = (derivative - fd).abs() / fd.abs().max(floor);
            eprintln!("d{m}/d{field}: {derivative:e} vs {fd:e}: {err:.1e}");
            worst = worst.max(err);
        }
    }
    worst
}

#[test]
fn derivatives_match_differences_of_full_scene_runs() {
    // The two scenes' runs are independent: one on each core.
    let (seated, unseated) = rayon::join(
        || {
            worst_difference(
                &base(),
                &[
                    "seat_time_s",
                    "peak_contact_force_N",
                    "two_point_start_s",
                    "two_point_end_s",
                    "two_point_depth_m",
                ],
            )
        },
        || worst_difference(&unseated(), &["final_depth_m"]),
    );
    eprintln!("worst: {seated:e} (seated run), {unseated:e} (final depth)");
    assert!(
        seated < 1e-5 && unseated < 1e-5,
        "worst relative error {seated:e} (seated), {unseated:e} (final depth)"
    );
}

/// The value of `field` as written in `text`.
fn value_of(text: &str, field: &str) -> f64 {
    let (text, key) = if field == "insert_compliant.hole_material.youngs_modulus" {
        (
            &text[text.find("[insert_compliant.hole_material]").unwrap()..],
            "youngs_modulus",
        )
    } else {
        (text, field.rsplit('.').next().unwrap())
    };
    let line = text
        .lines()
        .find(|l| l.starts_with(&format!("{key} =")))
        .unwrap();
    line.split('=')
        .nth(1)
        .unwrap()
        .split('#')
        .next()
        .unwrap()
        .trim()
        .parse()
        .unwrap()
}

#[test]
fn unknown_names_are_refused_with_the_valid_ones() {
    let text = with(
        &base(),
        "parameters",
        "[\"insert_compliant.friction\", \"insert_compliant.mu\"]",
    );
    let err = scene::parse(&text).unwrap_err();
    let e = &err.errors[0].error;
    assert_eq!(e.field(), Some("sensitivities.parameters"));
    let msg = e.to_string();
    assert!(
        msg.contains("insert_compliant.mu") && msg.contains("insert_compliant.hole_diameter"),
        "{msg}"
    );
}

#[test]
fn a_field_the_model_does_not_use_is_a_flagged_zero() {
    let text = with(
        &unseated(),
        "parameters",
        "[\"insert_compliant.tangential_damping\", \"insert_compliant.friction\"]",
    );
    let rows = run(&text);
    let (_, d, e, flag) = &rows[&(
        "final_depth_m".to_owned(),
        "insert_compliant.tangential_damping".to_owned(),
    )];
    assert_eq!((*d, *e), (0.0, 0.0));
    assert_eq!(flag, "not used by this model");
    let (_, d, _, flag) = &rows[&(
        "final_depth_m".to_owned(),
        "insert_compliant.friction".to_owned(),
    )];
    assert!(flag.is_empty() && *d != 0.0, "{d} {flag}");
}

#[test]
fn a_run_ending_at_t_end_just_short_of_seating_is_flagged() {
    // The same short run with the target just beyond the depth reached at
    // t_end: a 0.1 % change of the load seats it.
    let short = unseated();
    let rows = run(&short);
    let key = (
        "final_depth_m".to_owned(),
        "insert_compliant.axial_force".to_owned(),
    );
    let (depth, d, _, flag) = rows[&key].clone();
    assert!(flag.is_empty() && d > 0.0, "{d} {flag}");
    let just = with(&short, "target_depth", &format!("{:e}", depth + 1e-4 * d));
    let rows = run(&just);
    let (_, d, _, flag) = &rows[&key];
    assert!(d.is_nan() && flag.contains("seats the peg"), "{d} {flag}");
    let (_, _, _, seat) = &rows[&("seat_time_s".to_owned(), key.1.clone())];
    assert_eq!(seat, "not seated within t_end");
}

/// The shipped sensitivity scene naming `fields`, with `limits` (the body
/// of a `[limits]` table).
fn shipped_with(fields: &[&str], limits: &str) -> String {
    let text = crate::common::scene_text::shipped("insert_compliant_sensitivities");
    let head = &text[..=text.find("\n[sensitivities]").unwrap()];
    format!(
        "{head}[sensitivities]\nparameters = [{}]\n[limits]\n{limits}\n",
        quoted(fields)
    )
}

/// The shipped scene's fields: eight that move something, one that does
/// not.
const SHIPPED: [&str; 9] = [
    "insert_compliant.friction",
    "insert_compliant.clearance_ratio",
    "insert_compliant.hole_diameter",
    "insert_compliant.axial_force",
    "insert_compliant.torque",
    "insert_compliant.initial_tilt",
    "insert_compliant.peg_fillet",
    "insert_compliant.peg_material.youngs_modulus",
    "insert_compliant.tangential_damping",
];

/// The errors of parsing `text` naming `sensitivities.parameters`, as text.
fn sensitivity_limit_errors(text: &str) -> Vec<String> {
    match scene::parse(text) {
        Ok(_) => Vec::new(),
        Err(e) => e
            .errors
            .iter()
            .filter(|l| l.error.field() == Some("sensitivities.parameters"))
            .map(|l| l.error.to_string())
            .collect(),
    }
}

#[test]
fn the_sensitivity_run_counts_against_the_limits() {
    // The shipped scene (default integrator.max_steps = 10^6) passes the
    // default limits: (1 + 8) 10^6 steps of the model's states.
    let shipped = crate::common::scene_text::shipped("insert_compliant_sensitivities");
    assert!(
        SHIPPED
            .iter()
            .all(|f| shipped.contains(&format!("\"{f}\"")))
    );
    assert!(scene::parse(&shipped).is_ok());
    assert!(scene::parse(&shipped_with(&SHIPPED, "")).is_ok());
    // Below (1 + 8) 10^6, the sensitivity run is refused naming the field
    // and the limit, with how to raise it; the plain run (10^6) is not.
    let errors = sensitivity_limit_errors(&shipped_with(&SHIPPED, "max_steps = 8_999_999"));
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains("max_steps")
            && errors[0].contains("9.000e6")
            && errors[0].contains("[limits] max_steps"),
        "{}",
        errors[0]
    );
    assert!(scene::parse(&shipped_with(&SHIPPED, "max_steps = 9_000_000")).is_ok());
    // The estimate follows the fields integrated: three fields that move
    // something, and one that does not (it adds nothing).
    let four = [SHIPPED[0], SHIPPED[3], SHIPPED[4], SHIPPED[8]];
    assert!(scene::parse(&shipped_with(&four, "max_steps = 4_000_000")).is_ok());
    let errors = sensitivity_limit_errors(&shipped_with(&four, "max_steps = 3_999_999"));
    assert!(
        errors.len() == 1 && errors[0].contains("4.000e6"),
        "{errors:?}"
    );
    // The plain pass keeps every step: 10^6 of them exceed a sample limit
    // that the plain run's 602 output samples meet.
    let errors = sensitivity_limit_errors(&shipped_with(&SHIPPED, "max_output_samples = 1000"));
    assert!(
        errors.len() == 1 && errors[0].contains("max_output_samples"),
        "{errors:?}"
    );
}
