//! End-to-end tests of the `pegdyn` binary: `check` and `run` on good and
//! bad scene files. Bad scenes must fail with exit code 1 and an error on
//! stderr that names the offending field and value.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::common::cli as cli_common;
use cli_common::pegdyn;

fn fixture(name: &str) -> String {
    format!("tests/fixtures/{name}")
}

/// A fresh output directory under the target dir, unique per test.
fn out_dir(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-{test}"));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// (fixture, field that must be named, bad value that must be named)
const BAD: &[(&str, &str, &str)] = &[
    ("missing_length.toml", "pendulum.length", "missing"),
    ("nan_mass.toml", "pendulum.mass", "NaN"),
    ("inf_angle.toml", "pendulum.theta0_deg", "inf"),
    ("negative_length.toml", "pendulum.length", "-0.5"),
    ("negative_mass.toml", "pendulum.mass", "-2"),
    ("unknown_kind.toml", "kind", "trebuchet"),
    ("bad_rtol.toml", "integrator.rtol", "-1e-6"),
    ("unknown_method.toml", "integrator.method", "euler"),
    ("unknown_field.toml", "pendulum.colour", "unknown field"),
    ("wrong_type.toml", "pendulum.mass", "\"heavy\""),
    ("zero_atol.toml", "integrator.atol", "0.0"),
    ("rk4_without_h.toml", "integrator.h", "missing"),
    ("t_end_before_t0.toml", "integrator.t_end", "1.0"),
];

fn assert_rejected(out: &Output, file: &str, field: &str, value: &str) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{file}: stderr: {stderr}");
    assert!(
        stderr.contains(&format!("`{field}`")),
        "{file}: field {field} not named in: {stderr}"
    );
    assert!(
        stderr.contains(value),
        "{file}: value {value} not named in: {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{file}: {stderr}");
}

#[test]
fn check_rejects_bad_scenes_naming_field_and_value() {
    for &(file, field, value) in BAD {
        let out = pegdyn(&["check", &fixture(file)]);
        assert_rejected(&out, file, field, value);
        assert!(
            out.stdout.is_empty(),
            "{file}: nothing on stdout for a bad scene"
        );
    }
}

#[test]
fn run_rejects_bad_scenes_naming_field_and_value_and_writes_nothing() {
    let dir = out_dir("bad");
    for &(file, field, value) in BAD {
        let out = pegdyn(&["run", &fixture(file), "--out", dir.to_str().unwrap()]);
        assert_rejected(&out, file, field, value);
    }
    assert!(!dir.exists(), "no output directory for rejected scenes");
}

#[test]
fn syntax_error_reports_line_and_column() {
    let out = pegdyn(&["check", &fixture("syntax_error.toml")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr.contains("line 8, column 12"), "{stderr}");
}

#[test]
fn check_accepts_shipped_scenes() {
    for scene in [
        "scenes/pendulum.toml",
        "scenes/double_pendulum.toml",
        &fixture("good_pendulum.toml"),
    ] {
        let out = pegdyn(&["check", scene]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{scene}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(stdout.contains("OK"), "{stdout}");
    }
}

#[test]
fn check_reports_every_bad_file_and_fails() {
    let out = pegdyn(&[
        "check",
        "scenes/pendulum.toml",
        &fixture("negative_mass.toml"),
        &fixture("nan_mass.toml"),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr.contains("negative_mass.toml") && stderr.contains("nan_mass.toml"),
        "{stderr}"
    );
}

#[test]
fn check_reports_every_problem_of_a_file() {
    let out = pegdyn(&["check", &fixture("two_errors.toml")]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    for (field, value) in [
        ("pendulum.length", "NaN"),
        ("pendulum.mass", "-1"),
        ("integrator.rtol", "2"),
    ] {
        let line = stderr
            .lines()
            .find(|l| l.contains(&format!("`{field}`")))
            .unwrap_or_else(|| panic!("{field} not reported: {stderr}"));
        assert!(line.contains(value), "{line}");
    }
}

#[test]
fn run_writes_to_out_by_default_and_is_quiet_when_not_a_terminal() {
    let dir = out_dir("default-out");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join(fixture("good_pendulum_rk4.toml"));
    let out = Command::new(env!("CARGO_BIN_EXE_pegdyn"))
        .args(["run", scene.to_str().unwrap()])
        .current_dir(&dir)
        .output()
        .expect("the pegdyn binary runs");
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "no progress line on a pipe: {:?}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(dir.join("out/good_pendulum_rk4.csv").is_file());
    assert!(dir.join("out/good_pendulum_rk4.svg").is_file());
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(pegdyn(&[]).status.code(), Some(2));
    assert_eq!(pegdyn(&["check"]).status.code(), Some(2));
    assert_eq!(pegdyn(&["frobnicate"]).status.code(), Some(2));
    assert_eq!(pegdyn(&["--help"]).status.code(), Some(0));
}

#[test]
fn missing_file_is_an_error_naming_the_path() {
    let out = pegdyn(&["check", "tests/fixtures/does_not_exist.toml"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr.contains("does_not_exist.toml"), "{stderr}");
}

/// A CSV file as its header and numeric rows.
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).expect("CSV written");
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("header")
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse().expect("numeric CSV field"))
                .collect()
        })
        .collect();
    (header, rows)
}

/// The value printed for metric `name` in the run summary.
fn metric(stdout: &str, name: &str) -> f64 {
    let line = stdout
        .lines()
        .find(|l| l.trim_start().starts_with(name))
        .unwrap_or_else(|| panic!("no `{name}` in {stdout}"));
    let value = line.split('=').nth(1).expect("name = value");
    value
        .split_whitespace()
        .next()
        .expect("value")
        .parse()
        .expect("number")
}

/// Runs a pendulum scene and checks its outputs against the physics: the
/// initial angle, the amplitude bound from energy conservation, a small
/// energy error, and the measured period against the exact AGM period.
fn run_pendulum(scene: &str, test: &str, theta0_deg: f64, t_end: f64, dt: f64) {
    let dir = out_dir(test);
    let out = pegdyn(&["run", scene, "--out", dir.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("reached t_end"), "{stdout}");

    let stem = Path::new(scene).file_stem().unwrap().to_str().unwrap();
    let (header, rows) = read_csv(&dir.join(format!("{stem}.csv")));
    assert_eq!(
        header,
        [
            "t_s",
            "theta_rad",
            "omega_rad_s",
            "energy_J",
            "energy_error"
        ]
    );
    assert_eq!(rows.len(), (t_end / dt).round() as usize + 1);
    assert_eq!(rows[0][0], 0.0);
    assert_eq!(rows.last().unwrap()[0], t_end);
    let theta0 = theta0_deg.to_radians();
    assert_eq!(rows[0][1], theta0);
    for r in &rows {
        assert!(
            r[1].abs() <= theta0 + 1e-8,
            "amplitude exceeded at t = {}: {}",
            r[0],
            r[1]
        );
        assert!(r[4].abs() < 1e-8, "energy error {} at t = {}", r[4], r[0]);
    }
    // The amplitude is reached again: the pendulum swings, not creeps.
    assert!(rows.iter().any(|r| r[1] < -0.99 * theta0));
    assert!(metric(&stdout, "max |E - E0|") < 1e-8);
    assert!(metric(&stdout, "period relative error") < 1e-8, "{stdout}");

    let svg = std::fs::read_to_string(dir.join(format!("{stem}.svg"))).expect("SVG written");
    assert!(
        svg.starts_with("<svg") && svg.contains("Energy error"),
        "not an SVG plot"
    );
}

#[test]
fn run_pendulum_dopri5_conserves_energy_and_period() {
    run_pendulum("scenes/pendulum.toml", "pendulum", 60.0, 10.0, 0.01);
}

#[test]
fn run_pendulum_rk4_conserves_energy_and_period() {
    run_pendulum(&fixture("good_pendulum_rk4.toml"), "rk4", 90.0, 3.0, 0.1);
}

#[test]
fn run_pendulum_rosenbrock_conserves_energy_and_period() {
    run_pendulum(
        &fixture("good_pendulum_rosenbrock.toml"),
        "rosenbrock",
        45.0,
        5.0,
        0.05,
    );
}

#[test]
fn run_double_pendulum_conserves_energy() {
    let dir = out_dir("double");
    let scene = fixture("good_double_pendulum.toml");
    let out = pegdyn(&["run", &scene, "--out", dir.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (header, rows) = read_csv(&dir.join("good_double_pendulum.csv"));
    assert_eq!(header.len(), 7);
    assert_eq!(header[1], "theta1_rad");
    assert_eq!(rows.len(), 151);
    assert_eq!(
        (rows[0][1], rows[0][2], rows[0][4]),
        (90f64.to_radians(), 45f64.to_radians(), 1.0)
    );
    let e0 = rows[0][5];
    for r in &rows {
        assert!(
            (r[5] - e0).abs() < 1e-6 * e0.abs().max(1.0),
            "energy {} vs {e0} at t = {}",
            r[5],
            r[0]
        );
    }
    // It moves: the upper rod swings through the vertical.
    assert!(rows.iter().any(|r| r[1] < 0.0));
    assert!(metric(&stdout, "max |E - E0|") < 1e-7);
    assert!(dir.join("good_double_pendulum.svg").exists());
}

#[test]
fn unplanned_stop_writes_outputs_and_exits_1() {
    let dir = out_dir("budget");
    let scene = fixture("step_budget_too_small.toml");
    let out = pegdyn(&["run", &scene, "--out", dir.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stdout}{stderr}");
    assert!(
        stderr.contains("step budget of 20 steps exhausted"),
        "{stderr}"
    );
    // What was computed before the stop is still written.
    let (_, rows) = read_csv(&dir.join("step_budget_too_small.csv"));
    assert!(!rows.is_empty() && rows.last().unwrap()[0] < 5.0);
}

#[test]
fn codegen_prints_source_and_report() {
    let out = pegdyn(&["codegen"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0));
    assert!(stdout.contains("@generated") && stdout.contains("pub mod pendulum"));
    assert!(stdout.contains("add/sub"));
    let report = pegdyn(&["codegen", "--report-only"]);
    let report = String::from_utf8_lossy(&report.stdout);
    assert!(
        report.contains("add/sub") && !report.contains("pub mod"),
        "{report}"
    );
}

#[test]
fn closed_stdout_is_not_a_panic() {
    // `pegdyn codegen | head -1`: the reader goes away after the first line.
    // The generated source is larger than a pipe buffer, so writes fail.
    let mut child = Command::new(env!("CARGO_BIN_EXE_pegdyn"))
        .arg("codegen")
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the pegdyn binary runs");
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("pegdyn exits");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(out.status.code(), Some(0));
}
