//! The run manifest `<out>/<scene>.run.toml`: which run produced the files
//! of a scene in an output directory, and how it ended. It is written
//! before the run replaces any output (`status = "running"`) and again
//! when the run ends ([`super::record::RunRecord`]):
//!
//! ```toml
//! # pegdyn run manifest: the run that wrote the files listed below
//! pegdyn_manifest = 1
//! scene = "scenes/pendulum.toml"
//! scene_hash = "fnv1a64:9c1f0e2d7a4b3c5e"
//! pegdyn_version = "0.1.0"
//! command = "pegdyn run scenes/pendulum.toml --out out"
//! out = "out"
//! lossy = []
//! pid = 4242
//! started = "2026-11-26T01:02:03Z"
//! status = "ok"
//! ended = "2026-11-26T01:02:04Z"
//! files = ["pendulum.csv", "pendulum.svg"]
//! stale = []
//! ```
//!
//! - `scene_hash`: of the text that was parsed (read once, before the run).
//! - `lossy`: which of `scene`, `command`, `out` held bytes that are not
//!   UTF-8 (shown here with U+FFFD in their place).
//! - `status`: `running` (with `pid` and `started`), then `ok`,
//!   `partial: <why>` (an integration stopped early), `failed: <error>`
//!   or `interrupted: <signal>`; a `running` manifest whose process is
//!   gone is a run that was killed.
//! - `files`: what this run wrote (its sink's record,
//!   [`super::sink::Sink::written`]); `stale`: files named like this
//!   scene's outputs ([`super::names::of_scene`]) that this run did not
//!   write — an earlier run's, not to be read as this run's.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::names;

/// The format number written as `pegdyn_manifest`.
pub const FORMAT: i64 = 1;

/// The FNV-1a 64-bit hash of `bytes`, as 16 hex digits (identifies a scene
/// file's exact text; not a cryptographic hash).
pub fn fnv1a64(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in bytes {
        h ^= u64::from(*b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// What a manifest records.
#[derive(Debug, Clone, PartialEq)]
pub struct Manifest {
    /// The scene file as given (lossy if not UTF-8, see `lossy`).
    pub scene: String,
    /// `fnv1a64:<hex>` of the scene text that was parsed.
    pub scene_hash: String,
    /// The command line (arguments joined by spaces).
    pub command: String,
    /// The output directory as given.
    pub out: String,
    /// Which of `scene`, `command`, `out` were not UTF-8.
    pub lossy: Vec<&'static str>,
    /// The process that ran.
    pub pid: u32,
    /// When the run started (RFC 3339, UTC).
    pub started: String,
    /// `running`, `ok`, `partial: ...`, `failed: ...`, `interrupted: ...`.
    pub status: String,
    /// When the run ended (absent while running).
    pub ended: Option<String>,
    /// Files this run wrote (file names, sorted).
    pub files: Vec<PathBuf>,
    /// Files of this scene's name this run did not write.
    pub stale: Vec<PathBuf>,
}

fn quoted(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The file names of `paths` as a TOML array, sorted, each once.
fn list(paths: &[PathBuf]) -> String {
    let mut names: Vec<String> = paths
        .iter()
        .map(|p| {
            p.file_name()
                .map_or_else(|| p.to_string_lossy(), |f| f.to_string_lossy())
                .into_owned()
        })
        .collect();
    names.sort();
    names.dedup();
    let items: Vec<String> = names.iter().map(|n| quoted(n)).collect();
    format!("[{}]", items.join(", "))
}

impl Manifest {
    /// The manifest's TOML text.
    pub fn to_toml(&self) -> String {
        let lossy: Vec<String> = self.lossy.iter().map(|f| quoted(f)).collect();
        let mut text = format!(
            "# pegdyn run manifest: the run that wrote the files listed below\n\
             pegdyn_manifest = {FORMAT}\nscene = {}\nscene_hash = {}\npegdyn_version = {}\n\
             command = {}\nout = {}\nlossy = [{}]\npid = {}\nstarted = {}\nstatus = {}\n",
            quoted(&self.scene),
            quoted(&self.scene_hash),
            quoted(env!("CARGO_PKG_VERSION")),
            quoted(&self.command),
            quoted(&self.out),
            lossy.join(", "),
            self.pid,
            quoted(&self.started),
            quoted(&self.status),
        );
        if let Some(ended) = &self.ended {
            let _ = writeln!(text, "ended = {}", quoted(ended));
        }
        let _ = write!(
            text,
            "files = {}\nstale = {}\n",
            list(&self.files),
            list(&self.stale)
        );
        text
    }
}

/// What an existing file with a manifest's name holds.
#[derive(Debug, Clone, PartialEq)]
pub enum Existing {
    /// No such file.
    None,
    /// A pegdyn manifest; `running` with the process id when its run had
    /// not ended when it was written.
    Manifest {
        /// `Some((pid, started))` for `status = "running"`.
        running: Option<(u32, String)>,
    },
    /// Something else (a user's file, a directory, unreadable): never
    /// replaced.
    Foreign,
}

/// Reads `path` and says whether it is a pegdyn manifest: a TOML table with
/// `pegdyn_manifest`, or, as written before that key existed, with
/// `pegdyn_version`, `scene_hash` and `status`.
pub fn existing(path: &Path) -> Existing {
    let meta = match std::fs::symlink_metadata(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Existing::None,
        Err(_) => return Existing::Foreign,
        Ok(m) => m,
    };
    // A manifest is small; anything large or not a plain file is not one.
    if !meta.is_file() || meta.len() > 1 << 22 {
        return Existing::Foreign;
    }
    let Ok(text) = std::fs::read_to_string(path) else {
        return Existing::Foreign;
    };
    let Ok(t) = text.parse::<toml::Table>() else {
        return Existing::Foreign;
    };
    let str_of = |k: &str| t.get(k).and_then(toml::Value::as_str);
    let ours = t
        .get("pegdyn_manifest")
        .is_some_and(toml::Value::is_integer)
        || (str_of("pegdyn_version").is_some()
            && str_of("scene_hash").is_some()
            && str_of("status").is_some());
    if !ours {
        return Existing::Foreign;
    }
    let pid = t
        .get("pid")
        .and_then(toml::Value::as_integer)
        .and_then(|p| u32::try_from(p).ok());
    let running = match (str_of("status"), pid) {
        (Some("running"), Some(pid)) => Some((pid, str_of("started").unwrap_or("").to_owned())),
        _ => None,
    };
    Existing::Manifest { running }
}

/// Files in `dir` named like outputs of scene `name`
/// ([`names::of_scene`]), other than its manifest, that are not in
/// `written`, sorted.
pub fn stale_files(dir: &Path, name: &str, written: &[PathBuf]) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let written: Vec<_> = written.iter().filter_map(|p| p.file_name()).collect();
    let manifest = names::manifest(name);
    let mut stale: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.file_name().is_some_and(|f| {
                let f_s = f.to_string_lossy();
                names::of_scene(name, &f_s) && f_s != manifest && !written.contains(&f)
            })
        })
        .collect();
    stale.sort();
    stale
}
