//! The names of the files a run writes: the one place that names them.
//!
//! A run of the scene named `s` (the scene file's stem) writes
//!
//! ```text
//! s.<ext>              its main table (csv), figure (svg) or page     Part::Main
//! s.<part>.<ext>       further files, e.g. s.events.csv               Part::Sub("events")
//! s.run.toml           the run manifest                               manifest()
//! .s.<...>.tmp-<pid>   a file being written, renamed when complete    temporary()
//! ```
//!
//! Every name starts with the scene's name and a `.`, and a scene name
//! cannot contain a `.` ([`check_scene_name`]): the scene a file belongs to
//! is the part of its name before the first `.`, so that no two scenes'
//! files can have the same name (scene `a_events` writes `a_events.csv`,
//! scene `a` writes `a.events.csv`) and a manifest names only its own
//! scene's files ([`of_scene`]).
//!
//! ```
//! use pegdyn::output::names::{self, Part};
//! assert_eq!(Part::Main.file_name("drop_3d", "csv"), "drop_3d.csv");
//! assert_eq!(Part::Sub("events").file_name("drop_3d", "csv"), "drop_3d.events.csv");
//! assert_eq!(names::manifest("drop_3d"), "drop_3d.run.toml");
//! assert!(names::of_scene("drop_3d", "drop_3d.views.svg"));
//! assert!(!names::of_scene("insert", "insert_rcc.csv"));
//! assert!(names::check_scene_name("v1.2").is_err());
//! ```

use std::path::{Path, PathBuf};

/// What separates a scene's name from the rest of its files' names; a
/// scene name cannot contain it.
pub const SEPARATOR: char = '.';

/// The part name the manifest takes (`<scene>.run.toml`); no other file
/// may use it.
const MANIFEST_PART: &str = "run";

/// Which of a run's files.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// The scene's main file of its type: `<scene>.<ext>`.
    Main,
    /// A further file: `<scene>.<part>.<ext>`. `part` is not `run` (the
    /// manifest's) and contains no `.`.
    Sub(&'static str),
}

impl Part {
    /// The file name of this part of the run of scene `scene`.
    pub fn file_name(self, scene: &str, ext: &str) -> String {
        match self {
            Part::Main => format!("{scene}{SEPARATOR}{ext}"),
            Part::Sub(part) => {
                debug_assert!(part != MANIFEST_PART && !part.contains(SEPARATOR));
                format!("{scene}{SEPARATOR}{part}{SEPARATOR}{ext}")
            }
        }
    }
}

/// Why a scene name cannot name a run's files.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NameError {
    /// The name is empty.
    #[error("a scene name cannot be empty")]
    Empty,
    /// The name contains the separator of output names.
    #[error(
        "the scene name `{name}` contains `{SEPARATOR}`, which separates a scene's name from the \
         rest of its output files' names (`<name>.csv`, `<name>.events.csv`, `<name>.run.toml`); \
         rename the scene file (e.g. `{suggestion}.toml`)"
    )]
    Separator {
        /// The name as given.
        name: String,
        /// The name with every `.` replaced by `_`.
        suggestion: String,
    },
    /// The name contains a path separator or a control character.
    #[error("the scene name {name:?} contains `/`, `\\` or a control character")]
    Character {
        /// The name as given.
        name: String,
    },
}

/// Checks that `name` can name a run's files: not empty, no `.` (the
/// separator), no path separator, no control character.
///
/// # Errors
/// The first rule `name` breaks.
pub fn check_scene_name(name: &str) -> Result<(), NameError> {
    if name.is_empty() {
        return Err(NameError::Empty);
    }
    if name.contains(SEPARATOR) {
        return Err(NameError::Separator {
            name: name.to_owned(),
            suggestion: name.replace(SEPARATOR, "_"),
        });
    }
    if name
        .chars()
        .any(|c| c == '/' || c == '\\' || c.is_control())
    {
        return Err(NameError::Character {
            name: name.to_owned(),
        });
    }
    Ok(())
}

/// The run manifest's file name, `<scene>.run.toml`.
pub fn manifest(scene: &str) -> String {
    format!("{scene}{SEPARATOR}{MANIFEST_PART}{SEPARATOR}toml")
}

/// Whether `file` (a file name) is named like a file of scene `scene`:
/// `<scene>.*` (its outputs and its manifest).
pub fn of_scene(scene: &str, file: &str) -> bool {
    file.strip_prefix(scene)
        .is_some_and(|rest| rest.starts_with(SEPARATOR))
}

/// The temporary name `path` is written under before it is renamed into
/// place: `.<file name>.tmp-<pid>` in the same directory.
pub fn temporary(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}

/// If `file` (a file name) is a temporary file of scene `scene`
/// ([`temporary`] of one of its files), the id of the process that wrote
/// it.
pub fn temporary_of(scene: &str, file: &str) -> Option<u32> {
    let (final_name, pid) = file.strip_prefix('.')?.rsplit_once(".tmp-")?;
    if !of_scene(scene, final_name) || pid.is_empty() || !pid.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    pid.parse().ok()
}
