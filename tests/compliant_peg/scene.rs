//! The `insert_compliant` scene: the shipped scene inserts the peg from its
//! tilted two-point start, writes the CSV/SVG with the documented columns and
//! keeps the energy balance; bad values are refused naming the TOML field.

use crate::common::cli;

use pegdyn::scene;
use std::path::Path;

const SCENE: &str = include_str!("../../scenes/insert_compliant.toml");

fn refused_field(from: &str, to: &str) -> String {
    assert!(SCENE.contains(from), "{from}");
    let err = scene::parse(&SCENE.replacen(from, to, 1)).unwrap_err();
    err.errors
        .first()
        .and_then(|e| e.error.field())
        .unwrap_or_default()
        .to_owned()
}

#[test]
fn bad_values_are_refused_naming_the_field() {
    assert_eq!(
        refused_field("friction = 0.1 ", "friction = -0.1 "),
        "insert_compliant.friction"
    );
    assert_eq!(
        refused_field("clearance_ratio = 0.002", "clearance_ratio = 0.0"),
        "insert_compliant.clearance_ratio"
    );
    assert_eq!(
        refused_field("youngs_modulus = 210e9    # Pa", "youngs_modulus = 0.0"),
        "insert_compliant.peg_material.youngs_modulus"
    );
    assert_eq!(
        refused_field(
            "poisson_ratio = 0.3\n\n[insert_compliant.hole",
            "poisson_ratio = 0.7\n\n[insert_compliant.hole"
        ),
        "insert_compliant.peg_material.poisson_ratio"
    );
    assert_eq!(
        refused_field("initial_tilt = 0.01", "initial_tilt = 0.2"),
        "insert_compliant.initial_tilt"
    );
}

#[test]
fn shipped_scene_inserts_the_peg_and_keeps_the_energy_balance() {
    let dir = cli::fresh_dir("compliant_scene", "shipped");
    let summary = cli::run_scene(SCENE, "insert_compliant", &dir);
    let integ = summary.integration.as_ref().unwrap();
    assert!(
        integ.success && integ.stop.contains("inserted"),
        "{}",
        integ.stop
    );
    let metric = |name: &str| cli::metric(&summary, name);
    assert!(metric("max |T + P - W + S") < 1e-6);
    assert!(metric("peak contact force") > 0.0);
    let csv = std::fs::read_to_string(dir.join("insert_compliant.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    for col in [
        "t_s",
        "depth_m",
        "f_A_N",
        "f_B_N",
        "p0_A_Pa",
        "p0_B_Pa",
        "delta_A_m",
        "delta_B_m",
        "balance_J",
    ] {
        assert!(
            header.split(',').any(|c| c == col),
            "missing column {col}: {header}"
        );
    }
    assert!(Path::new(&dir.join("insert_compliant.svg")).exists());
    std::fs::remove_dir_all(&dir).ok();
}
