//! The classes of hostile-but-valid scenes, end to end through the
//! `pegdyn` binary: each is refused by `check` with the field and its own
//! value, or runs and leaves complete, honest outputs.

use std::path::{Path, PathBuf};

use crate::common::cli as cli_common;
use cli_common::{fresh_dir, pegdyn};

fn dir(test: &str) -> PathBuf {
    fresh_dir("hostile", test)
}

/// The shipped scene `name` with `from` replaced by `to` (must occur).
fn variant(name: &str, from: &str, to: &str) -> String {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.toml")),
    )
    .unwrap();
    assert!(text.contains(from), "{name} has no {from:?}");
    text.replacen(from, to, 1)
}

/// `pegdyn check` on `text` fails naming every `(field, value)`.
fn refused(test: &str, text: &str, expect: &[&str]) {
    let d = dir(test);
    let path = d.join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let out = pegdyn(&["check", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    for e in expect {
        assert!(stderr.contains(e), "missing {e:?} in:\n{stderr}");
    }
}

#[test]
fn hangs_and_aborts_are_refused_by_check() {
    // Degenerate fillet: used to hang the elliptic-integral iteration.
    refused(
        "fillet",
        &variant(
            "insert_compliant",
            "peg_fillet = 0.0002",
            "peg_fillet = 1e-200",
        ),
        &["insert_compliant.peg_fillet` = 1e-200", "Hertz"],
    );
    // Output times: 1e9 s at the shipped interval, and an interval of 1e-300 s.
    refused(
        "t_end",
        &variant("pendulum", "t_end = 10.0", "t_end = 1e9"),
        &[
            "integrator.output_interval",
            "1.000e11 output samples",
            "max_memory_mb",
        ],
    );
    refused(
        "interval",
        &variant(
            "pendulum",
            "output_interval = 0.01",
            "output_interval = 1e-300",
        ),
        &[
            "integrator.output_interval` = 1e-300",
            "1.000e301",
            "[limits] max_output_samples",
        ],
    );
    // Grids: fig9 count of i64::MAX, a jamming sweep of 1000 x 1000 runs.
    refused(
        "count",
        &variant("fig9", "count = 400", "count = 9223372036854775807"),
        &["gamma.count", "9.223372036854776e18", "max_grid_points"],
    );
    refused(
        "sweep",
        &variant("jamming", "n = 13", "n = 1000"),
        &["sweep.n` = 1000.0", "1.000e6", "max_runs"],
    );
}

#[test]
fn limits_table_raises_a_limit() {
    let text = variant("fig9", "count = 400", "count = 2000000")
        + "\n[limits]\nmax_grid_points = 5_000_000\n";
    let d = dir("limits");
    let path = d.join("scene.toml");
    std::fs::write(&path, &text).unwrap();
    let out = pegdyn(&["check", path.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bad = text.replace("max_grid_points = 5_000_000", "max_grid_pts = 5");
    refused("limits_typo", &bad, &["limits.max_grid_pts"]);
}

#[test]
fn long_runs_stream_every_sample_and_plot_a_decimated_copy() {
    // 200 001 samples: every one in the CSV, in order and finite; the plot
    // keeps about 4000 (the SVG stays small).
    let text = variant("pendulum", "t_end = 10.0", "t_end = 2000.0");
    let d = dir("stream");
    let path = d.join("long.toml");
    std::fs::write(&path, &text).unwrap();
    let out_dir = d.join("out");
    let out = pegdyn(&[
        "run",
        "-q",
        path.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let csv = std::fs::read_to_string(out_dir.join("long.csv")).unwrap();
    let times: Vec<f64> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(times.len(), 200_001);
    assert!(times.windows(2).all(|w| w[1] > w[0]));
    assert_eq!((times[0], times[times.len() - 1]), (0.0, 2000.0));
    assert!(
        csv.lines().skip(1).all(|l| l
            .split(',')
            .all(|c| c.parse::<f64>().is_ok_and(f64::is_finite))),
        "a cell is not a finite number"
    );
    let svg = std::fs::metadata(out_dir.join("long.svg")).unwrap().len();
    assert!(
        svg < 400_000,
        "svg of {svg} bytes: the plot was not decimated"
    );
    let manifest = std::fs::read_to_string(out_dir.join("long.run.toml")).unwrap();
    assert!(manifest.contains("status = \"ok\""), "{manifest}");
}

#[test]
fn limit_flag_raises_a_limit() {
    // 2e6 grid points: refused by default, accepted with --limit, for
    // check and run alike; a bad flag is a usage error (exit 2).
    let text = variant("fig9", "count = 400", "count = 2000000");
    let d = dir("limit_flag");
    let path = d.join("scene.toml");
    std::fs::write(&path, &text).unwrap();
    let p = path.to_str().unwrap();
    let out = pegdyn(&["check", p]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("--limit max_grid_points=..."), "{stderr}");
    for flag in ["max_grid_points=5e6", "grid_points=5_000_000"] {
        let out = pegdyn(&["check", "--limit", flag, p]);
        assert!(
            out.status.success(),
            "{flag}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    // The flag replaces the scene's own [limits] value, also downwards.
    let out = pegdyn(&[
        "check",
        "--limit",
        "max_grid_points=500",
        "scenes/fig9.toml",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("gamma.count") && stderr.contains("5e2"),
        "{stderr}"
    );
    // Run with a lowered sample limit is refused before any output.
    let out = pegdyn(&[
        "run",
        "--limit",
        "samples=10",
        "--out",
        d.join("out").to_str().unwrap(),
        "scenes/pendulum.toml",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("max_output_samples"), "{stderr}");
    assert!(!d.join("out").join("pendulum.csv").exists());
    for bad in ["max_grid_pts=5", "max_grid_points=0", "max_grid_points"] {
        let out = pegdyn(&["check", "--limit", bad, p]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{bad}: {stderr}");
        assert!(stderr.contains(bad), "{stderr}");
    }
}

#[test]
fn wrong_physics_is_refused_with_the_scene_value() {
    refused(
        "depth",
        &variant(
            "insert_compliant",
            "target_depth = 0.03",
            "target_depth = 0.5",
        ),
        &["insert_compliant.target_depth` = 0.5", "peg_length"],
    );
    refused(
        "clearance",
        &variant(
            "insert_compliant",
            "clearance_ratio = 0.002",
            "clearance_ratio = 1e-15",
        ),
        &["insert_compliant.clearance_ratio` = 1e-15", "1e-9"],
    );
    refused(
        "clearance0",
        &variant(
            "insert_compliant",
            "clearance_ratio = 0.002",
            "clearance_ratio = 0.0",
        ),
        &["insert_compliant.clearance_ratio` = 0.0"],
    );
    refused(
        "modulus",
        &variant(
            "insert_compliant",
            "youngs_modulus = 210e9",
            "youngs_modulus = 1e-30",
        ),
        &["peg_material.youngs_modulus` = 1e-30"],
    );
    refused(
        "gravity",
        &variant("fig9", "gravity = 9.81", "gravity = 0.0"),
        &["peg.gravity` = 0.0", "m g"],
    );
}

#[test]
fn non_finite_results_are_refused_before_they_run() {
    // Precession of 1e200 1/s overflowed the reactions; it is now outside
    // the rigid model's range (rim speed), refused by run before any file.
    let d = dir("psidot");
    let path = d.join("fast.toml");
    std::fs::write(
        &path,
        variant("fig9", "psidot = [0.0, 10.0]", "psidot = [0.0, 1e200]"),
    )
    .unwrap();
    let out_dir = d.join("out");
    let out = pegdyn(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("motion.psidot[1]` = 1e200") && stderr.contains("rim speed"),
        "{stderr}"
    );
    assert!(!out_dir.join("fast.csv").exists() && !out_dir.join("fast.svg").exists());
}

#[test]
fn physics_ranges_of_rigid_pendulum_and_jamming_kinds_are_refused() {
    // The fuzzed align_forward scene whose reactions reached 1e308 N and
    // whose plot then hung: every offending field is named with its limit.
    let af = variant("align_forward", "height = 0.070", "height = 7.7e-154")
        .replacen("mass = 1.0", "mass = 1.4e157", 1)
        .replacen("psidot = 10.0", "psidot = 6.3e76", 1);
    refused(
        "rigid_repro",
        &af,
        &[
            "peg.height` = 7.7e-154: must lie in [1e-6, 1e3] m",
            "peg.mass` = 1.4e157: must lie in [1e-9, 1e6] kg",
            "initial.psidot` = 6.3e76",
            "exceeds 1e3 m/s",
        ],
    );
    refused(
        "rigid_load",
        &variant(
            "align_forward",
            "force = [0.0, 0.0, 0.0]",
            "force = [1e9, 0.0, 0.0]",
        ),
        &[
            "loads.force[0]` = 1000000000.0",
            "above 1e5 m/s^2",
            "limit 1.000e5 N",
        ],
    );
    refused(
        "rigid_clearance",
        &variant(
            "fig9",
            "peg_diameter = 0.04995",
            "peg_diameter = 0.04999999999999",
        ),
        &["peg.peg_diameter", "clearance ratio", "1e-9"],
    );
    refused(
        "pendulum_spin",
        &variant("pendulum", "omega0 = 0.0", "omega0 = 1e160"),
        &["pendulum.omega0` = 1e160", "sqrt(2e12 g/L) = 4.429e6 rad/s"],
    );
    refused(
        "pendulum_length",
        &variant("pendulum", "length = 1.0", "length = 1e-30"),
        &["pendulum.length` = 1e-30: must lie in [1e-6, 1e6] m"],
    );
    refused(
        "double_mass",
        &variant("double_pendulum", "mass2 = 1.0", "mass2 = 1e300"),
        &["double_pendulum.mass2` = 1e300: must lie in [1e-9, 1e9] kg"],
    );
    refused(
        "jamming_c",
        &variant("jamming", "c = [0.002, 0.01]", "c = [1e-15, 0.01]"),
        &["jamming.c[0]` = 1e-15: must lie in [1e-9,"],
    );
    refused(
        "sweep_mu",
        &variant("jamming", "mu = 0.3", "mu = 100.0"),
        &["sweep.mu` = 100.0: must lie in [1e-6, 1e1]"],
    );
    refused(
        "sweep_damping",
        &variant("jamming", "contact_damping = 1.5", "contact_damping = -1.5"),
        &["sweep.contact_damping` = -1.5: must lie in [0, 1e3] s/m"],
    );
}

#[test]
fn a_non_finite_value_leaves_no_file_and_names_its_column() {
    use pegdyn::error::OutputError;
    use pegdyn::output::csv::CsvWriter;
    let d = dir("csv_nan");
    let path = d.join("x.csv");
    let mut w = CsvWriter::create(&path, &["t_s", "force_n"]).unwrap();
    w.row(&[0.0, 1.0]).unwrap();
    let e = w.row(&[0.5, f64::NAN]).unwrap_err();
    drop(w);
    match &e {
        OutputError::NonFinite {
            column, row, first, ..
        } => {
            assert_eq!(
                (column.as_str(), *row, first.as_str()),
                ("force_n", 1, "0.5")
            );
        }
        other => panic!("{other}"),
    }
    assert!(e.to_string().contains("nothing was written"), "{e}");
    let left: Vec<_> = std::fs::read_dir(&d).unwrap().collect();
    assert!(left.is_empty(), "{left:?}");
}

#[test]
fn outputs_are_recorded_and_never_replace_the_scene() {
    let d = dir("outputs");
    // A scene saved under an output's name in the output directory.
    let scene = d.join("p.svg");
    let text = variant("pendulum", "t_end = 10.0", "t_end = 0.5");
    std::fs::write(&scene, &text).unwrap();
    let out = pegdyn(&["run", scene.to_str().unwrap(), "--out", d.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(std::fs::read_to_string(&scene).unwrap(), text);
    // A normal run: manifest with the files; an earlier run's file is stale.
    let scene = d.join("p.toml");
    std::fs::write(&scene, &text).unwrap();
    let out_dir = d.join("out");
    std::fs::create_dir_all(&out_dir).unwrap();
    std::fs::write(out_dir.join("p.old.csv"), "t\n").unwrap();
    let out = pegdyn(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("p.old.csv"), "{stderr}");
    let m: toml::Table = std::fs::read_to_string(out_dir.join("p.run.toml"))
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(m["status"].as_str(), Some("ok"));
    let files: Vec<&str> = m["files"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|v| v.as_str())
        .collect();
    assert_eq!(files, ["p.csv", "p.svg"]);
    assert_eq!(m["stale"][0].as_str(), Some("p.old.csv"));
    assert!(m["scene_hash"].as_str().unwrap().starts_with("fnv1a64:"));
    // No temporary file is left.
    let names: Vec<String> = std::fs::read_dir(&out_dir)
        .unwrap()
        .filter_map(Result::ok)
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    assert!(names.iter().all(|n| !n.starts_with('.')), "{names:?}");
}

#[test]
fn accuracy_with_a_filter_matching_nothing_is_an_error() {
    let out = pegdyn(&["accuracy", "--only", "NO-SUCH-LABEL-ANYWHERE"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    if cfg!(feature = "accuracy") {
        assert!(stderr.contains("matches no grid point"), "{stderr}");
    } else {
        assert!(stderr.contains("--features accuracy"), "{stderr}");
    }
}
