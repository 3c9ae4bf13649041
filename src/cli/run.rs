//! `pegdyn run SCENE [--out DIR]`: load, validate, run, print a summary.

use std::path::Path;
use std::process::ExitCode;

use pegdyn::scene::{self, Progress, RunContext};

/// Runs one scene file, writing into `out`.
pub fn run(path: &Path, out: &Path, quiet: bool) -> ExitCode {
    let loaded = match scene::load(path) {
        Ok(s) => s,
        Err(errors) => {
            for e in errors.to_string().lines() {
                errln!("{}: error: {e}", path.display());
            }
            return ExitCode::FAILURE;
        }
    };
    if let Err(e) = std::fs::create_dir_all(out) {
        errln!(
            "error: cannot create output directory {}: {e}",
            out.display()
        );
        return ExitCode::FAILURE;
    }
    outln!(
        "{} ({}): {}",
        loaded.name,
        loaded.kind,
        loaded.scene.describe()
    );
    let mut ctx = RunContext {
        out_dir: out.to_path_buf(),
        name: loaded.name.clone(),
        progress: Progress::new(quiet),
    };
    let result = loaded.scene.run(&mut ctx);
    ctx.progress.finish();
    match result {
        Ok(summary) => {
            outln!("{}", summary.to_string().trim_end());
            match &summary.integration {
                Some(i) if !i.success => {
                    errln!(
                        "{}: error: integration stopped early: {}",
                        path.display(),
                        i.stop
                    );
                    ExitCode::FAILURE
                }
                _ => ExitCode::SUCCESS,
            }
        }
        Err(e) => {
            errln!("{}: error: {e}", path.display());
            ExitCode::FAILURE
        }
    }
}
