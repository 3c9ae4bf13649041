//! Work is bounded before it is built: a scene's work is estimated from its
//! tables (grid points from the lengths of their lists, runs, samples) and
//! refused by `pegdyn check` with the limit named before anything is
//! constructed; with the limits raised past what the machine holds, a run
//! ends with a typed error naming the limit, never with the abort of a
//! failed allocation. Each case runs under an address-space cap (`ulimit
//! -v`), so that building the work first would abort the process instead
//! of passing slowly.

use crate::common::scene_text::shipped;
use std::path::{Path, PathBuf};

use crate::common::cli::{fresh_dir, pegdyn_capped};

/// 2 GiB of address space: far more than any of these checks needs, far
/// less than the grids they refuse.
const CAP_KIB: u64 = 2 * 1024 * 1024;

/// `[a, b, ...]` with `n` distinct values from `start` in steps of `step`.
fn list(n: usize, start: f64, step: f64) -> String {
    let items: Vec<String> = (0..n)
        .map(|k| format!("{:e}", start + k as f64 * step))
        .collect();
    format!("[{}]", items.join(", "))
}

/// The shipped scene `name` with each line starting with a key of
/// `replace` set to its value.
fn with_lines(name: &str, replace: &[(&str, String)]) -> String {
    let mut found = vec![false; replace.len()];
    let text: Vec<String> = shipped(name)
        .lines()
        .map(|l| {
            for (i, (key, value)) in replace.iter().enumerate() {
                if l.starts_with(&format!("{key} =")) {
                    found[i] = true;
                    return format!("{key} = {value}");
                }
            }
            l.to_owned()
        })
        .collect();
    assert!(found.iter().all(|f| *f), "{name}: {replace:?}");
    text.join("\n") + "\n"
}

/// The hostile scenes: `(file name, text, limit key that bounds them)`,
/// each about 10^9 grid points or runs.
fn huge() -> Vec<(&'static str, String, &'static str)> {
    let axis = || list(178, 1e-5, 1e-6); // 178^4 ≈ 1.0e9 points
    let big = || list(31_623, 0.0, 1e-6); // 31 623^2 ≈ 1.0e9 points
    vec![
        (
            "rotation",
            with_lines(
                "rotation_assist",
                &[
                    ("lateral_errors", axis()),
                    ("angular_errors_deg", list(178, 0.1, 0.001)),
                    ("precession_rates", axis()),
                    ("spin_rates", axis()),
                ],
            ),
            "max_runs",
        ),
        (
            "design",
            with_lines(
                "design_margins",
                &[
                    ("centre_lateral_errors", big()),
                    ("angular_errors_deg", list(31_623, -1.0, 5e-5)),
                ],
            ),
            "max_runs",
        ),
        (
            "fig9",
            with_lines("fig9", &[("count", "1_000_000_000".into())]),
            "max_grid_points",
        ),
        (
            "jamming",
            with_lines("jamming", &[("n", "31_623".into())]),
            "max_runs",
        ),
    ]
}

fn write(dir: &Path, file: &str, text: &str) -> PathBuf {
    let p = dir.join(format!("{file}.toml"));
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn grids_of_a_billion_points_are_refused_by_check_before_they_are_built() {
    let d = fresh_dir("bounded", "refused");
    for (file, text, limit) in huge() {
        let path = write(&d, file, &text);
        let out = pegdyn_capped(CAP_KIB, &["check", path.to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{file}: {stderr}");
        assert!(
            stderr.contains(limit),
            "{file}: {limit} not named: {stderr}"
        );
        assert!(stderr.contains("e9"), "{file}: the estimate: {stderr}");
        assert!(!stderr.contains("memory allocation"), "{file}: {stderr}");
    }
}

#[test]
fn limits_raised_past_the_machine_give_a_typed_error_not_an_abort() {
    let d = fresh_dir("bounded", "raised");
    let raised = [
        "--limit",
        "runs=1e12",
        "--limit",
        "grid_points=1e12",
        "--limit",
        "samples=1e13",
        "--limit",
        "memory_mb=1e12",
        "--limit",
        "steps=1e9",
    ];
    let mut cases = huge();
    // `sweep.n` stays in its range (at most 1e4): 1e8 runs, whose points
    // (two per run, reserved up front) still pass the memory cap.
    for case in cases.iter_mut().filter(|c| c.0 == "jamming") {
        case.1 = with_lines("jamming", &[("n", "10_000".into())]);
    }
    // A stored time series of 10^10 samples (the rigid peg's forward run).
    cases.push((
        "samples",
        with_lines("align_forward", &[("output_interval", "1e-9".into())]),
        "max_output_samples",
    ));
    // A streamed one: only its output times are reserved.
    cases.push((
        "streamed",
        with_lines("pendulum", &[("output_interval", "1e-9".into())]),
        "max_output_samples",
    ));
    for (file, text, limit) in cases {
        let path = write(&d, file, &text);
        let out_dir = d.join(format!("out-{file}"));
        let mut args = vec![
            "run",
            path.to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
            "-q",
        ];
        args.extend(raised);
        let out = pegdyn_capped(CAP_KIB, &args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{file}: {stderr}");
        assert!(
            stderr.contains("cannot reserve memory") && stderr.contains(limit),
            "{file}: {stderr}"
        );
        assert!(!stderr.contains("memory allocation"), "{file}: {stderr}");
    }
}
