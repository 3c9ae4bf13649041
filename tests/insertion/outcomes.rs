//! Robot insertion with a compliant wrist: a small scene for each outcome
//! (seated, jammed, wedged, missed, force limit), recognized; and the
//! `drop_3d`, `insert_rcc` and `rotation_assist` scene kinds parsed,
//! refused on bad fields with the field named, and run end to end.

use crate::common::cli;

use crate::common::rcc;
use pegdyn::compliant_peg_3d::outcome::Outcome;
use pegdyn::scene::Progress;
use pegdyn::scene::shared::compliant_peg_3d::insertion::{RccScene, run_one};

/// The shipped `insert_rcc` scene's text with `(key, value)` lines
/// replaced (the key at the start of a line). The tip starts 2 mm in the
/// bore (`start_height = -2e-3`) unless `changes` says otherwise: the
/// cases below assume that start.
fn variant(changes: &[(&str, &str)]) -> String {
    variant_from(changes, &[("start_height", "-2e-3")])
}

/// The shipped `insert_rcc` scene's text with `changes`, then `defaults`
/// for the keys `changes` leaves alone, replaced.
fn variant_from(changes: &[(&str, &str)], defaults: &[(&str, &str)]) -> String {
    let base = include_str!("../../scenes/insert_rcc.toml");
    base.lines()
        .map(|l| {
            for (k, v) in changes.iter().chain(defaults) {
                if l.starts_with(&format!("{k} ")) || l.starts_with(&format!("{k}=")) {
                    return format!("{k} = {v}");
                }
            }
            l.to_string()
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn outcome(changes: &[(&str, &str)]) -> (Outcome, f64, f64) {
    let (_, built, run) = rcc::run(&variant(changes));
    let (depth, ..) = pegdyn::compliant_peg_3d::insertion::depth_tilt(
        &built.params,
        &pegdyn::compliant_peg_3d::insertion::peg_state(&run.solution.x_final),
    );
    (run.outcome, run.solution.t_final, depth)
}

#[test]
fn a_remote_centre_at_the_tip_seats_the_peg() {
    let (o, t, depth) = outcome(&[("seat_depth", "0.004")]);
    assert_eq!(o, Outcome::Seated, "t = {t}");
    assert!((depth - 0.004).abs() < 1e-9, "{depth}");
    // From 2 mm to 4 mm at 10 mm/s, behind the robot by the wrist's sag.
    assert!(t > 0.19 && t < 0.25, "{t}");
}

#[test]
fn a_stiff_tilted_wrist_with_low_friction_jams() {
    // μ = 0.15, the contacts far apart (l/d > μ: no wedge), the stiff
    // angular spring pushes the moment outside the no-jam region.
    let (o, t, _) = outcome(&[
        ("friction", "0.15"),
        ("clearance_ratio", "0.006"),
        ("angular_stiffness", "300.0"),
        ("angular_error_deg", "2.0"),
        ("lateral_error", "0.0"),
        ("start_height", "-5e-3"),
        ("seat_depth", "0.012"),
        ("wrist_force_limit", "60.0"),
    ]);
    match o {
        Outcome::Jammed { contacts, limit } => {
            assert!(
                contacts.contains("edge_side") && contacts.contains("rim_wall"),
                "{contacts}"
            );
            // The robot stopped at its wrist force limit; the summary says so.
            let l = limit.expect("stopped by a force limit");
            assert_eq!(l.which, "wrist");
            assert!((l.force / 60.0 - 1.0).abs() < 1e-3, "{}", l.force);
            let text = pegdyn::scene::shared::compliant_peg_3d::insertion::outcome_text(
                &Outcome::Jammed { contacts, limit },
            );
            assert!(
                text.ends_with("(the run stopped at the wrist force limit, 60 N)"),
                "{text}"
            );
        }
        other => panic!("{other:?} at {t}"),
    }
}

#[test]
fn high_friction_at_a_shallow_two_point_contact_wedges() {
    let (o, t, depth) = outcome(&[
        ("friction", "0.3"),
        ("clearance_ratio", "0.006"),
        ("angular_stiffness", "300.0"),
        ("angular_error_deg", "2.0"),
        ("lateral_error", "0.0"),
        ("start_height", "-5e-3"),
        ("seat_depth", "0.012"),
        ("wrist_force_limit", "60.0"),
    ]);
    assert!(matches!(o, Outcome::Wedged { .. }), "{o:?} at {t}");
    assert!(depth < 0.0055, "{depth}");
}

#[test]
fn a_lateral_error_beyond_the_mouth_misses() {
    let (o, t, _) = outcome(&[
        // The whole rim is over the top face: the tilted rim lands on it.
        ("lateral_error", "0.028"),
        ("start_height", "3e-4"),
    ]);
    assert_eq!(o, Outcome::Missed, "t = {t}");
    // The lowest rim point starts 0.3 mm − r sin 1° = 0.0825 mm above the
    // face, less the wrist's static sag m g / K_z = 9.4 µm: 7.3 ms at
    // 10 mm/s, plus the contact's approach.
    assert!(t > 0.0073 && t < 0.0085, "{t}");
}

#[test]
fn a_low_wrist_limit_stops_the_robot_on_one_contact() {
    // Held above the mouth the wrist starts with the peg's weight (1.9 N)
    // and the limit is reached on the chamfer.
    for limit in ["2.5", "3.0"] {
        let text = variant_from(&[("wrist_force_limit", limit)], &[]);
        let (_, _, run) = rcc::run(&text);
        match run.outcome {
            Outcome::ForceLimit { which, force } => {
                assert_eq!(which, "wrist");
                let limit: f64 = limit.parse().unwrap();
                assert!((force - limit).abs() < 1e-6, "{force}");
            }
            other => panic!("{other:?}"),
        }
    }
}

#[test]
fn a_wrist_limit_below_the_preload_of_a_start_in_the_bore_is_refused() {
    // Centred and upright 2 mm deep, the wrist is deflected by the robot's
    // 0.3 mm and 1 degree errors: 6.1 N before the run begins.
    for limit in ["4.0", "6.0"] {
        let text = variant(&[("wrist_force_limit", limit)]);
        let e = pegdyn::scene::parse_named(&format!("{text}\n"), "rcc")
            .expect_err("a limit below the start's force");
        let shown = e.to_string();
        assert_eq!(
            e.errors[0].error.field(),
            Some("criteria.wrist_force_limit"),
            "{shown}"
        );
        assert!(
            shown.contains("already carries 6.0") && shown.contains("centred and upright"),
            "{shown}"
        );
    }
    assert!(pegdyn::scene::parse_named(&variant(&[("wrist_force_limit", "6.5")]), "rcc").is_ok());
}

/// `text` run in-process as scene `name` into a fresh directory.
fn run_scene(text: &str, name: &str) -> pegdyn::scene::RunSummary {
    cli::run_scene(text, name, &cli::fresh_dir("insertion", name))
}

#[test]
fn each_scene_kind_is_refused_on_a_bad_field_naming_it() {
    for (text, key, bad, field) in [
        (
            include_str!("../../scenes/insert_rcc.toml"),
            "lateral_stiffness",
            "-1.0",
            "wrist.lateral_stiffness",
        ),
        (
            include_str!("../../scenes/insert_rcc.toml"),
            "seat_depth",
            "0.5",
            "criteria.seat_depth",
        ),
        (
            include_str!("../../scenes/drop_3d.toml"),
            "gamma",
            "0.01",
            "drop.gamma",
        ),
        (
            include_str!("../../scenes/drop_3d.toml"),
            "friction",
            "nan",
            "peg.friction",
        ),
        // A fuzzed case: a 1e193 m peg made the lean search bisect forever.
        (
            include_str!("../../scenes/drop_3d.toml"),
            "length",
            "3.6579432895081554e193",
            "peg.length",
        ),
        (
            include_str!("../../scenes/rotation_assist.toml"),
            "yield_pressure",
            "0.0",
            "grid.yield_pressure",
        ),
        (
            include_str!("../../scenes/rotation_assist.toml"),
            "spin_rates",
            "[]",
            "grid.spin_rates",
        ),
    ] {
        let t: String = text
            .lines()
            .map(|l| {
                if l.starts_with(&format!("{key} ")) {
                    format!("{key} = {bad}")
                } else {
                    l.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join("\n");
        let err = pegdyn::scene::parse(&t).unwrap_err().to_string();
        assert!(err.contains(field), "{field}: {err}");
    }
}

#[test]
fn insert_rcc_runs_end_to_end_and_writes_its_files() {
    let text = variant(&[("seat_depth", "0.003"), ("output_interval", "2e-3")]);
    let s = run_scene(&text, "rcc");
    assert!(s.success());
    // CSV, events, figure, views, and last the replay page.
    assert_eq!(s.outputs.len(), 5);
    let page = pegdyn::output::names::Part::Main.file_name("rcc", "html");
    assert!(s.outputs[4].ends_with(page), "{:?}", s.outputs);
    for p in &s.outputs {
        assert!(std::fs::metadata(p).unwrap().len() > 100, "{}", p.display());
    }
    let outcome = s
        .metrics
        .iter()
        .find(|m| m.name.starts_with("outcome"))
        .unwrap();
    assert_eq!(
        (
            outcome.name.as_str(),
            outcome.text.as_deref(),
            outcome.value
        ),
        ("outcome", Some("seated"), 0.0)
    );
    let csv = std::fs::read_to_string(&s.outputs[0]).unwrap();
    assert!(csv.lines().next().unwrap().contains("rim_wall_1_N_N"));
}

#[test]
fn drop_3d_runs_end_to_end_and_lists_transitions() {
    let text = include_str!("../../scenes/drop_3d.toml").replace("t_end = 0.05", "t_end = 0.01");
    let s = run_scene(&text, "drop");
    assert_eq!(s.outputs.len(), 5);
    let page = pegdyn::output::names::Part::Main.file_name("drop", "html");
    assert!(s.outputs[4].ends_with(page), "{:?}", s.outputs);
    let events = std::fs::read_to_string(&s.outputs[1]).unwrap();
    assert!(
        events.starts_with("t_s,transition,contact_state"),
        "{events}"
    );
    assert!(events.lines().count() >= 2, "{events}");
}

#[test]
fn rotation_assist_runs_a_tiny_grid() {
    let text = include_str!("../../scenes/rotation_assist.toml")
        .replace("lateral_errors = [1e-4, 3e-4]", "lateral_errors = [1e-4]")
        .replace(
            "angular_errors_deg = [0.5, 1.5]",
            "angular_errors_deg = [0.5]",
        )
        .replace("spin_rates = [0.0, 20.0]", "spin_rates = [0.0]")
        .replace("seat_depth = 0.006", "seat_depth = 0.003");
    let s = run_scene(&text, "sweep");
    let runs = s.metrics.iter().find(|m| m.name == "runs").unwrap();
    assert_eq!(runs.value, 2.0);
    let csv = std::fs::read_to_string(&s.outputs[0]).unwrap();
    assert_eq!(csv.lines().count(), 3, "{csv}");
    assert!(csv.lines().nth(1).unwrap().contains("seated"), "{csv}");
}

#[test]
fn a_force_controlled_descent_seats_the_peg() {
    // Constant 5 N down the robot's axis instead of the axial spring.
    let text = variant(&[("seat_depth", "0.004")])
        .replace("speed = 0.01 ", "axial_force = 5.0\nspeed = 0.01 ");
    let mut doc: toml::Table = toml::from_str(&text).unwrap();
    doc.remove("kind");
    doc.remove("description");
    let scene: RccScene = doc.try_into().unwrap();
    let built = scene.build().unwrap();
    assert!(matches!(
        built.held.robot.descent,
        pegdyn::compliant_peg_3d::robot::Descent::Force { force } if force == 5.0
    ));
    let (spec, _) = scene
        .integrator
        .resolved(pegdyn::scene::integrator::DefaultMethod::NON_STIFF);
    let run = run_one(&built, &spec, false, &mut Progress::silent()).unwrap();
    assert_eq!(run.outcome, Outcome::Seated);
    // The wrist pushes with the commanded 5 N less its axial damper's
    // force on the descent (the robot frame stays put): −5 + C_z |v_z|.
    let s = run
        .system
        .sample(run.solution.t_final, &run.solution.x_final)
        .unwrap();
    let fz = s.wrist.unwrap().force_robot.z;
    let vz = run.solution.x_final[9];
    let cz = built.held.wrist.axial_damping;
    assert!(vz < -1e-3, "{vz}");
    assert!(
        (fz - (-5.0 - cz * vz)).abs() < 1e-3,
        "{fz} vs {}",
        -5.0 - cz * vz
    );
}

#[test]
fn from_above_the_mouth_two_point_contact_starts_at_the_analytic_depth() {
    // The shipped scene starts 1 mm above the mouth: the rim lands on the
    // rounded chamfer, slides off it onto the wall (rim_edge + rim_wall at
    // about 1 mm: both points on the rim, not two-point contact) and meets
    // the mouth edge with its side near the analytic two-point depth
    // rho_h + rho_p + (D - d)/theta0 = 5.10 mm. Stopped at 5.5 mm.
    let text = variant_from(
        &[("seat_depth", "0.0055"), ("output_interval", "2e-3")],
        &[],
    );
    assert!(text.contains("start_height = 1e-3 "));
    let s = run_scene(&text, "rcc_above");
    let metric = |name: &str| {
        s.metrics
            .iter()
            .find(|m| m.name.starts_with(name))
            .unwrap_or_else(|| panic!("{name}: {:?}", s.metrics))
            .value
    };
    assert_eq!(metric("outcome"), 0.0, "{:?}", s.metrics);
    let analytic = metric("two-point depth");
    assert!((analytic - 5.10e-3).abs() < 0.01e-3, "{analytic}");
    let simulated = metric("simulated two-point contact from depth");
    assert!(
        (simulated - analytic).abs() < 0.2e-3,
        "{simulated} vs {analytic}"
    );
    // The rim did touch the chamfer first, and the contact list says so.
    let events = std::fs::read_to_string(&s.outputs[1]).unwrap();
    assert!(events.contains("rim_edge 0 -> 1"), "{events}");
    assert!(events.contains("edge_side 0 -> 1"), "{events}");
}
