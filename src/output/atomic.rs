//! Output files appear whole or not at all: each file is written under a
//! temporary name in its directory and renamed into place when complete
//! (a rename within one directory is atomic on POSIX file systems). A file
//! that fails half-way leaves no trace under its final name.
//!
//! The module also keeps, per process, the list of files committed (for the
//! run manifest, [`super::manifest`]) and the paths that must never be
//! overwritten (the scene file a run was started from).

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use crate::error::OutputError;

static WRITTEN: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());
static PROTECTED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The temporary name `path` is written under: `.<file name>.tmp-<pid>` in
/// the same directory.
pub fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}

/// The absolute form of `path` with its directory resolved (the file itself
/// need not exist).
fn resolved(path: &Path) -> PathBuf {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty());
    let dir = dir.map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    let dir = dir.canonicalize().unwrap_or(dir);
    match path.file_name() {
        Some(n) => dir.join(n),
        None => dir,
    }
}

/// Forbids this process to write `path` (e.g. the scene file of a run).
pub fn protect(path: &Path) {
    if let Ok(mut p) = PROTECTED.lock() {
        p.push(resolved(path));
    }
}

/// Whether `path` is protected by [`protect`].
pub fn is_protected(path: &Path) -> bool {
    let target = resolved(path);
    PROTECTED.lock().is_ok_and(|p| p.contains(&target))
}

/// Renames the complete temporary file `tmp` to `path` and records `path`
/// as written.
///
/// # Errors
/// [`OutputError::WouldOverwriteScene`] for a protected `path` (the
/// temporary file is removed); [`OutputError::Io`] if the rename fails.
pub fn commit(tmp: &Path, path: &Path) -> Result<(), OutputError> {
    if is_protected(path) {
        // Best effort: the temporary copy is garbage either way.
        let _ = std::fs::remove_file(tmp);
        return Err(OutputError::WouldOverwriteScene {
            path: path.to_path_buf(),
        });
    }
    std::fs::rename(tmp, path).map_err(|source| OutputError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    if let Ok(mut w) = WRITTEN.lock() {
        w.push(resolved(path));
    }
    Ok(())
}

/// Writes `bytes` to `path` atomically (temporary file, then rename); a
/// path in a [`super::memory::Capture`] directory writes nothing.
///
/// # Errors
/// As [`commit`], and [`OutputError::Io`] if the temporary file cannot be
/// written.
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    if super::memory::is_memory(path) {
        return Ok(());
    }
    let tmp = temp_path(path);
    if let Err(source) = std::fs::write(&tmp, bytes) {
        let _ = std::fs::remove_file(&tmp);
        return Err(OutputError::Io {
            path: path.to_path_buf(),
            source,
        });
    }
    commit(&tmp, path)
}

/// The files committed so far by this process that lie in `dir` (resolved).
pub fn written_in(dir: &Path) -> Vec<PathBuf> {
    let dir = dir.canonicalize().unwrap_or_else(|_| dir.to_path_buf());
    let mut out: Vec<PathBuf> = WRITTEN
        .lock()
        .map(|w| {
            w.iter()
                .filter(|p| p.parent() == Some(&dir))
                .cloned()
                .collect()
        })
        .unwrap_or_default();
    out.sort();
    out.dedup();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn write_replaces_whole_and_refuses_protected_paths() {
        let dir = std::env::temp_dir().join(format!("pegdyn-atomic-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("a.csv");
        write(&path, b"one").unwrap();
        write(&path, b"two").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "two");
        assert!(!temp_path(&path).exists());
        assert!(written_in(&dir).iter().any(|p| p.ends_with("a.csv")));
        let scene = dir.join("scene.svg");
        std::fs::write(&scene, "kind = 1").unwrap();
        protect(&scene);
        let e = write(&scene, b"<svg/>").unwrap_err();
        assert!(matches!(e, OutputError::WouldOverwriteScene { .. }), "{e}");
        assert_eq!(std::fs::read_to_string(&scene).unwrap(), "kind = 1");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
