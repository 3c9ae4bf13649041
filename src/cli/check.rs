//! `pegdyn check SCENE...`: parse and validate, print `OK` with a one-line
//! description, or every error found, prefixed by the file name.

use std::path::PathBuf;
use std::process::ExitCode;

use pegdyn::scene;
use pegdyn::scene::limits::LimitOverrides;

/// Checks each file; fails if any file fails.
pub fn check(paths: &[PathBuf], limits: &LimitOverrides) -> ExitCode {
    let mut ok = true;
    for path in paths {
        match scene::load_with(path, limits) {
            Ok(s) => outln!(
                "{}: OK ({}): {}",
                path.display(),
                s.kind,
                s.scene.describe()
            ),
            Err(errors) => {
                ok = false;
                for e in errors.to_string().lines() {
                    errln!("{}: error: {e}", path.display());
                }
            }
        }
    }
    if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
