//! The jamming diagram checked with dynamics (compliant Hertz contacts,
//! `compliant_peg::simulate_insertion`): a load far outside the parallelogram
//! jams and one well inside inserts, and on a coarse grid the simulated
//! class boundary matches the exact parallelogram within the grid spacing.
//! The scene's `[sweep]` writes its CSV and SVG.

use crate::common::cli;

use std::path::PathBuf;

use pegdyn::jamming::dynamic::{SweepSetup, SweepSpec};
use pegdyn::jamming::sweep::RunClass;

fn setup() -> SweepSetup {
    SweepSetup::new(SweepSpec {
        t_max: 0.2,
        early_stop: true,
        ..SweepSpec::reference()
    })
    .unwrap()
}

#[test]
fn far_outside_jams_well_inside_inserts() {
    let s = setup();
    let corner = s.diagram.corners[2]; // P₁, top right
    // well inside: pure axial push
    assert!(s.diagram.margin([0.0, 0.0]) > 0.8);
    assert_eq!(s.run_one([0.0, 0.0]).unwrap(), RunClass::Inserted);
    // far outside: moment 1.5 × the corner's, past the two-point line
    let far = [0.0, 1.5 * corner[1]];
    assert!(s.diagram.margin(far) < -1.0);
    assert_eq!(s.run_one(far).unwrap(), RunClass::Jammed);
    // far outside sideways: force inside the edge friction cone
    let side = [1.6 * corner[0], 0.0];
    assert!(s.diagram.margin(side) < -1.0);
    assert_eq!(s.run_one(side).unwrap(), RunClass::Jammed);
}

#[test]
fn sweep_scene_boundary_matches_the_exact_diagram() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/jamming.toml");
    let text = std::fs::read_to_string(path).unwrap();
    // the scene's sweep on a coarser 9 × 9 grid
    let coarse = text.replace("n = 13 ", "n = 9 ");
    assert_ne!(coarse, text);
    let dir = cli::fresh_dir("jamming_dynamic", "sweep_scene");
    let summary = cli::run_scene(&coarse, "jamming", &dir);
    let metric = |name: &str| cli::metric(&summary, name);
    assert_eq!(metric("sweep runs"), 81.0);
    assert_eq!(metric("points contradicting the exact diagram"), 0.0);
    let judged = metric("grid points judged");
    assert!(judged >= 15.0, "{judged}");
    let csv = std::fs::read_to_string(dir.join("jamming.sweep.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "fx_over_fz,m_over_rfz,class,lean_plus,lean_minus,margin_exact,margin_whitney,\
         margin_exact_d_dr,margin_exact_d_dc,margin_exact_d_dmu,margin_exact_d_dl"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    // The margin's derivatives along r, c, μ and l: numbers at every grid
    // point but the centre, which the point-symmetric diagram's mirrored
    // edges hold at equal distances (no derivative there, an empty cell).
    for row in &rows {
        assert_eq!(row.len(), 11, "{row:?}");
        let centre = row[0].parse::<f64>().unwrap() == 0.0 && row[1].parse::<f64>().unwrap() == 0.0;
        for cell in &row[7..] {
            if centre {
                assert!(cell.is_empty(), "{row:?}");
            } else {
                assert!(cell.parse::<f64>().is_ok_and(f64::is_finite), "{row:?}");
            }
        }
    }
    let classes: Vec<&str> = rows.iter().map(|r| r[2]).collect();
    assert_eq!(classes.len(), 81);
    assert!(classes.contains(&"inserted") && classes.contains(&"jammed"));
    assert!(dir.join("jamming.sweep.svg").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
