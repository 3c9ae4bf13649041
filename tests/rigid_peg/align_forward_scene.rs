//! Scene `align_forward` (rigid three-point peg, forward dynamics): the shipped scene runs
//! to a contact event and writes the documented CSV columns with finite
//! values; bad scenes are refused by the CLI naming the field.

use std::path::{Path, PathBuf};

use crate::common::cli as cli_common;
use cli_common::{fresh_dir, pegdyn};

fn dir(test: &str) -> PathBuf {
    fresh_dir("align-forward", test)
}

const SCENE: &str = "scenes/align_forward.toml";

#[test]
fn shipped_scene_writes_the_documented_columns_and_reports_the_event() {
    let out = dir("run");
    let o = pegdyn(&["run", SCENE, "--out", out.to_str().unwrap(), "-q"]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{stdout}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // The event: which, when, where.
    assert!(
        stdout.contains("lift-off of K") && stdout.contains("gamma = "),
        "{stdout}"
    );
    let csv = std::fs::read_to_string(out.join("align_forward.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "t,gamma,psi,gammadot,psidot,N_K,N_B1,N_B2"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() > 10);
    for r in &rows {
        assert_eq!(r.len(), 8);
        assert!(r.iter().all(|v| v.is_finite()), "{r:?}");
    }
    // Time increases; the last row is the lift-off of K: N_K ≈ 0, B's push.
    assert!(rows.windows(2).all(|w| w[1][0] > w[0][0]));
    let last = rows.last().unwrap();
    assert!(
        last[5].abs() < 1e-6 && last[6] > 0.0 && last[7] > 0.0,
        "{last:?}"
    );
    assert!(out.join("align_forward.svg").exists());
}

/// (replacement in the shipped scene, field that must be named)
const BAD: &[(&str, &str, &str)] = &[
    (
        "peg_diameter = 0.04995",
        "peg_diameter = 0.05",
        "peg.peg_diameter",
    ),
    ("\ngamma = 0.3 ", "\ngamma = 0.04 ", "initial.gamma"),
    ("mass = 1.0", "mass = -1.0", "peg.mass"),
    ("psidot = 10.0", "psidot = nan", "initial.psidot"),
    ("m_gamma = -0.15", "m_gamma = inf", "loads.m_gamma"),
    ("v_stop = 1e-6", "v_stop = 0.0", "friction.v_stop"),
];

#[test]
fn bad_scenes_are_refused_naming_the_field() {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(SCENE)).unwrap();
    let d = dir("bad");
    for (k, &(from, to, field)) in BAD.iter().enumerate() {
        assert!(text.contains(from), "{from}");
        let path = d.join(format!("bad{k}.toml"));
        std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
        let out = d.join("o");
        let runs: [Vec<&str>; 2] = [
            vec!["check", path.to_str().unwrap()],
            vec![
                "run",
                path.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
            ],
        ];
        for args in runs {
            let o = pegdyn(&args);
            let stderr = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(1), "{field}: {stderr}");
            assert!(
                stderr.contains(&format!("`{field}`")),
                "{field} not named: {stderr}"
            );
            assert!(!stderr.contains("panicked"), "{stderr}");
        }
    }
}

#[test]
fn check_accepts_the_shipped_scene() {
    let o = pegdyn(&["check", SCENE]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(String::from_utf8_lossy(&o.stdout).contains("OK (align_forward)"));
}
