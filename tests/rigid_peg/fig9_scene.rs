//! Scene `fig9` (rigid three-point peg): validation names the offending field; the run
//! writes the documented CSV columns with N_B1 = N_B2 at ψ̇ = 0.

use pegdyn::scene;

const GOOD: &str = r#"
kind = "fig9"
[peg]
hole_diameter = 0.050
peg_diameter = 0.04995
height = 0.070
mass = 1.0
gravity = 9.81
friction = 0.2
[motion]
gammadot = -2.0
psidot = [0.0, 10.0, -10.0]
[gamma]
values = [0.05, 0.1, 0.3]
"#;

fn error_of(text: &str) -> String {
    scene::parse(text).unwrap_err().to_string()
}

#[test]
fn start_at_or_below_gamma0_is_refused_naming_the_field() {
    let t = GOOD.replace("values = [0.05, 0.1, 0.3]", "values = [0.05, 0.0447]");
    let e = error_of(&t);
    assert!(e.contains("gamma.values[1]") && e.contains("gamma0"), "{e}");
    let t = GOOD.replace(
        "values = [0.05, 0.1, 0.3]",
        "start_over_gamma0 = 1.0\nend = 0.5\ncount = 10",
    );
    assert!(error_of(&t).contains("gamma.start_over_gamma0"));
    let t = GOOD.replace(
        "values = [0.05, 0.1, 0.3]",
        "start = 0.01\nend = 0.5\ncount = 10",
    );
    assert!(error_of(&t).contains("gamma.start"));
}

#[test]
fn peg_wider_than_hole_is_refused_naming_the_field() {
    let e = error_of(&GOOD.replace("peg_diameter = 0.04995", "peg_diameter = 0.050"));
    assert!(e.contains("peg.peg_diameter"), "{e}");
}

#[test]
fn run_writes_the_documented_columns() {
    let out = std::env::temp_dir().join(format!("pegdyn_fig9_{}", std::process::id()));
    std::fs::create_dir_all(&out).unwrap();
    let loaded = scene::parse_named(GOOD, "fig9").unwrap();
    let sink = pegdyn::output::sink::Sink::directory(&out, "fig9");
    let mut ctx = scene::RunContext::new(sink, scene::Progress::silent());
    loaded.run(&mut ctx).unwrap();
    let csv = std::fs::read_to_string(out.join("fig9.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "gamma,psidot,N_B1_over_mg,N_B2_over_mg,N_K_over_mg,M_gamma_over_mgD,M_psi_over_mgD,feasible"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 9);
    for r in rows.iter().filter(|r| r[1] == 0.0) {
        assert!((r[2] - r[3]).abs() < 1e-9 * r[2].abs());
    }
    // Mirror symmetry: ψ̇ → −ψ̇ swaps B1 and B2 and reverses M_ψ.
    for k in 0..3 {
        let (up, down) = (&rows[3 + k], &rows[6 + k]);
        assert!(
            (up[2] - down[3]).abs() < 1e-9 * up[2].abs(),
            "{up:?} vs {down:?}"
        );
        assert!((up[6] + down[6]).abs() < 1e-9 * up[6].abs());
    }
    assert!(out.join("fig9.svg").exists());
    std::fs::remove_dir_all(&out).ok();
}
