//! Output files appear whole or not at all: each file is written under a
//! temporary name in its directory ([`super::names::temporary`]) and
//! renamed into place when complete (a rename within one directory is
//! atomic on POSIX file systems). A file that fails half-way leaves no
//! trace under its final name.
//!
//! These are plain file operations: which files a run may write, and the
//! record of what it wrote, belong to its [`super::sink::Sink`].

use std::path::{Path, PathBuf};

use super::names;
use crate::error::OutputError;

/// The absolute form of `path` with its directory resolved (the file itself
/// need not exist), to compare two spellings of one path.
pub fn resolved(path: &Path) -> PathBuf {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty());
    let dir = dir.map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    let dir = dir.canonicalize().unwrap_or(dir);
    match path.file_name() {
        Some(n) => dir.join(n),
        None => dir,
    }
}

/// Renames the complete temporary file `tmp` to `path`.
///
/// # Errors
/// [`OutputError::Io`] if the rename fails (the temporary file is removed).
pub fn commit(tmp: &Path, path: &Path) -> Result<(), OutputError> {
    std::fs::rename(tmp, path).map_err(|source| {
        // Best effort: the temporary copy is garbage either way.
        let _ = std::fs::remove_file(tmp);
        OutputError::Io {
            path: path.to_path_buf(),
            source,
        }
    })
}

/// Writes `bytes` to `path` atomically (temporary file, then rename).
///
/// # Errors
/// [`OutputError::Io`] if the temporary file cannot be written or renamed.
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    let tmp = names::temporary(path);
    if let Err(source) = std::fs::write(&tmp, bytes) {
        let _ = std::fs::remove_file(&tmp);
        return Err(OutputError::Io {
            path: path.to_path_buf(),
            source,
        });
    }
    commit(&tmp, path)
}
