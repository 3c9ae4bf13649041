//! The run manifest `<out>/<scene>.run.toml`: what produced the files in an
//! output directory, and whether it succeeded.
//!
//! ```toml
//! scene = "scenes/pendulum.toml"
//! scene_hash = "fnv1a64:9c1f0e2d7a4b3c5e"
//! pegdyn_version = "0.1.0"
//! command = "pegdyn run scenes/pendulum.toml --out out"
//! status = "ok"
//! files = ["pendulum.csv", "pendulum.svg"]
//! stale = []
//! ```
//!
//! `files` lists what this run wrote (its sink's record,
//! [`super::sink::Sink::written`]); `stale` lists files of the same scene
//! name ([`super::names::of_scene`]) in the directory that this run did not
//! write — left by an earlier run, and not to be read as this run's.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::{atomic, names};
use crate::error::OutputError;

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
#[derive(Debug, Clone)]
pub struct Manifest<'a> {
    /// The scene file as given on the command line.
    pub scene: &'a Path,
    /// The scene file's text.
    pub scene_text: &'a [u8],
    /// The command line.
    pub command: String,
    /// `ok`, or `failed: <reason>`.
    pub status: String,
    /// Files this run wrote (absolute or relative to the output
    /// directory; listed by file name, sorted).
    pub files: Vec<PathBuf>,
}

/// Files in `dir` named like outputs of scene `name`
/// ([`names::of_scene`]), other than its manifest, that are not in
/// `written`, sorted.
pub fn stale_files(dir: &Path, name: &str, written: &[PathBuf]) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let names: Vec<_> = written.iter().filter_map(|p| p.file_name()).collect();
    let manifest = names::manifest(name);
    let mut stale: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.file_name().is_some_and(|f| {
                let f_s = f.to_string_lossy();
                names::of_scene(name, &f_s) && f_s != manifest && !names.contains(&f)
            })
        })
        .collect();
    stale.sort();
    stale
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

/// Writes `<dir>/<name>.run.toml` atomically; returns its path and the
/// stale files it lists.
///
/// # Errors
/// [`OutputError::Io`] if the file cannot be written.
pub fn write(
    dir: &Path,
    name: &str,
    m: &Manifest<'_>,
) -> Result<(PathBuf, Vec<PathBuf>), OutputError> {
    let stale = stale_files(dir, name, &m.files);
    let text = format!(
        "scene = {}\nscene_hash = {}\npegdyn_version = {}\ncommand = {}\nstatus = {}\nfiles = {}\nstale = {}\n",
        quoted(&m.scene.to_string_lossy()),
        quoted(&format!("fnv1a64:{}", fnv1a64(m.scene_text))),
        quoted(env!("CARGO_PKG_VERSION")),
        quoted(&m.command),
        quoted(&m.status),
        list(&m.files),
        list(&stale),
    );
    let path = dir.join(names::manifest(name));
    atomic::write(&path, text.as_bytes())?;
    Ok((path, stale))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn manifest_lists_files_and_stale_outputs() {
        let dir = std::env::temp_dir().join(format!("pegdyn-manifest-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("s.csv"), "t\n").unwrap();
        std::fs::write(dir.join("s_old.svg"), "").unwrap();
        std::fs::write(dir.join("other.csv"), "").unwrap();
        let m = Manifest {
            scene: Path::new("scenes/s.toml"),
            scene_text: b"kind = \"pendulum\"",
            command: "pegdyn run \"scenes/s.toml\"".into(),
            status: "ok".into(),
            files: vec![dir.join("s.csv")],
        };
        let (path, stale) = write(&dir, "s", &m).unwrap();
        assert_eq!(stale, vec![dir.join("s_old.svg")]);
        let text = std::fs::read_to_string(&path).unwrap();
        let parsed: toml::Table = text.parse().unwrap();
        assert_eq!(parsed["status"].as_str(), Some("ok"));
        assert_eq!(parsed["files"].as_array().map(Vec::len), Some(1));
        assert_eq!(parsed["stale"][0].as_str(), Some("s_old.svg"));
        assert_eq!(
            parsed["command"].as_str(),
            Some("pegdyn run \"scenes/s.toml\"")
        );
        assert_eq!(fnv1a64(b""), "cbf29ce484222325");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
