//! A run's record in its output directory, kept true from start to end:
//! [`RunRecord::start`] looks at what an earlier run left (a manifest that
//! is not pegdyn's is never replaced; a `running` manifest whose process is
//! gone is reported; temporary files of processes that are gone are
//! reported and removed), then writes the manifest with
//! `status = "running"`, the process id and the start time — before the run
//! replaces any output. [`RunRecord::finish`] writes how the run ended and
//! the files it wrote ([`super::manifest`] describes the format).

use std::ffi::OsString;
use std::fmt;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use super::manifest::{self, Existing, Manifest};
use super::{atomic, names};
use crate::error::OutputError;

/// Where a run came from, as the operating system gave it (paths and
/// arguments need not be UTF-8).
#[derive(Debug, Clone)]
pub struct Origin<'a> {
    /// The scene file as given.
    pub scene: &'a Path,
    /// The scene text that was parsed (hashed into the manifest).
    pub text: &'a [u8],
    /// The command line.
    pub command: Vec<OsString>,
    /// The output directory as given.
    pub out: &'a Path,
}

/// Something an earlier run left that [`RunRecord::start`] found.
#[derive(Debug, Clone, PartialEq)]
pub enum Notice {
    /// A manifest said `running` and its process is gone: that run was
    /// killed before it could record its end.
    EarlierRunDied {
        /// The dead run's process id.
        pid: u32,
        /// When it started.
        started: String,
    },
    /// A manifest says `running` and its process is alive: another run of
    /// this scene writes into the same directory now.
    OtherRunRunning {
        /// Its process id.
        pid: u32,
        /// When it started.
        started: String,
    },
    /// A temporary file of a process that is gone, removed.
    RemovedTemporary(PathBuf),
}

impl fmt::Display for Notice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Notice::EarlierRunDied { pid, started } => write!(
                f,
                "an earlier run (process {pid}, started {started}) did not finish: its manifest \
                 still said \"running\" and the process is gone; its record is replaced"
            ),
            Notice::OtherRunRunning { pid, started } => write!(
                f,
                "another run of this scene (process {pid}, started {started}) is writing into the \
                 same directory; the manifest will record whichever run ends last"
            ),
            Notice::RemovedTemporary(p) => write!(
                f,
                "removed {}, a partial file left by a run that was killed",
                p.display()
            ),
        }
    }
}

/// The record of one run in progress.
#[derive(Debug)]
pub struct RunRecord {
    dir: PathBuf,
    name: String,
    manifest: Manifest,
}

/// The text of `s` and whether it lost bytes that are not UTF-8.
fn lossy(s: &std::ffi::OsStr) -> (String, bool) {
    match s.to_str() {
        Some(t) => (t.to_owned(), false),
        None => (s.to_string_lossy().into_owned(), true),
    }
}

/// Whether process `pid` is alive: `Some(false)` when it is gone (or a
/// zombie), `None` where this cannot be told (no `/proc`).
pub fn process_alive(pid: u32) -> Option<bool> {
    if pid == std::process::id() {
        return Some(true);
    }
    if !Path::new("/proc/self").exists() {
        return None;
    }
    match std::fs::read_to_string(format!("/proc/{pid}/stat")) {
        // The state follows the command name in parentheses.
        Ok(stat) => Some(
            stat.rsplit_once(')')
                .and_then(|(_, rest)| rest.trim_start().chars().next())
                .is_none_or(|state| state != 'Z' && state != 'X'),
        ),
        Err(_) => Some(false),
    }
}

/// `t` as RFC 3339 UTC to the second, e.g. `2026-11-26T01:02:03Z`.
pub fn utc(t: SystemTime) -> String {
    let secs = t.duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, rem) = (secs / 86_400, secs % 86_400);
    // Civil date from days since 1970-01-01 (H. Hinnant's algorithm).
    let z = days as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z",
        rem / 3600,
        (rem % 3600) / 60,
        rem % 60
    )
}

/// Temporary files of scene `name` in `dir` whose process is gone.
fn orphans(dir: &Path, name: &str) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut found: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .filter(|e| {
            names::temporary_of(name, &e.file_name().to_string_lossy())
                .is_some_and(|pid| process_alive(pid) == Some(false))
        })
        .map(|e| e.path())
        .collect();
    found.sort();
    found
}

impl RunRecord {
    /// Starts the record of a run of scene `name` into `dir` (which must
    /// exist): checks what earlier runs left, removes temporary files of
    /// processes that are gone, and writes the `running` manifest.
    ///
    /// # Errors
    /// [`OutputError::ForeignManifest`] if a file with the manifest's name
    /// is not a pegdyn manifest (nothing is written then);
    /// [`OutputError::Io`] if the manifest cannot be written.
    pub fn start(
        dir: &Path,
        name: &str,
        origin: &Origin<'_>,
    ) -> Result<(RunRecord, Vec<Notice>), OutputError> {
        let path = dir.join(names::manifest(name));
        let mut notices = Vec::new();
        match manifest::existing(&path) {
            Existing::Foreign => return Err(OutputError::ForeignManifest { path }),
            Existing::Manifest {
                running: Some((pid, started)),
            } => notices.push(match process_alive(pid) {
                Some(false) => Notice::EarlierRunDied { pid, started },
                _ => Notice::OtherRunRunning { pid, started },
            }),
            Existing::Manifest { running: None } | Existing::None => {}
        }
        for orphan in orphans(dir, name) {
            if std::fs::remove_file(&orphan).is_ok() {
                notices.push(Notice::RemovedTemporary(orphan));
            }
        }
        let (scene, scene_lossy) = lossy(origin.scene.as_os_str());
        let (out, out_lossy) = lossy(origin.out.as_os_str());
        let words: Vec<(String, bool)> = origin.command.iter().map(|a| lossy(a)).collect();
        let command = words
            .iter()
            .map(|(w, _)| w.as_str())
            .collect::<Vec<_>>()
            .join(" ");
        let mut marked = Vec::new();
        for (field, lost) in [
            ("scene", scene_lossy),
            ("command", words.iter().any(|(_, l)| *l)),
            ("out", out_lossy),
        ] {
            if lost {
                marked.push(field);
            }
        }
        let record = RunRecord {
            dir: dir.to_path_buf(),
            name: name.to_owned(),
            manifest: Manifest {
                scene,
                scene_hash: format!("fnv1a64:{}", manifest::fnv1a64(origin.text)),
                command,
                out,
                lossy: marked,
                pid: std::process::id(),
                started: utc(SystemTime::now()),
                status: "running".into(),
                ended: None,
                files: Vec::new(),
                stale: manifest::stale_files(dir, name, &[]),
            },
        };
        record.write()?;
        Ok((record, notices))
    }

    fn write(&self) -> Result<(), OutputError> {
        let path = self.dir.join(names::manifest(&self.name));
        atomic::write(&path, self.manifest.to_toml().as_bytes())
    }

    /// The manifest as last written.
    pub fn manifest(&self) -> &Manifest {
        &self.manifest
    }

    /// Records the end of the run: `status` (`ok`, `partial: ...`,
    /// `failed: ...`, `interrupted: ...`), the files it wrote, and the
    /// files of this scene's name it did not write (returned).
    ///
    /// # Errors
    /// [`OutputError::Io`] if the manifest cannot be written.
    pub fn finish(mut self, status: String, written: &[PathBuf]) -> Result<Manifest, OutputError> {
        self.manifest.status = status;
        self.manifest.ended = Some(utc(SystemTime::now()));
        self.manifest.files = written.to_vec();
        self.manifest.stale = manifest::stale_files(&self.dir, &self.name, written);
        self.write()?;
        Ok(self.manifest)
    }
}
