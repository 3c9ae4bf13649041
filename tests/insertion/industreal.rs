//! The IndustReal kit's round pegs (4, 8, 12 and 16 mm at their true
//! clearances), shipped as `scenes/industreal_round_*mm.toml`: each scene
//! is valid and names the peg it says; the 16 mm peg seats when the robot
//! has carried it to the seat depth.

use crate::common::rcc;
use pegdyn::compliant_peg_3d::insertion::{depth_tilt, peg_state};
use pegdyn::compliant_peg_3d::outcome::Outcome;
use pegdyn::scene::document::Document;
use pegdyn::scene::shared::compliant_peg_3d::insertion::RccScene;

/// `(peg diameter, hole diameter, scene text)`, m.
const SCENES: [(f64, f64, &str); 4] = [
    (
        0.003988,
        0.004100,
        include_str!("../../scenes/industreal_round_4mm.toml"),
    ),
    (
        0.007986,
        0.008100,
        include_str!("../../scenes/industreal_round_8mm.toml"),
    ),
    (
        0.011983,
        0.012200,
        include_str!("../../scenes/industreal_round_12mm.toml"),
    ),
    (
        0.015983,
        0.016500,
        include_str!("../../scenes/industreal_round_16mm.toml"),
    ),
];

#[test]
fn the_industreal_scenes_build_the_kit_s_pegs() {
    for (d, big_d, text) in SCENES {
        let scene: RccScene = Document::parse(text)
            .and_then(|doc| doc.body())
            .expect("the scene parses");
        let built = scene.build().expect("the scene is valid");
        let p = &built.params;
        // d = D (1 − c): the peg's diameter from the hole's and the ratio.
        assert!((p.hole_diameter - big_d).abs() < 1e-15, "{big_d}");
        assert!(
            (p.peg_diameter - d).abs() < 1e-15,
            "{d}: {}",
            p.peg_diameter
        );
        // Steel, 50 mm long: m = ρ π r² L.
        let mass = 8000.0 * std::f64::consts::PI * (0.5 * p.peg_diameter).powi(2) * 0.05;
        assert!((p.mass - mass).abs() < 1e-12 * mass, "{} {mass}", p.mass);
        assert_eq!(built.criteria.seat_depth, 0.02);
    }
}

#[test]
fn the_16_mm_peg_seats_when_the_robot_has_carried_it_to_the_seat_depth() {
    let (scene, built, run) = rcc::run(SCENES[3].2);
    assert_eq!(run.outcome, Outcome::Seated);
    let (depth, ..) = depth_tilt(&built.params, &peg_state(&run.solution.x_final));
    assert!((depth - 0.02).abs() < 1e-9, "{depth}");
    // The robot travels start height + seat depth at its speed; the wrist
    // lags by its axial deflection, below the force limit over the axial
    // stiffness (the run would have stopped at the limit).
    let travel = (scene.robot.start_height + 0.02) / scene.robot.speed;
    let lag = scene.criteria.wrist_force_limit / scene.wrist.axial_stiffness / scene.robot.speed;
    let t = run.solution.t_final;
    assert!(
        (t - travel).abs() <= lag,
        "t = {t}, travel {travel}, lag {lag}"
    );
}
