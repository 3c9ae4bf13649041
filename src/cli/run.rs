//! `pegdyn run SCENE [--out DIR]`: load, validate, record the run as
//! running, run (SIGINT and SIGTERM stop it cooperatively), print a
//! summary, and record how it ended in `<out>/<scene>.run.toml`.

use std::path::Path;
use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

use pegdyn::error::RunError;
use pegdyn::integrate::Interrupt;
use pegdyn::output::record::{Origin, RunRecord};
use pegdyn::output::sink::Sink;
use pegdyn::scene::limits::LimitOverrides;
use pegdyn::scene::{self, Progress, RunContext};
use signal_hook::consts::{SIGINT, SIGTERM};

/// Whether the scene file lies in `out` under a name an output could take
/// (any extension but `.toml`: outputs are `.csv`, `.svg`, `.run.toml`).
fn scene_in_outputs(path: &Path, out: &Path) -> bool {
    let dir = |p: &Path| p.canonicalize().ok();
    let parent = path.parent().filter(|p| !p.as_os_str().is_empty());
    let scene_dir = dir(parent.unwrap_or(Path::new(".")));
    scene_dir.is_some() && scene_dir == dir(out) && path.extension().is_none_or(|e| e != "toml")
}

/// Makes SIGINT and SIGTERM request `stop` (the run ends cooperatively at
/// its next step and records `interrupted`); a second signal ends the
/// process at once (exit 128 + signal, the manifest left `running` as
/// after `kill -9`, for the next run to report). Returns the number of the
/// last signal received (0 for none).
fn on_signals(stop: &Interrupt) -> std::io::Result<Arc<AtomicUsize>> {
    let which = Arc::new(AtomicUsize::new(0));
    for sig in [SIGINT, SIGTERM] {
        // Registered first, so that it sees the flag as the earlier signal left it.
        signal_hook::flag::register_conditional_shutdown(sig, 128 + sig, stop.flag())?;
        signal_hook::flag::register_usize(sig, Arc::clone(&which), sig as usize)?;
        signal_hook::flag::register(sig, stop.flag())?;
    }
    Ok(which)
}

fn signal_name(sig: usize) -> &'static str {
    match i32::try_from(sig) {
        Ok(SIGINT) => "SIGINT",
        Ok(SIGTERM) => "SIGTERM",
        _ => "a stop request",
    }
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
    // The text is read once: what is parsed is what the manifest hashes.
    let loaded = scene::loader::read(path).and_then(|(text, name)| {
        scene::parse_named_with(&text, &name, limits).map(|loaded| (loaded, text))
    });
    let (loaded, text) = match loaded {
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
    let stop = Interrupt::new();
    let signal = on_signals(&stop).unwrap_or_else(|e| {
        errln!(
            "{}: warning: cannot catch SIGINT/SIGTERM ({e}): an interrupted run will leave its \
             manifest saying \"running\"",
            path.display()
        );
        Arc::new(AtomicUsize::new(0))
    });
    let origin = Origin {
        scene: path,
        text: text.as_bytes(),
        command: std::env::args_os().collect(),
        out,
    };
    let record = match RunRecord::start(out, &loaded.name, &origin) {
        Ok((record, notices)) => {
            for n in notices {
                errln!("{}: warning: {n}", path.display());
            }
            record
        }
        Err(e) => {
            errln!("{}: error: {e}", path.display());
            return ExitCode::FAILURE;
        }
    };
    outln!(
        "{} ({}): {}",
        loaded.name,
        loaded.kind,
        loaded.scene.describe()
    );
    // The scene file is never replaced by an output.
    let sink = Sink::directory(out, &loaded.name).protecting(path);
    let progress = Progress::new(quiet).with_interrupt(stop);
    let mut ctx = RunContext::new(sink, progress);
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
        Err(RunError::Interrupted) => {
            let sig = signal.load(Ordering::Relaxed);
            errln!(
                "{}: error: interrupted by {}; the outputs completed before are listed in the \
                 manifest",
                path.display(),
                signal_name(sig)
            );
            let code = u8::try_from(128 + sig).unwrap_or(1);
            (
                ExitCode::from(code),
                format!("interrupted: {}", signal_name(sig)),
            )
        }
        Err(e) => {
            errln!("{}: error: {e}", path.display());
            (ExitCode::FAILURE, format!("failed: {e}"))
        }
    };
    match record.finish(status, &ctx.sink().written()) {
        Ok(m) if !m.stale.is_empty() => {
            let names: Vec<String> = m.stale.iter().map(|p| p.display().to_string()).collect();
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
