//! Shared by the end-to-end tests of the `pegdyn` binary (`tests/cli.rs`,
//! `tests/align_forward_scene.rs`, `tests/hostile_scenes.rs`), included with
//! `#[path]`: running the binary from the crate root, and a fresh output
//! directory per test.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the `pegdyn` binary with `args` in the crate root.
pub fn pegdyn(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pegdyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the pegdyn binary runs")
}

/// An empty directory `<prefix>-<test>` under the target's temporary dir,
/// removed first if an earlier run left it.
pub fn fresh_dir(prefix: &str, test: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{prefix}-{test}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("the target's temporary dir is writable");
    d
}
