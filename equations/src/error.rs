//! Errors of the generator: a model that fails verification, or an output
//! file that cannot be written. Every variant names the module and function
//! (or path) it is about, so that `build.rs` can print one precise line.

use std::path::PathBuf;

/// Why generation failed.
#[derive(Debug, thiserror::Error)]
pub enum GenError {
    /// An output uses a symbol that no input of the function binds.
    #[error("{module}::{function}: symbol `{symbol}` is used but bound by no input")]
    UnboundSymbol {
        /// The module (model) name.
        module: String,
        /// The function name.
        function: String,
        /// The symbol name.
        symbol: String,
    },

    /// A symbol appears in two inputs of one function, or twice in one input.
    #[error("{module}::{function}: symbol `{symbol}` is bound twice")]
    SymbolBoundTwice {
        /// The module (model) name.
        module: String,
        /// The function name.
        function: String,
        /// The symbol name.
        symbol: String,
    },

    /// An input name is used by two functions of one module with different
    /// symbols, so the module's `<INPUT>_NAMES` constant would be ambiguous.
    #[error("{module}: input `{input}` has different components in different functions")]
    InconsistentInput {
        /// The module name.
        module: String,
        /// The input name.
        input: String,
    },

    /// A matrix declared symmetric is not: entries (row, col) and (col, row)
    /// are different expressions.
    #[error(
        "{module}::{function}: output `{output}` is declared symmetric but ({row}, {col}) != ({col}, {row})"
    )]
    NotSymmetric {
        /// The module (model) name.
        module: String,
        /// The function name.
        function: String,
        /// The output name.
        output: String,
        /// The row of the first differing entry.
        row: usize,
        /// Its column.
        col: usize,
    },

    /// A matrix whose entry count is not rows × cols.
    #[error("{module}::{function}: output `{output}` is {rows}x{cols} but has {entries} entries")]
    Shape {
        /// The module (model) name.
        module: String,
        /// The function name.
        function: String,
        /// The output name.
        output: String,
        /// Rows declared.
        rows: usize,
        /// Columns declared.
        cols: usize,
        /// Entries given.
        entries: usize,
    },

    /// A constant that is infinite (NaN cannot be stored at all).
    #[error("{module}::{function}: non-finite constant {value} in output `{output}`")]
    NonFiniteConstant {
        /// The module (model) name.
        module: String,
        /// The function name.
        function: String,
        /// The output name.
        output: String,
        /// The constant.
        value: f64,
    },

    /// A module, function, input or output name that is not a Rust
    /// identifier in snake_case, or a duplicate one.
    #[error("invalid or duplicate {what} name `{name}` (want a unique snake_case identifier)")]
    InvalidName {
        /// What the name names: `module`, `function`, `input` or `output`.
        what: &'static str,
        /// The name.
        name: String,
    },

    /// A function with no outputs, or an input with no symbols.
    #[error("{module}::{function}: {reason}")]
    Empty {
        /// The module (model) name.
        module: String,
        /// The function name.
        function: String,
        /// What is missing.
        reason: &'static str,
    },

    /// A typed input or output struct that cannot be emitted as declared.
    #[error("{module}: struct `{item}`: {reason}")]
    Struct {
        /// The module (model) name.
        module: String,
        /// The struct name.
        item: String,
        /// What is wrong.
        reason: String,
    },
    /// The emitted tokens did not parse as a Rust file (a bug in the emitter).
    #[error("emitted code for module `{module}` does not parse: {message}")]
    Parse {
        /// The module name.
        module: String,
        /// The parser's message.
        message: String,
    },

    /// A model given to [`crate::builder`] is incomplete or inconsistent:
    /// `symbol` names the coordinate, parameter or expression at fault.
    #[error("model `{model}`, {function}: `{symbol}`: {reason}")]
    Model {
        /// The model name.
        model: String,
        /// The function, or the declaration step (`declaration`,
        /// `lagrange`, `explicit`, `typed_input`, ...).
        function: String,
        /// The symbol name.
        symbol: String,
        /// What is wrong.
        reason: String,
    },

    /// Reading or writing an output file failed.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
}
