//! Shared by the end-to-end tests of the `pegdyn` binary
//! (`tests/scene_cli/`, the scene tests of the other groups): running the
//! binary from the crate root, a fresh output directory per test, and
//! running a scene in-process and reading its summary's metrics.

#![allow(dead_code)]

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};

/// Runs the `pegdyn` binary with `args` in the crate root.
pub fn pegdyn(args: &[&str]) -> Output {
    pegdyn_os(args)
}

/// As [`pegdyn`], with arguments that need not be UTF-8 (paths).
pub fn pegdyn_os<S: AsRef<OsStr>>(args: &[S]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pegdyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the pegdyn binary runs")
}

/// Starts the `pegdyn` binary with `args` in the crate root, its output
/// captured, without waiting for it.
pub fn spawn_pegdyn(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_pegdyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the pegdyn binary starts")
}

/// Runs `pegdyn args` with its address space capped at `kib` KiB (`ulimit
/// -v` in `sh`), so that an allocation the machine cannot hold fails
/// instead of succeeding lazily.
pub fn pegdyn_capped(kib: u64, args: &[&str]) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {kib} && exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_pegdyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("sh runs the pegdyn binary")
}

/// An empty directory `<prefix>-<test>` under the target's temporary dir,
/// removed first if an earlier run left it.
pub fn fresh_dir(prefix: &str, test: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{prefix}-{test}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("the target's temporary dir is writable");
    d
}

/// Parses `text` as a scene named `name` and runs it in-process, writing
/// its files into `dir` (silent progress).
pub fn run_scene(text: &str, name: &str, dir: &Path) -> pegdyn::scene::RunSummary {
    let loaded = pegdyn::scene::parse_named(text, name).expect("the test scene parses");
    let sink = pegdyn::output::sink::Sink::directory(dir, name);
    let mut ctx = pegdyn::scene::RunContext::new(sink, pegdyn::scene::Progress::silent());
    loaded.run(&mut ctx).expect("the test scene runs")
}

/// The value of the first metric of `summary` whose name starts with
/// `prefix`.
pub fn metric(summary: &pegdyn::scene::RunSummary, prefix: &str) -> f64 {
    summary
        .metrics
        .iter()
        .find(|m| m.name.starts_with(prefix))
        .map(|m| m.value)
        .unwrap_or_else(|| panic!("no metric {prefix}: {:?}", summary.metrics))
}
