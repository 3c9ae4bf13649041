//! End-to-end tests of the `pegdyn` binary: `check` and `run` on good and
//! bad scene files. Bad scenes must fail with exit code 1 and an error on
//! stderr that names the offending field and value.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn pegdyn(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pegdyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the pegdyn binary runs")
}

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
