//! Error types of the runtime crate that reach the user: scene loading and
//! validation ([`SceneError`], [`SceneErrors`]), output writing
//! ([`OutputError`]) and running a scene ([`RunError`]).
//!
//! Every scene error names the offending field by its dotted path (for
//! example `pendulum.length`) and, where there is one, the offending value.

use std::fmt;
use std::path::PathBuf;

/// One problem with a scene file.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The scene file.
        path: PathBuf,
        /// The underlying I/O error.
        source: std::io::Error,
    },
    /// The file is not valid TOML.
    #[error("TOML syntax error: {message}")]
    Syntax {
        /// The parser's description of the problem.
        message: String,
    },
    /// A required field is absent.
    #[error("missing field `{}`", shown(field))]
    Missing {
        /// Dotted path of the missing field, e.g. `pendulum.length`.
        field: String,
    },
    /// A field that this scene kind does not know (often a typo).
    #[error("unknown field `{}`; {expected}", shown(field))]
    Unknown {
        /// Dotted path of the unknown field.
        field: String,
        /// Which fields are allowed there.
        expected: String,
    },
    /// A field holds a value of the wrong TOML type.
    #[error(
        "`{}` has the wrong type: found {}, expected {expected}",
        shown(field),
        shown(found)
    )]
    WrongType {
        /// Dotted path of the field.
        field: String,
        /// The value found, with its TOML type, e.g. `string "heavy"`.
        found: String,
        /// The type expected.
        expected: String,
    },
    /// A field holds a value of the right type that is not acceptable
    /// (NaN, negative mass, `t_end <= t0`, an unknown method name, ...).
    #[error("`{}` = {}: {reason}", shown(field), shown(value))]
    Invalid {
        /// Dotted path of the field.
        field: String,
        /// The offending value as written (Rust formatting of the parsed value).
        value: String,
        /// Why it is rejected.
        reason: String,
    },
    /// The scene's name (its file's stem) cannot name its output files.
    #[error(transparent)]
    Name(#[from] crate::output::names::NameError),
    /// The `kind` field names no registered scene kind.
    #[error(
        "`kind` = {}: unknown scene kind; known kinds: {known}",
        shown(&format!("{value:?}"))
    )]
    UnknownKind {
        /// The kind as written.
        value: String,
        /// Comma-separated list of the registered kinds.
        known: String,
    },
}

impl SceneError {
    /// Shorthand for [`SceneError::Invalid`].
    pub fn invalid(
        field: impl Into<String>,
        value: impl fmt::Debug,
        reason: impl Into<String>,
    ) -> Self {
        SceneError::Invalid {
            field: field.into(),
            value: format!("{value:?}"),
            reason: reason.into(),
        }
    }

    /// Dotted path of the field this error is about, if any.
    pub fn field(&self) -> Option<&str> {
        match self {
            SceneError::Io { .. } | SceneError::Syntax { .. } | SceneError::Name(_) => None,
            SceneError::Missing { field }
            | SceneError::Unknown { field, .. }
            | SceneError::WrongType { field, .. }
            | SceneError::Invalid { field, .. } => Some(field),
            SceneError::UnknownKind { .. } => Some("kind"),
        }
    }
}

/// Longest text of the scene file an error message repeats whole (a key,
/// a value): longer text is cut, so that a megabyte key is not echoed to
/// the terminal.
pub const SHOWN_CHARS: usize = 80;

/// `text` as an error message shows it: whole up to [`SHOWN_CHARS`]
/// characters, else its first 60 characters and how long it is.
///
/// ```
/// use pegdyn::error::shown;
/// assert_eq!(shown("pendulum.length"), "pendulum.length");
/// let long = "x".repeat(10_000_000);
/// let s = shown(&long);
/// assert!(s.len() < 100 && s.ends_with("… (10000000 bytes)"), "{s}");
/// ```
pub fn shown(text: &str) -> std::borrow::Cow<'_, str> {
    if text.chars().nth(SHOWN_CHARS).is_none() {
        return text.into();
    }
    let head: String = text.chars().take(60).collect();
    format!("{head}… ({} bytes)", text.len()).into()
}

/// A position in a scene file, 1-based.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Location {
    /// Line number, starting at 1.
    pub line: usize,
    /// Column number in characters, starting at 1.
    pub column: usize,
}

/// A [`SceneError`] with the place in the file it refers to, when known.
#[derive(Debug)]
pub struct Located {
    /// The error.
    pub error: SceneError,
    /// Where in the file, when the field could be found there.
    pub at: Option<Location>,
}

/// All problems found in one scene file (at least one).
#[derive(Debug)]
pub struct SceneErrors {
    /// The problems, in the order they were found.
    pub errors: Vec<Located>,
}

impl SceneErrors {
    /// Errors without locations.
    pub fn new(errors: impl IntoIterator<Item = SceneError>) -> Self {
        SceneErrors {
            errors: errors
                .into_iter()
                .map(|error| Located { error, at: None })
                .collect(),
        }
    }
}

impl From<SceneError> for SceneErrors {
    fn from(error: SceneError) -> Self {
        SceneErrors::new([error])
    }
}

impl fmt::Display for SceneErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, e) in self.errors.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            if let Some(at) = e.at {
                write!(f, "line {}, column {}: ", at.line, at.column)?;
            }
            write!(f, "{}", e.error)?;
        }
        Ok(())
    }
}

impl std::error::Error for SceneErrors {}

/// Failure to write an output file.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// Creating or writing a file failed.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The output file.
        path: PathBuf,
        /// The underlying I/O error.
        source: std::io::Error,
    },
    /// A CSV row has a different number of columns than the header.
    #[error("{path}: row {row} has {got} columns, header has {expected}")]
    RowWidth {
        /// The output file.
        path: PathBuf,
        /// 0-based data row index.
        row: usize,
        /// Columns in the row.
        got: usize,
        /// Columns in the header.
        expected: usize,
    },
    /// The plotting library reported an error.
    #[error("cannot draw {path}: {message}")]
    Plot {
        /// The output file.
        path: PathBuf,
        /// The plotting library's message.
        message: String,
    },
    /// A value to be written is NaN or infinite: the run went non-finite.
    /// The file is not written (its partial temporary copy is removed).
    #[error(
        "{path}: column `{column}` is {value} in data row {row} (first column = {first}); \
         the model left the finite range there — likely an extreme scene value \
         (a rate, load, modulus or scale of zero or of many decades); nothing was written to this file"
    )]
    NonFinite {
        /// The output file.
        path: PathBuf,
        /// The first non-finite column's name.
        column: String,
        /// Its value (`NaN`, `inf`, `-inf`).
        value: String,
        /// 0-based data row index.
        row: usize,
        /// The row's first column (time or the swept variable), as written.
        first: String,
    },
    /// The output would replace the scene file the run was started from.
    #[error(
        "refusing to write {path}: it is the scene file itself; choose another --out directory"
    )]
    WouldOverwriteScene {
        /// The output file (the scene file).
        path: PathBuf,
    },
    /// A file with the run manifest's name exists and is not a pegdyn run
    /// manifest (a user's own file): it is never replaced.
    #[error(
        "refusing to run: {path} exists and is not a pegdyn run manifest, and a run of this scene \
         would replace it with its own; move that file or choose another --out directory"
    )]
    ForeignManifest {
        /// The file with the manifest's name.
        path: PathBuf,
    },
    /// A plot has no finite data point to scale its axes by.
    #[error("cannot draw {path}: panel {panel:?} has no finite data point")]
    EmptyPlot {
        /// The output file.
        path: PathBuf,
        /// Title of the panel.
        panel: String,
    },
}

/// Failure while running a scene.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// Writing the CSV or SVG failed.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// The jamming analysis refused a parameter (cannot happen after the
    /// scene's `check`; reported rather than unwrapped).
    #[error("jamming analysis refused {0}")]
    Jamming(#[from] crate::jamming::ParamError),
    /// The rigid three-point peg model has no physical answer at a state.
    #[error("rigid peg: {0}")]
    Rigid(#[from] crate::rigid_peg::RigidError),
    /// The integrator rejected its input.
    #[error(transparent)]
    Integrate(#[from] crate::integrate::IntegrateError),
    /// The forward-sensitivity run refused its model or input.
    #[error("sensitivities: {0}")]
    Sensitivity(#[from] crate::sensitivity::SensitivityError),
    /// A Hertz contact of the compliant 3-D peg could not be set up at a
    /// state (relative curvature not positive).
    #[error("Hertz contact: {0}")]
    Hertz(#[from] crate::hertz::HertzError),
    /// The contact law refused a state during a run, with the time and
    /// the scene fields that set the refused quantity.
    #[error("Hertz contact refused at t = {t} s: {source}; {fields}")]
    HertzAt {
        /// Time of the run's last state, s.
        t: f64,
        /// The scene fields that set the law, with their values and what
        /// to change, in words.
        fields: String,
        /// The law's refusal.
        source: crate::hertz::HertzError,
    },
    /// The run's replay page could not be made (a run without samples, a
    /// non-finite number in the record, a state the model refuses).
    #[error("replay page: {0}")]
    Replay(#[from] crate::replay::ReplayError),
    /// A stop was requested (a signal, Ctrl-C) before the run finished.
    #[error("interrupted before the run finished")]
    Interrupted,
    /// A scene field that could only be checked against the model it
    /// runs (a state component's name).
    #[error(transparent)]
    Field(#[from] SceneError),
    /// Memory for a result whose size the scene sets could not be
    /// reserved (the limits were raised past what the machine has).
    #[error(transparent)]
    Memory(#[from] crate::scene::reserve::ReserveError),
}

impl From<crate::rigid_peg::trajectory::ForwardError> for RunError {
    /// Each variant to its namesake (the rigid error keeps its
    /// `rigid peg:` prefix).
    fn from(e: crate::rigid_peg::trajectory::ForwardError) -> RunError {
        use crate::rigid_peg::trajectory::ForwardError;
        match e {
            ForwardError::Integrate(e) => RunError::Integrate(e),
            ForwardError::Rigid(e) => RunError::Rigid(e),
        }
    }
}
