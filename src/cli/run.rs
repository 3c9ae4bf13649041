//! `pegdyn run SCENE [--out DIR]`: load, validate, run, print a summary,
//! and record the run in `<out>/<scene>.run.toml`.

use std::path::Path;
use std::process::ExitCode;

use pegdyn::output::manifest;
use pegdyn::output::sink::Sink;
use pegdyn::scene::limits::LimitOverrides;
use pegdyn::scene::{self, Progress, RunContext};

/// Whether the scene file lies in `out` under a name an output could take
/// (any extension but `.toml`: outputs are `.csv`, `.svg`, `.run.toml`).
fn scene_in_outputs(path: &Path, out: &Path) -> bool {
    let dir = |p: &Path| p.canonicalize().ok();
    let parent = path.parent().filter(|p| !p.as_os_str().is_empty());
    let scene_dir = dir(parent.unwrap_or(Path::new(".")));
    scene_dir.is_some() && scene_dir == dir(out) && path.extension().is_none_or(|e| e != "toml")
}

/// Runs one scene file, writing into `out` (with `no_replay`, no replay
/// page).
pub fn run(
    path: &Path,
    out: &Path,
    quiet: bool,
    limits: &LimitOverrides,
    no_replay: bool,
) -> ExitCode {
    let loaded = match scene::load_with(path, limits) {
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
    if scene_in_outputs(path, out) {
        errln!(
            "{}: error: the scene file lies in the output directory {} under a name its outputs \
             could take; choose another --out directory or save the scene as .toml",
            path.display(),
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
    // The scene file is never replaced by an output.
    let sink = Sink::directory(out, &loaded.name).protecting(path);
    let mut ctx = RunContext::new(sink, Progress::new(quiet));
    if no_replay {
        ctx = ctx.without_replay();
    }
    let result = loaded.run(&mut ctx);
    ctx.progress.finish();
    let (code, status) = match result {
        Ok(summary) => {
            outln!("{}", summary.to_string().trim_end());
            match &summary.integration {
                Some(i) if !i.success => {
                    errln!(
                        "{}: error: integration stopped early: {}",
                        path.display(),
                        i.stop
                    );
                    (
                        ExitCode::FAILURE,
                        format!("partial: integration stopped early: {}", i.stop),
                    )
                }
                _ => (ExitCode::SUCCESS, "ok".to_owned()),
            }
        }
        Err(e) => {
            errln!("{}: error: {e}", path.display());
            (ExitCode::FAILURE, format!("failed: {e}"))
        }
    };
    let text = std::fs::read(path).unwrap_or_default();
    let record = manifest::Manifest {
        scene: path,
        scene_text: &text,
        command: std::env::args().collect::<Vec<_>>().join(" "),
        status,
        files: ctx.sink().written(),
    };
    match manifest::write(out, &loaded.name, &record) {
        Ok((_, stale)) if !stale.is_empty() => {
            let names: Vec<String> = stale.iter().map(|p| p.display().to_string()).collect();
            errln!(
                "{}: warning: files of an earlier run, not written by this one: {}",
                path.display(),
                names.join(", ")
            );
        }
        Ok(_) => {}
        Err(e) => errln!("{}: warning: no run manifest: {e}", path.display()),
    }
    code
}
