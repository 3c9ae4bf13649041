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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_of_two_scenes_never_coincide() {
        // Pairs of scene names that collided with `_` as the separator.
        let pairs = [("a", "a_events"), ("insert", "insert_rcc"), ("x", "x_run")];
        let parts = [Part::Main, Part::Sub("events"), Part::Sub("views")];
        for (a, b) in pairs {
            for pa in parts {
                for pb in parts {
                    for ext in ["csv", "svg", "toml"] {
                        assert_ne!(pa.file_name(a, ext), pb.file_name(b, ext));
                    }
                }
                assert!(!of_scene(a, &pa.file_name(b, "csv")), "{a} {b} {pa:?}");
                assert!(!of_scene(b, &pa.file_name(a, "csv")), "{a} {b} {pa:?}");
                assert_ne!(pa.file_name(a, "toml"), manifest(b));
            }
            assert_ne!(manifest(a), manifest(b));
        }
        assert_eq!(Part::Sub("events").file_name("a", "csv"), "a.events.csv");
        assert_eq!(Part::Main.file_name("a_events", "csv"), "a_events.csv");
    }

    #[test]
    fn scene_names_with_the_separator_are_refused_with_a_suggestion() {
        for ok in ["pendulum", "a_events", "Übung 3", "x-run", "a\u{fffd}b"] {
            assert_eq!(check_scene_name(ok), Ok(()), "{ok}");
        }
        let e = check_scene_name("x.run").unwrap_err();
        assert!(e.to_string().contains("`x_run.toml`"), "{e}");
        for bad in ["", ".hidden", "v1.2", "a/b", "a\\b", "a\nb", "a\0b"] {
            assert!(check_scene_name(bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn temporary_files_are_recognized_with_their_process() {
        let tmp = temporary(Path::new("out/drop_3d.csv"));
        let file = tmp.file_name().unwrap().to_str().unwrap();
        assert_eq!(temporary_of("drop_3d", file), Some(std::process::id()));
        assert_eq!(temporary_of("drop", file), None);
        assert_eq!(temporary_of("a", ".a.csv.tmp-12"), Some(12));
        assert_eq!(temporary_of("a", ".a.csv.tmp-"), None);
        assert_eq!(temporary_of("a", ".a.csv.tmp-1x"), None);
        assert_eq!(temporary_of("a", "a.csv"), None);
        assert_eq!(temporary_of("a", ".a_b.csv.tmp-3"), None);
    }
}
