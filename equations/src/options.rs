//! Generation options, passed as values (no global or thread-local state).

/// Default name of the generated source file in the output directory.
pub const SOURCE_FILE: &str = "generated.rs";
/// Default name of the operation-count report in the output directory.
pub const REPORT_FILE: &str = "codegen_report.txt";

/// How [`crate::codegen::render`] generates code.
///
/// The defaults are what a crate that generates its own models needs: the
/// stable numerical forms on, and none of the extras (the registry, the
/// function list, pegdyn's test harness), which cost build time to
/// generate and compile.
///
/// ```
/// use pegdyn_equations::Options;
/// let o = Options::default();
/// assert!(o.stable_rewrites);
/// assert!(!o.registry && !o.function_list && !o.test_harness);
/// assert!(o.parameter_jacobians.is_empty());
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
    /// function, such as accuracy checks against double-double
    /// (`pegdyn::accuracy::measure_function`). Off by default.
    pub registry: bool,
    /// Also render the function-list macros (`generated_list.rs`,
    /// [`crate::codegen::registry::list`]) for code that must name every
    /// generated function statically (pegdyn's benches). Off by default.
    pub function_list: bool,
    /// Also render pegdyn's test harness: the emitter-coverage model and
    /// its call table (`generated_calls.rs`, [`crate::codegen::harness`]).
    /// Off by default; only pegdyn's own build turns it on.
    pub test_harness: bool,
    /// The models (by module name) whose parameter Jacobians `∂f/∂p` are
    /// generated beside their functions: `rhs_p` of an explicit model's
    /// `rhs`, `parameter_terms` of a Lagrangian model, and `<function>_p`
    /// of every function its declaration marks with
    /// [`ModelBuilder::parameter_jacobian`](crate::ModelBuilder::parameter_jacobian)
    /// or [`ModelBuilder::solution_parameter_jacobian`](crate::ModelBuilder::solution_parameter_jacobian).
    /// Empty by default: they cost generation and compile time, so a build
    /// names only the models whose sensitivities it integrates. A name that
    /// is not a declared model is refused by [`crate::Generator::render`].
    pub parameter_jacobians: Vec<String>,
    /// File name of the generated source in the output directory.
    pub source_file: String,
    /// File name of the operation-count report in the output directory.
    pub report_file: String,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            stable_rewrites: true,
            registry: false,
            function_list: false,
            test_harness: false,
            parameter_jacobians: Vec::new(),
            source_file: SOURCE_FILE.to_owned(),
            report_file: REPORT_FILE.to_owned(),
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
