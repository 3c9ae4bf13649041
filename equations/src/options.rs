//! Generation options, passed as values (no global or thread-local state).

/// How [`crate::builder::Generator`] generates code.
///
/// ```
/// use pegdyn_equations::Options;
/// let o = Options::default();
/// assert!(o.stable_rewrites);
/// let naive = Options { stable_rewrites: false, ..Options::default() };
/// assert!(!naive.stable_rewrites);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Apply the simplifier's stable numerical forms (the rows of
    /// [`crate::simplify::rules::RULES`] with `stable: true`): rewrites that
    /// keep the value and remove a cancellation, overflow or NaN from the
    /// floating-point evaluation. On by default; off only to measure what
    /// they buy.
    pub stable_rewrites: bool,
    /// Emit `pub mod registry` after the models: a table of every generated
    /// function with callers on slices at `f64` and at double-double
    /// (`pegdyn::generated::Function` rows), for tools that evaluate every
    /// function, such as accuracy checks against the interpreter.
    pub registry: bool,
    /// File name of the generated source in the output directory.
    pub source_file: String,
    /// File name of the operation-count report in the output directory.
    pub report_file: String,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            stable_rewrites: true,
            registry: true,
            source_file: crate::codegen::SOURCE_FILE.to_owned(),
            report_file: crate::codegen::REPORT_FILE.to_owned(),
        }
    }
}

/// The environment variable that switches the stable rewrites off in
/// [`Options::from_env`] when set to `1`.
pub const NAIVE_FORMS_ENV: &str = "PEGDYN_NAIVE_FORMS";

impl Options {
    /// The defaults, with [`Options::stable_rewrites`] off when the
    /// environment variable `PEGDYN_NAIVE_FORMS` is `1` (a build script
    /// should then print `cargo:rerun-if-env-changed=PEGDYN_NAIVE_FORMS`).
    pub fn from_env() -> Options {
        let naive = std::env::var_os(NAIVE_FORMS_ENV).is_some_and(|v| v == "1");
        Options {
            stable_rewrites: !naive,
            ..Options::default()
        }
    }

    /// A fresh expression arena that applies these options.
    pub fn graph(&self) -> crate::Graph {
        crate::Graph::with_stable_rewrites(self.stable_rewrites)
    }
}
