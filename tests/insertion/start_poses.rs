//! Start poses checked by `check`: a start whose surfaces overlap the block
//! (a tilt or lateral error that puts the rim below the top face, a wrist
//! too soft to hold the peg up) is refused on the field that places it,
//! with the start height that clears the block; that height is accepted.
//! A start that only touches (the `drop_3d` lean) runs.

use crate::common::scene_text::{shipped, with};

use pegdyn::scene::parse_named;

/// The number after `at least ` in `text`.
fn at_least(text: &str) -> f64 {
    let rest = text.split("at least ").nth(1).unwrap_or_default();
    rest.split(' ')
        .next()
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no height in {text}"))
}

/// The start height a refusal names (`at least h`) clears the block, with
/// a micrometre to spare: `text` at that height is accepted.
fn the_named_height_clears(text: &str, shown: &str, case: &str) {
    let clears = at_least(shown) + 1e-6;
    let text = with(text, "start_height", &format!("{clears:e}"));
    assert!(
        parse_named(&text, "rcc").is_ok(),
        "{case} at {clears} m: {:?}",
        parse_named(&text, "rcc").err().map(|e| e.to_string())
    );
}

#[test]
fn a_tilted_start_inside_the_block_is_refused_with_the_height_that_clears_it() {
    for (angle, height) in [
        ("30.0", "1e-3"),
        ("20.0", "0.0"),
        ("-20.0", "2e-3"),
        ("-30.0", "0.0"),
    ] {
        let text = with(
            &with(&shipped("insert_rcc"), "angular_error_deg", angle),
            "start_height",
            height,
        );
        let e = parse_named(&text, "rcc").expect_err("an overlapping start");
        let shown = e.to_string();
        let line = text
            .lines()
            .position(|l| l.starts_with("start_height"))
            .map(|i| i + 1);
        assert_eq!(e.errors.len(), 1, "{shown}");
        assert_eq!(
            e.errors[0].error.field(),
            Some("robot.start_height"),
            "{shown}"
        );
        assert_eq!(e.errors[0].at.map(|a| a.line), line, "{shown}");
        for part in [
            "the start pose overlaps the block",
            "contact force of",
            &format!("robot.angular_error_deg = {}", angle.trim_end_matches(".0")),
            "robot.lateral_error = 3e-4 m",
        ] {
            assert!(shown.contains(part), "{part:?} missing: {shown}");
        }
        the_named_height_clears(&text, &shown, angle);
    }
}

#[test]
fn a_wrist_too_soft_to_hold_the_peg_up_is_named() {
    for k in ["1.0", "10.0", "100.0"] {
        let text = with(&shipped("insert_rcc"), "axial_stiffness", k);
        let e = parse_named(&text, "rcc").expect_err("a sagging start");
        let shown = e.to_string();
        assert_eq!(
            e.errors[0].error.field(),
            Some("wrist.axial_stiffness"),
            "{shown}"
        );
        assert!(
            shown.contains("static sag m g / K_z") && shown.contains(&format!("= {k}:")),
            "{shown}"
        );
    }
}

#[test]
fn a_grid_point_that_starts_inside_the_block_is_named_by_its_entries() {
    let text = with(
        &with(
            &shipped("rotation_assist"),
            "angular_errors_deg",
            "[0.5, 30.0]",
        ),
        "start_height",
        "1e-3",
    );
    let e = parse_named(&text, "grid").expect_err("an overlapping grid point");
    let fields: Vec<&str> = e.errors.iter().filter_map(|l| l.error.field()).collect();
    assert!(
        !fields.is_empty() && fields.iter().all(|f| *f == "grid.angular_errors_deg[1]"),
        "{e}"
    );
    assert!(
        e.to_string().contains("grid.lateral_errors[0] = 1e-4"),
        "{e}"
    );
    let text = with(
        &shipped("design_margins"),
        "angular_errors_deg",
        "[-2.0, 0.0, 25.0]",
    );
    let e = parse_named(&text, "margins").expect_err("an overlapping grid point");
    assert!(
        e.errors
            .iter()
            .all(|l| l.error.field() == Some("grid.angular_errors_deg[2]")),
        "{e}"
    );
    assert!(e.to_string().contains("overlaps the block"), "{e}");
}

#[test]
fn starts_that_only_touch_run() {
    for name in [
        "drop_3d",
        "insert_rcc",
        "rotation_assist",
        "design_margins",
        "insert_compliant",
    ] {
        assert!(parse_named(&shipped(name), name).is_ok(), "{name}");
    }
    // The lean of drop_3d at every tilt and at the smallest sizes touches.
    for gamma in ["0.1", "0.3", "0.8", "1.1"] {
        let text = with(&shipped("drop_3d"), "gamma", gamma);
        assert!(parse_named(&text, "drop").is_ok(), "gamma {gamma}");
    }
    let mut tiny = shipped("drop_3d");
    for (k, v) in [
        ("hole_diameter", "1e-6"),
        ("length", "1e-6"),
        ("rim_fillet", "1e-7"),
        ("mouth_fillet", "1e-7"),
        ("bore_depth", "1e-6"),
    ] {
        tiny = with(&tiny, k, v);
    }
    assert!(
        parse_named(&tiny, "tiny").is_ok(),
        "{:?}",
        parse_named(&tiny, "tiny").err().map(|e| e.to_string())
    );
}

#[test]
fn an_insert_compliant_tilt_out_of_its_start_range_is_named_with_the_bound() {
    let base = shipped("insert_compliant");
    // Too small: the two-point start lies deeper than the peg is long.
    for tilt in ["1e-4", "1e-3"] {
        let e = parse_named(&with(&base, "initial_tilt", tilt), "c").expect_err(tilt);
        let shown = e.to_string();
        assert_eq!(
            e.errors[0].error.field(),
            Some("insert_compliant.initial_tilt"),
            "{shown}"
        );
        assert!(
            shown.contains("beyond insert_compliant.peg_length = 0.1 m"),
            "{shown}"
        );
    }
    // Too large: past the wall contact's split tilt, with its value.
    for tilt in ["0.2", "0.5", "1.5"] {
        let e = parse_named(&with(&base, "initial_tilt", tilt), "c").expect_err(tilt);
        let shown = e.to_string();
        assert_eq!(
            e.errors[0].error.field(),
            Some("insert_compliant.initial_tilt"),
            "{shown}"
        );
        let bound: f64 = shown
            .split("below ")
            .nth(1)
            .and_then(|r| r.split(' ').next())
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("no bound in {shown}"));
        // About 0.8 sqrt(2 c) at c = 0.002.
        assert!(
            (bound / (0.8 * 0.004_f64.sqrt()) - 1.0).abs() < 0.1,
            "{shown}"
        );
        let inside = with(&base, "initial_tilt", &format!("{}", 0.9 * bound));
        assert!(parse_named(&inside, "c").is_ok(), "{shown}");
    }
    assert!(parse_named(&with(&base, "initial_tilt", "0.05"), "c").is_ok());
}

#[test]
fn a_lateral_offset_that_puts_the_rim_into_the_top_face_is_refused() {
    for (offset, height) in [
        ("0.0126", "0.0"),
        ("0.0126", "1e-5"),
        ("0.03", "0.0"),
        ("0.03", "1e-5"),
    ] {
        let text = with(
            &with(&shipped("insert_rcc"), "lateral_error", offset),
            "start_height",
            height,
        );
        let e = parse_named(&text, "rcc").expect_err("an overlapping start");
        let shown = e.to_string();
        assert_eq!(
            e.errors[0].error.field(),
            Some("robot.start_height"),
            "{shown}"
        );
        assert!(
            shown.contains("the start pose overlaps the block")
                && shown.contains(&format!("robot.lateral_error = {offset} m")),
            "{shown}"
        );
        the_named_height_clears(&text, &shown, offset);
    }
}
