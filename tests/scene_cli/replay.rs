//! The replay page a run writes (`<scene>.html`, docs/replay.md): written by
//! `pegdyn run` for the kinds that make one, turned off by `--no-replay` and
//! `[replay] page = false`, kept by a run in memory, not made by a sweep's
//! runs; the grid kinds' `replay.run` picks the run and is checked.

use std::path::Path;

use pegdyn::output::memory::Keep;
use pegdyn::output::names::Part;
use pegdyn::output::sink::Sink;
use pegdyn::scene::{self, Progress, RunContext};

use crate::common::cli::{fresh_dir, pegdyn};

/// The page's file name: the one place these tests name it.
fn page_name(scene: &str) -> String {
    Part::Main.file_name(scene, "html")
}

/// The shipped scene `name` with `edit` applied to its TOML table.
fn shipped(name: &str, edit: impl FnOnce(&mut toml::Table)) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.toml"));
    let text = std::fs::read_to_string(path).expect("a shipped scene");
    let mut t: toml::Table = toml::from_str(&text).expect("shipped scenes are TOML");
    edit(&mut t);
    toml::to_string(&t).expect("a table writes as TOML")
}

fn set(t: &mut toml::Table, dotted: &str, v: impl Into<toml::Value>) {
    let (table, key) = dotted.split_once('.').expect("table.key");
    t.entry(table)
        .or_insert_with(|| toml::Value::Table(toml::Table::new()))
        .as_table_mut()
        .expect("a table")
        .insert(key.into(), v.into());
}

/// The compliant planar peg, 20 ms of it: a quick run with a page.
fn planar(edit: impl FnOnce(&mut toml::Table)) -> String {
    shipped("insert_compliant", |t| {
        set(t, "integrator.t_end", 0.02);
        edit(t);
    })
}

/// A two-point `rotation_assist` grid (spin 0 and 20 rad/s), 40 ms long so
/// that no point seats.
fn tiny_grid(edit: impl FnOnce(&mut toml::Table)) -> String {
    shipped("rotation_assist", |t| {
        set(t, "grid.lateral_errors", vec![3e-4]);
        set(t, "grid.angular_errors_deg", vec![1.5]);
        set(t, "grid.precession_rates", vec![0.0]);
        set(t, "grid.spin_rates", vec![0.0, 20.0]);
        set(t, "integrator.t_end", 0.04);
        edit(t);
    })
}

fn write_scene(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).expect("the test dir is writable");
    path.to_string_lossy().into_owned()
}

fn run_cli(args: &[&str]) -> String {
    let out = pegdyn(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{args:?}: {stderr}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn pegdyn_run_writes_the_page_unless_told_not_to() {
    let dir = fresh_dir("replay", "cli");
    let scene = write_scene(&dir, "tilted", &planar(|_| {}));
    let out = dir.join("out");
    let out_s = out.to_string_lossy().into_owned();
    let stdout = run_cli(&["run", &scene, "--out", &out_s, "-q"]);
    let page = out.join(page_name("tilted"));
    assert!(
        stdout.contains(&format!("wrote {}", page.display())),
        "{stdout}"
    );
    let html = std::fs::read_to_string(&page).expect("the page is written");
    assert!(html.starts_with("<!DOCTYPE html>"), "{}", &html[..40]);
    assert!(html.contains("compliant planar peg pushed in from a two-point start"));
    let manifest = std::fs::read_to_string(out.join(pegdyn::output::names::manifest("tilted")))
        .expect("a manifest");
    assert!(manifest.contains(&page_name("tilted")), "{manifest}");

    // --no-replay: the same run, no page, and the manifest lists the old
    // page as stale rather than as written.
    let stdout = run_cli(&["run", &scene, "--out", &out_s, "-q", "--no-replay"]);
    assert!(!stdout.contains(".html"), "{stdout}");
    // [replay] page = false: no page either.
    let off = write_scene(&dir, "quiet", &planar(|t| set(t, "replay.page", false)));
    let stdout = run_cli(&["run", &off, "--out", &out_s, "-q"]);
    assert!(!stdout.contains(".html"), "{stdout}");
    assert!(!out.join(page_name("quiet")).exists());
}

#[test]
fn a_run_in_memory_keeps_the_same_page_and_a_sweep_run_makes_none() {
    let text = planar(|_| {});
    let dir = fresh_dir("replay", "memory");
    let on_disk = {
        let loaded = scene::parse_named(&text, "mem").expect("valid");
        let mut ctx = RunContext::new(Sink::directory(&dir, "mem"), Progress::silent());
        loaded.run(&mut ctx).expect("runs");
        std::fs::read(dir.join(page_name("mem"))).expect("a page")
    };
    let loaded = scene::parse_named(&text, "mem").expect("valid");
    let mut ctx = RunContext::new(Sink::memory("mem", Keep::Tables), Progress::silent());
    assert!(ctx.replay_wanted());
    loaded.run(&mut ctx).expect("runs");
    let files = ctx.sink().take_files();
    assert_eq!(files.len(), 1);
    assert_eq!(files[0].file, page_name("mem"));
    assert!(
        files[0].bytes == on_disk,
        "the page in memory differs from the file"
    );

    let mut ctx = RunContext::new(Sink::memory("mem", Keep::Nothing), Progress::silent());
    assert!(!ctx.replay_wanted());
    loaded.run(&mut ctx).expect("runs");
    assert!(ctx.sink().take_files().is_empty());
    let ctx = RunContext::new(Sink::memory("mem", Keep::Tables), Progress::silent());
    assert!(!ctx.without_replay().replay_wanted());
}

/// The page of `text` run in memory, as text.
fn page_in_memory(text: &str) -> String {
    let loaded = scene::parse_named(text, "grid").expect("valid");
    let mut ctx = RunContext::new(Sink::memory("grid", Keep::Tables), Progress::silent());
    loaded.run(&mut ctx).expect("runs");
    let files = ctx.sink().take_files();
    assert_eq!(files.len(), 1, "one page");
    String::from_utf8(files[0].bytes.clone()).expect("UTF-8")
}

#[test]
fn a_grid_kind_shows_the_run_replay_run_picks() {
    // Default "worst": nothing seats in 40 ms, so the first point.
    let worst = page_in_memory(&tiny_grid(|_| {}));
    assert!(
        worst.contains("grid point 0 (the first that did not seat)")
            && worst.contains("spin 0 rad/s"),
        "worst"
    );
    let second = page_in_memory(&tiny_grid(|t| set(t, "replay.run", 1)));
    assert!(
        second.contains("grid point 1 (chosen by replay.run)") && second.contains("spin 20 rad/s"),
        "index 1"
    );
    let nominal = page_in_memory(&tiny_grid(|t| set(t, "replay.run", "nominal")));
    assert!(
        nominal.contains("the nominal run (the [robot] table as written)"),
        "nominal"
    );
    assert_ne!(worst, second);
}

#[test]
fn a_bad_replay_table_is_refused_naming_the_field() {
    let refused = |text: &str| -> String {
        match scene::parse_named(text, "bad") {
            Ok(_) => panic!("accepted: {text}"),
            Err(e) => e.to_string(),
        }
    };
    let e = refused(&tiny_grid(|t| set(t, "replay.run", 2)));
    assert!(
        e.contains("replay.run") && e.contains("2 points") && e.contains("0 to 1"),
        "{e}"
    );
    let e = refused(&tiny_grid(|t| set(t, "replay.run", "best")));
    assert!(
        e.contains("replay.run") && e.contains("\"worst\", \"nominal\""),
        "{e}"
    );
    let e = refused(&tiny_grid(|t| set(t, "replay.run", -1)));
    assert!(e.contains("replay.run") && e.contains("-1"), "{e}");
    let e = refused(&tiny_grid(|t| set(t, "replay.page", "yes")));
    assert!(e.contains("replay.page"), "{e}");
    // A kind of one run chooses none.
    let e = refused(&planar(|t| set(t, "replay.run", 0)));
    assert!(
        e.contains("replay.run") && e.contains("unknown field"),
        "{e}"
    );
    let e = refused(&planar(|t| set(t, "replay.colour", "red")));
    assert!(e.contains("replay.colour"), "{e}");
}
