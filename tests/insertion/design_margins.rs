//! The chamfer's capture rule checked by simulation, and the
//! `design_margins` scene kind run end to end and refused on bad `[grid]`
//! fields with the field named (`docs/insertion.md`, "Design margins").

use crate::common::cli;
use crate::common::differences::richardson;

use pegdyn::compliant_peg_3d::outcome::Outcome;
use pegdyn::scene::Progress;
use pegdyn::scene::kinds::design_margins::chamfer::Touch;
use pegdyn::scene::kinds::design_margins::{DesignScene, GridRun};

/// The shipped `design_margins` scene's text with the first line of each
/// key replaced (the key at the start of a line; `seat_depth` is the
/// `[grid]` table's, which comes first).
fn variant(changes: &[(&str, &str)]) -> String {
    let mut done = vec![false; changes.len()];
    include_str!("../../scenes/design_margins.toml")
        .lines()
        .map(|l| {
            for (i, (k, v)) in changes.iter().enumerate() {
                if !done[i] && (l.starts_with(&format!("{k} ")) || l.starts_with(&format!("{k}=")))
                {
                    done[i] = true;
                    return format!("{k} = {v}");
                }
            }
            l.to_string()
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn design(changes: &[(&str, &str)]) -> pegdyn::scene::kinds::design_margins::Design {
    let mut doc: toml::Table = toml::from_str(&variant(changes)).unwrap();
    doc.remove("kind");
    doc.remove("description");
    let scene: DesignScene = doc.try_into().unwrap();
    scene.prepare().unwrap()
}

fn find(rows: &[GridRun], e: f64, deg: f64) -> &GridRun {
    rows.iter()
        .find(|r| r.point.centre_lateral == e && r.point.angular_deg == deg)
        .unwrap()
}

/// Not seated, held at the mouth: the tip no deeper than the mouth's
/// round (`ρ_h` = 0.5 mm), the rim on the round or the top face and
/// nothing in the bore.
fn outside_the_mouth(r: &GridRun) {
    assert_ne!(r.outcome, Outcome::Seated, "{r:?}");
    assert!(r.end_depth < 5e-4, "{r:?}");
    assert!(
        r.end_contacts.contains("rim_edge") || r.end_contacts.contains("rim_top"),
        "{r:?}"
    );
    assert!(
        !r.end_contacts.contains("rim_wall") && !r.end_contacts.contains("edge_side"),
        "{r:?}"
    );
}

#[test]
fn the_chamfer_accepts_what_the_rule_predicts_and_the_tilt_moves_the_tip_by_its_lever() {
    // Compliance centre 25 mm above the tip, tilt towards −x: the tip lies
    // at e_c + L_c sin θ = e_c ± 0.8725 mm at ±2°. The rule's aligned tip
    // capture is W_μ − (r − ρ_p) = 0.8375 − 0.8 × 0.2/√1.04 = 0.6806 mm, so
    // a centre error of ±0.9 mm is outside it for an aligned peg. With the
    // tilt that brings the tip back over the hole (tip ∓0.0275 mm) the rim
    // passes inside the round untouched (margin +0.65 mm) and seats. With
    // the other tilt the tip is ±1.7725 mm out; the side of the rim facing
    // the error is raised, its lower points off the error's plane touch
    // the round first at α = 14.3°, 65° from the error's line, where the
    // slope along the line loses to friction: rejected by 0.073 mm, and
    // the robot stops at its force limit with the rim on the round.
    let d = design(&[
        ("centre_lateral_errors", "[-0.9e-3, 0.9e-3]"),
        ("angular_errors_deg", "[-2.0, 2.0]"),
        ("seat_depth", "0.0015"),
    ]);
    let c = &d.capture;
    assert!((c.aligned_tip_error() - (0.8375e-3 - 0.8e-3 * 0.2 / 1.04f64.sqrt())).abs() < 1e-12);
    let rows = d.run_grid(&mut Progress::silent()).unwrap();
    assert_eq!(rows.len(), 4);
    let lever = 0.025 * 2f64.to_radians().sin();
    for (e, deg, inside) in [
        (-0.9e-3, 2.0, true),
        (0.9e-3, -2.0, true),
        (-0.9e-3, -2.0, false),
        (0.9e-3, 2.0, false),
    ] {
        let r = find(&rows, e, deg);
        let tip = e + lever * deg.signum();
        assert!((r.verdict.tip[0] - tip).abs() < 1e-15, "{r:?}");
        if inside {
            assert_eq!(r.verdict.touch, Touch::None, "{r:?}");
            assert!((r.verdict.margin - 0.650e-3).abs() < 1e-6, "{r:?}");
            assert_eq!(r.outcome, Outcome::Seated, "{r:?}");
            assert!((r.end_depth - 0.0015).abs() < 1e-9, "{r:?}");
        } else {
            match r.verdict.touch {
                Touch::Round {
                    alpha, cos_azimuth, ..
                } => {
                    assert!((alpha.to_degrees() - 14.27).abs() < 0.01, "{r:?}");
                    assert!((cos_azimuth - 0.4235).abs() < 1e-3, "{r:?}");
                }
                other => panic!("{other:?}"),
            }
            assert!((r.verdict.margin + 0.0733e-3).abs() < 1e-6, "{r:?}");
            outside_the_mouth(r);
            assert!(
                matches!(r.outcome, Outcome::ForceLimit { which: "wrist", .. }),
                "{r:?}"
            );
        }
        assert!(r.agrees(), "{r:?}");
    }
}

#[test]
fn an_aligned_peg_is_captured_inside_the_width_and_not_beyond() {
    // θ = 0: the tip's error is the centre's. 0.3 mm is inside the
    // 0.6806 mm capture (margin +0.381 mm); at 1.3 and 2.0 mm the rim's
    // outer arc lands on the top face, its farthest tube centre 0.46 and
    // 1.16 mm beyond the round's (margins −0.62 and −1.32 mm).
    let d = design(&[
        ("centre_lateral_errors", "[0.3e-3, 1.3e-3, 2.0e-3]"),
        ("angular_errors_deg", "[0.0]"),
        ("seat_depth", "0.0015"),
    ]);
    let rows = d.run_grid(&mut Progress::silent()).unwrap();
    let inside = find(&rows, 0.3e-3, 0.0);
    assert!(
        (inside.verdict.margin - (0.6806e-3 - 0.3e-3)).abs() < 1e-7,
        "{inside:?}"
    );
    assert_eq!(inside.outcome, Outcome::Seated, "{inside:?}");
    for (e, margin) in [(1.3e-3, -0.6194e-3), (2.0e-3, -1.3194e-3)] {
        let outside = find(&rows, e, 0.0);
        assert!(
            matches!(outside.verdict.touch, Touch::TopFace { .. }),
            "{outside:?}"
        );
        assert!(
            (outside.verdict.margin - margin).abs() < 1e-7,
            "{outside:?}"
        );
        outside_the_mouth(outside);
    }
}

#[test]
fn bad_grid_fields_are_refused_naming_them() {
    for (key, bad, field) in [
        (
            "angular_errors_deg",
            "[0.0, 45.0]",
            "grid.angular_errors_deg[1]",
        ),
        ("centre_lateral_errors", "[]", "grid.centre_lateral_errors"),
        (
            "centre_lateral_errors",
            "[2.0]",
            "grid.centre_lateral_errors[0]",
        ),
        (
            "centre_lateral_errors",
            "[0.06]",
            "grid.centre_lateral_errors[0]",
        ),
        ("seat_depth", "0.5", "grid.seat_depth"),
    ] {
        let text = variant(&[(key, bad)]);
        let err = pegdyn::scene::parse(&text).unwrap_err().to_string();
        assert!(err.contains(field), "{key} = {bad}: {err}");
    }
    // 15 grid points and the nominal run against a limit of 10 runs.
    let text = format!(
        "{}\n[limits]\nmax_runs = 10\n",
        include_str!("../../scenes/design_margins.toml")
    );
    let err = pegdyn::scene::parse(&text).unwrap_err().to_string();
    assert!(
        err.contains("`grid`") && err.contains("1.600e1 runs (max_runs)"),
        "{err}"
    );
}

#[test]
fn design_margins_runs_end_to_end_and_writes_its_files() {
    // A small grid and a short nominal run: 2° error, two-point contact
    // from about 3 mm, seated at 4 mm.
    let text = variant(&[
        ("centre_lateral_errors", "[0.0]"),
        ("angular_errors_deg", "[0.0, 2.0]"),
        ("seat_depth", "0.0015"),
        ("angular_error_deg", "2.0"),
        ("lateral_error", "0.0"),
    ])
    .replace("seat_depth = 0.008 ", "seat_depth = 0.004 ");
    let dir = cli::fresh_dir("insertion", "design_margins");
    let summary = cli::run_scene(&text, "design", &dir);
    let metric = |name: &str| cli::metric(&summary, name);
    assert_eq!(metric("grid runs"), 2.0);
    // (0, 0°) passes into the bore untouched; (0, 2°) puts the tip
    // 0.8725 mm out, beyond the aligned capture of 0.68 mm, but the raised
    // side of the tilted rim first touches the round off the error's plane
    // at α = 27.3°: accepted, and seated.
    assert_eq!(metric("grid points the capture rule accepts"), 2.0);
    assert_eq!(metric("grid runs seated"), 2.0);
    assert_eq!(
        metric("grid points the capture rule classifies as the simulation"),
        2.0
    );
    assert!((metric("wedging possible") - 0.2 * 0.025 * 0.997).abs() < 1e-12);
    let grid = std::fs::read_to_string(dir.join("design.csv")).unwrap();
    assert_eq!(grid.lines().count(), 3, "{grid}");
    let depth = std::fs::read_to_string(dir.join("design.depth.csv")).unwrap();
    assert_eq!(depth.lines().count(), 65);
    // The nominal run reaches two-point contact: some rows carry its ratio.
    let simulated = depth.lines().skip(1).filter(|l| !l.ends_with(',')).count();
    assert!(simulated > 5, "{depth}");
    for f in ["design.svg", "design.nojam.svg", "design.sensitivities.svg"] {
        let svg = std::fs::read_to_string(dir.join(f)).unwrap();
        assert!(svg.contains("<svg"), "{f}");
    }
    // The shipped [sensitivities] table: 3 widths x 6 fields. The capture
    // width W_mu = R + rho_h - (rho_h + rho_p) mu/sqrt(1 + mu^2) moves one
    // for one with the bore radius D/2 and not with the compliance centre.
    let sens = std::fs::read_to_string(dir.join("design.sensitivities.csv")).unwrap();
    assert_eq!(sens.lines().count(), 1 + 18, "{sens}");
    let cells = |metric: &str, field: &str| -> Vec<String> {
        let line = sens
            .lines()
            .find(|l| l.starts_with(&format!("{metric},{field},")))
            .unwrap_or_else(|| panic!("{metric} along {field}: {sens}"));
        line.split(',').map(str::to_owned).collect()
    };
    let row = cells("capture_width_m", "peg.hole_diameter");
    assert!(
        (row[3].parse::<f64>().unwrap() - 0.5).abs() < 1e-15,
        "{row:?}"
    );
    let row = cells("frictionless_capture_width_m", "wrist.centre_height");
    assert_eq!(
        (row[3].as_str(), row[5].as_str()),
        ("0", "not used by this model")
    );
    let ranking = summary
        .metrics
        .iter()
        .find(|m| m.name == "elasticities of capture_width_m")
        .and_then(|m| m.text.clone())
        .unwrap_or_else(|| panic!("the ranking is in the summary: {:?}", summary.metrics));
    assert!(ranking.starts_with("peg.hole_diameter"), "{ranking}");
}

#[test]
fn the_capture_widths_derivatives_match_differences_of_the_scene_along_every_field() {
    use pegdyn::scene::kinds::design_margins::sensitivities::{self, CaptureFields, FIELDS};
    // The keys of the fields in the scene's text (each appears once).
    let keys = [
        "hole_diameter",
        "clearance_ratio",
        "rim_fillet",
        "mouth_fillet",
        "friction",
        "centre_height",
    ];
    let grid = [
        ("centre_lateral_errors", "[0.0]"),
        ("angular_errors_deg", "[0.0]"),
    ];
    // A design away from the shipped one, so that no factor is 1 or 0.
    let base = [0.031, 0.0041, 4.1e-4, 7.3e-4, 0.37, 0.019];
    let at = |k: usize, v: Option<f64>| {
        let texts: Vec<String> = (0..6)
            .map(|i| {
                format!(
                    "{:e}",
                    if i == k {
                        v.unwrap_or(base[i])
                    } else {
                        base[i]
                    }
                )
            })
            .collect();
        let mut changes = grid.to_vec();
        for (key, text) in keys.iter().zip(&texts) {
            changes.push((key, text.as_str()));
        }
        design(&changes)
    };
    let d = at(0, None);
    let fields = CaptureFields {
        hole_diameter: d.nominal.params.hole_diameter,
        clearance_ratio: d.scene.peg.clearance_ratio,
    };
    let chosen: Vec<usize> = (0..FIELDS.len()).collect();
    let rows = sensitivities::rows(&d.capture, fields, &chosen);
    assert_eq!(rows.len(), 18);
    let widths: [fn(&pegdyn::scene::kinds::design_margins::chamfer::Capture) -> f64; 3] = [
        |c| c.width(),
        |c| c.frictionless_width(),
        |c| c.aligned_tip_error(),
    ];
    for (m, width) in widths.iter().enumerate() {
        for k in 0..FIELDS.len() {
            let row = &rows[m * FIELDS.len() + k];
            assert_eq!(row.parameter, FIELDS[k]);
            let exact = row.derivative.unwrap();
            let fd = richardson(base[k], 1e-3 * base[k].abs(), |v| {
                width(&at(k, Some(v)).capture)
            });
            // Each width is a few hundredths of a metre in fields of
            // metres (derivatives of order one) or of one (friction,
            // clearance): 1e-9 of the largest derivative is far above the
            // differences' rounding.
            assert!(
                (exact - fd).abs() <= 1e-9 * exact.abs().max(1e-3),
                "{} along {}: {exact} against {fd}",
                row.metric,
                row.parameter
            );
            if k == 5 {
                assert_eq!((exact, row.flag.as_str()), (0.0, "not used by this model"));
            } else {
                assert!(row.flag.is_empty(), "{row:?}");
                let el = row.elasticity.unwrap();
                assert!(
                    (el - base[k] / row.value.unwrap() * exact).abs() < 1e-15 * el.abs().max(1.0)
                );
            }
        }
    }
}

#[test]
fn a_capture_sensitivities_table_is_refused_on_bad_names_naming_the_valid_ones() {
    for (list, says) in [
        (
            r#"["peg.friction", "robot.speed"]"#,
            "unknown field; the fields are: peg.hole_diameter",
        ),
        (r#"["peg.friction", "peg.friction"]"#, "named twice"),
        ("[]", "name at least one field"),
    ] {
        let text = format!(
            "{}\n[sensitivities]\nparameters = {list}\n",
            variant(&[]).split("\n[sensitivities]").next().unwrap()
        );
        let err = pegdyn::scene::parse(&text).unwrap_err().to_string();
        assert!(
            err.contains("sensitivities.parameters") && err.contains(says),
            "{list}: {err}"
        );
    }
    // No error_control: nothing is integrated.
    let text = variant(&[]).replace(
        "[sensitivities]",
        "[sensitivities]\nerror_control = \"all\"",
    );
    let err = pegdyn::scene::parse(&text).unwrap_err().to_string();
    assert!(err.contains("error_control"), "{err}");
}
