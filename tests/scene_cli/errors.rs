//! Errors that point the right way: every value a scene refuses is named by
//! its own dotted path, with the value as written, on its own line (also a
//! list entry, a value a model refuses after the checks, a grid entry that
//! replaces a robot field), in the words of a TOML file (no `u64`,
//! `found map`, `as i128`), with long text cut; repeated list entries are
//! refused. Each property is checked on every numeric value of every
//! shipped scene, not only on the examples that first showed it.

use pegdyn::error::SceneErrors;
use pegdyn::scene::parse_named;

use crate::common::fields::{Field, JARGON, numeric_fields, replaced};
use crate::common::fuzz::shipped_scenes;

/// The refusal of `text`, `None` when it is accepted.
fn refusal(text: &str, name: &str) -> Option<SceneErrors> {
    parse_named(text, name).err()
}

fn no_jargon(e: &SceneErrors, what: &str) {
    let text = e.to_string();
    for j in JARGON {
        assert!(!text.contains(j), "{what}: `{j}` in {text}");
    }
}

/// Whether `e` places an error on the line of `f`, or names `f` in one.
fn points_at(e: &SceneErrors, f: &Field) -> bool {
    e.errors
        .iter()
        .any(|l| l.at.is_some_and(|at| at.line == f.line) || l.error.to_string().contains(&f.path))
}

#[test]
fn a_non_finite_value_is_named_with_its_value_on_its_own_line_in_every_scene() {
    let mut checked = 0;
    for (name, text) in shipped_scenes() {
        for f in numeric_fields(&text) {
            for token in ["nan", "inf", "-inf"] {
                let what = format!("{name}: {} = {token}", f.path);
                let e = refusal(&replaced(&text, &f, token), &name)
                    .unwrap_or_else(|| panic!("{what}: accepted"));
                no_jargon(&e, &what);
                let named = e
                    .errors
                    .iter()
                    .find(|l| l.error.field() == Some(f.path.as_str()))
                    .unwrap_or_else(|| panic!("{what}: not named in {e}"));
                assert_eq!(
                    named.at.map(|at| at.line),
                    Some(f.line),
                    "{what}: not on its line: {e}"
                );
                let shown = named.error.to_string().to_lowercase();
                assert!(shown.contains(token), "{what}: value not shown: {e}");
                checked += 1;
            }
        }
    }
    assert!(checked > 300, "{checked}");
}

#[test]
fn an_extreme_value_is_refused_where_it_is_written_in_every_scene() {
    for (name, text) in shipped_scenes() {
        for f in numeric_fields(&text) {
            let tokens: &[&str] = if f.integer {
                &["0", "-1", "99999999999999"]
            } else {
                &["1e300", "-1e300", "1e-300", "-1e-300", "0.0"]
            };
            for token in tokens {
                let what = format!("{name}: {} = {token}", f.path);
                let Some(e) = refusal(&replaced(&text, &f, token), &name) else {
                    continue;
                };
                no_jargon(&e, &what);
                assert!(
                    e.errors.iter().all(|l| l.at.is_some()),
                    "{what}: an error without a place: {e}"
                );
                // A work estimate above its `[limits]` key names the field
                // the estimate is kept under (the samples under
                // `integrator.output_interval`, however long the span).
                let over_limit = e.to_string().contains("[limits]");
                assert!(
                    points_at(&e, &f) || over_limit,
                    "{what}: refused elsewhere: {e}"
                );
            }
        }
    }
}

#[test]
fn a_value_of_the_wrong_type_is_named_in_toml_words() {
    let tokens = [
        "{ a = 1 }",
        "[1, 2]",
        "\"x\"",
        "true",
        "1979-05-27",
        "99999999999999999999",
    ];
    for (name, text) in shipped_scenes() {
        for f in numeric_fields(&text) {
            for token in tokens {
                let what = format!("{name}: {} = {token}", f.path);
                let Some(e) = refusal(&replaced(&text, &f, token), &name) else {
                    panic!("{what}: accepted");
                };
                no_jargon(&e, &what);
                assert!(points_at(&e, &f), "{what}: refused elsewhere: {e}");
            }
        }
    }
}

/// The shipped `rotation_assist` scene with `key = value` in `[grid]`.
fn grid(key: &str, value: &str) -> String {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/rotation_assist.toml"
    ))
    .unwrap();
    let line = text
        .lines()
        .find(|l| l.starts_with(&format!("{key} =")))
        .unwrap_or_else(|| panic!("no {key}"));
    text.replace(line, &format!("{key} = {value}"))
}

#[test]
fn out_of_range_grid_entries_are_named_as_grid_entries() {
    for (key, value, entry) in [
        ("lateral_errors", "[1e-4, 0.2]", "grid.lateral_errors[1]"),
        ("lateral_errors", "[-1.0, 3e-4]", "grid.lateral_errors[0]"),
        (
            "angular_errors_deg",
            "[0.5, 45.0]",
            "grid.angular_errors_deg[1]",
        ),
        ("precession_rates", "[0.0, 2e4]", "grid.precession_rates[1]"),
        ("spin_rates", "[-3e4, 20.0]", "grid.spin_rates[0]"),
    ] {
        let e = refusal(&grid(key, value), "grid").expect("refused");
        let text = e.to_string();
        let named: Vec<&str> = e.errors.iter().filter_map(|l| l.error.field()).collect();
        assert_eq!(named, [entry], "{text}");
        assert!(!text.contains("`robot."), "{text}");
        assert!(text.contains("must lie in"), "{text}");
    }
}

#[test]
fn repeated_list_entries_are_refused_naming_the_entry_they_repeat() {
    let e = refusal(&grid("spin_rates", "[0.0, 20.0, -0.0]"), "g").expect("refused");
    assert!(
        e.to_string()
            .contains("`grid.spin_rates[2]` = -0.0: repeats grid.spin_rates[0]"),
        "{e}"
    );
    let e = refusal(&grid("lateral_errors", "[1e-4, 3e-4, 1e-4, 3e-4]"), "g").expect("refused");
    let named: Vec<&str> = e.errors.iter().filter_map(|l| l.error.field()).collect();
    assert_eq!(
        named,
        ["grid.lateral_errors[2]", "grid.lateral_errors[3]"],
        "{e}"
    );
    for (scene, from, to, entry) in [
        (
            "design_margins",
            "angular_errors_deg = [-2.0, 0.0, 2.0]",
            "angular_errors_deg = [-2.0, 0.0, 2.0, 0.0]",
            "grid.angular_errors_deg[3]",
        ),
        (
            "jamming",
            "mu = [0.1, 0.3]",
            "mu = [0.1, 0.3, 0.1]",
            "jamming.mu[2]",
        ),
        (
            "fig9",
            "psidot = [0.0, 10.0]",
            "psidot = [0.0, 10.0, 10.0]",
            "motion.psidot[2]",
        ),
    ] {
        let path = format!("{}/scenes/{scene}.toml", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(path).unwrap();
        assert!(text.contains(from), "{scene}: {from}");
        let e = refusal(&text.replacen(from, to, 1), scene).expect("refused");
        assert!(
            e.errors
                .iter()
                .any(|l| l.error.field() == Some(entry) && l.error.to_string().contains("repeats")),
            "{scene}: {e}"
        );
    }
}

#[test]
fn long_text_from_the_scene_is_cut_in_errors() {
    let pendulum = "kind = \"pendulum\"\n[pendulum]\nlength = 1.0\nmass = 1.0\ntheta0_deg = 10.0\n\
                    [integrator]\nt_end = 1.0\n";
    let long = "x".repeat(10_000_000);
    for text in [
        format!("{long} = 1\n{pendulum}"),
        pendulum.replace("mass = 1.0", &format!("{long} = 1.0")),
        format!("kind = \"{long}\"\n"),
        format!("{pendulum}method = \"{long}\"\n"),
        pendulum.replace("mass = 1.0", &format!("mass = \"{long}\"")),
    ] {
        let e = refusal(&text, "long").expect("refused");
        let shown = e.to_string();
        assert!(
            shown.len() < 1000,
            "{} bytes: {}",
            shown.len(),
            &shown[..200]
        );
        assert!(
            shown.contains("10000000 bytes") || shown.contains("bytes)"),
            "{shown}"
        );
    }
}

#[test]
fn sweep_fields_out_of_their_physical_ranges_are_refused_by_name() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/jamming.toml"))
        .unwrap();
    let set = |key: &str, value: &str| {
        let from = text.find("[sweep]").unwrap();
        let (head, tail) = text.split_at(from);
        let line = tail
            .lines()
            .find(|l| l.starts_with(&format!("{key} =")))
            .unwrap_or_else(|| panic!("no {key}"));
        format!(
            "{head}{}",
            tail.replacen(line, &format!("{key} = {value}"), 1)
        )
    };
    for (key, value, field) in [
        ("fz_n", "1e300", "sweep.fz_n"),
        ("fz_n", "1e-300", "sweep.fz_n"),
        ("window_s", "1e-300", "sweep.window_s"),
        ("window_s", "0.5", "sweep.window_s"),
        ("t_max_s", "1e-300", "sweep.t_max_s"),
        ("advance_m", "1e-7", "sweep.advance_m"),
        ("fx_over_fz_max", "1e300", "sweep.fx_over_fz_max"),
        ("m_over_rfz_max", "1e-300", "sweep.m_over_rfz_max"),
        ("contact_damping", "nan", "sweep.contact_damping"),
        ("n", "2", "sweep.n"),
        // Not in the shipped table: written after `window_s`.
        ("window_s", "0.05\natol = 1e-300", "sweep.atol"),
        ("window_s", "0.05\natol = 1e-2", "sweep.atol"),
        ("window_s", "0.05\nrtol = 1e-300", "sweep.rtol"),
    ] {
        let e = refusal(&set(key, value), "jamming").unwrap_or_else(|| panic!("{key} accepted"));
        assert!(
            e.errors.iter().any(|l| l.error.field() == Some(field)),
            "{key} = {value}: {e}"
        );
        assert!(
            !e.errors.iter().any(|l| l.error.field() == Some("sweep")),
            "{e}"
        );
    }
}
