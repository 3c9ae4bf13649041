//! The names of the files a run writes: the one place that names them.
//!
//! A run of the scene named `s` (the scene file's stem) writes
//!
//! ```text
//! s.<ext>            its main table (csv) and figure (svg)         Part::Main
//! s_<part>.<ext>     further files, e.g. s_events.csv              Part::Sub("events")
//! <stem>.<ext>       a name the kind fixes whatever the scene's    Part::Fixed("wedging")
//!                    name (the jamming kind's tables)
//! s.run.toml         the run manifest                              manifest()
//! .<file>.tmp-<pid>  a file being written, renamed when complete  temporary()
//! ```
//!
//! ```
//! use pegdyn::output::names::{self, Part};
//! assert_eq!(Part::Main.file_name("drop_3d", "csv"), "drop_3d.csv");
//! assert_eq!(Part::Sub("events").file_name("drop_3d", "csv"), "drop_3d_events.csv");
//! assert_eq!(Part::Fixed("wedging").file_name("any", "csv"), "wedging.csv");
//! assert_eq!(names::manifest("drop_3d"), "drop_3d.run.toml");
//! assert!(names::of_scene("drop_3d", "drop_3d_views.svg"));
//! ```

use std::path::{Path, PathBuf};

/// Which of a run's files.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// The scene's main file of its type: `<scene>.<ext>`.
    Main,
    /// A further file: `<scene>_<part>.<ext>`.
    Sub(&'static str),
    /// A name the kind fixes whatever the scene is called: `<stem>.<ext>`.
    /// Two scenes of that kind in one directory write the same file.
    Fixed(&'static str),
}

impl Part {
    /// The file name of this part of the run of scene `scene`.
    pub fn file_name(self, scene: &str, ext: &str) -> String {
        match self {
            Part::Main => format!("{scene}.{ext}"),
            Part::Sub(part) => format!("{scene}_{part}.{ext}"),
            Part::Fixed(stem) => format!("{stem}.{ext}"),
        }
    }
}

/// The run manifest's file name, `<scene>.run.toml`.
pub fn manifest(scene: &str) -> String {
    format!("{scene}.run.toml")
}

/// Whether `file` (a file name) is named like an output of scene `scene`:
/// `<scene>.*` or `<scene>_*`.
pub fn of_scene(scene: &str, file: &str) -> bool {
    file.strip_prefix(scene)
        .is_some_and(|rest| rest.starts_with('.') || rest.starts_with('_'))
}

/// The temporary name `path` is written under before it is renamed into
/// place: `.<file name>.tmp-<pid>` in the same directory.
pub fn temporary(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}
