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
        module: String,
        function: String,
        symbol: String,
    },

    /// A symbol appears in two inputs of one function, or twice in one input.
    #[error("{module}::{function}: symbol `{symbol}` is bound twice")]
    SymbolBoundTwice {
        module: String,
        function: String,
        symbol: String,
    },

    /// An input name is used by two functions of one module with different
    /// symbols, so the module's `<INPUT>_NAMES` constant would be ambiguous.
    #[error("{module}: input `{input}` has different components in different functions")]
    InconsistentInput { module: String, input: String },

    /// A matrix declared symmetric is not: entries (row, col) and (col, row)
    /// are different expressions.
    #[error(
        "{module}::{function}: output `{output}` is declared symmetric but ({row}, {col}) != ({col}, {row})"
    )]
    NotSymmetric {
        module: String,
        function: String,
        output: String,
        row: usize,
        col: usize,
    },

    /// A matrix whose entry count is not rows × cols.
    #[error("{module}::{function}: output `{output}` is {rows}x{cols} but has {entries} entries")]
    Shape {
        module: String,
        function: String,
        output: String,
        rows: usize,
        cols: usize,
        entries: usize,
    },

    /// A constant that is infinite (NaN cannot be stored at all).
    #[error("{module}::{function}: non-finite constant {value} in output `{output}`")]
    NonFiniteConstant {
        module: String,
        function: String,
        output: String,
        value: f64,
    },

    /// A module, function, input or output name that is not a Rust
    /// identifier in snake_case, or a duplicate one.
    #[error("invalid or duplicate {what} name `{name}` (want a unique snake_case identifier)")]
    InvalidName { what: &'static str, name: String },

    /// A function with no outputs, or an input with no symbols.
    #[error("{module}::{function}: {reason}")]
    Empty {
        module: String,
        function: String,
        reason: &'static str,
    },

    /// The emitted tokens did not parse as a Rust file (a bug in the emitter).
    /// A typed input or output struct that cannot be emitted as declared.
    #[error("{module}: struct `{item}`: {reason}")]
    Struct {
        module: String,
        item: String,
        reason: String,
    },
    #[error("emitted code for module `{module}` does not parse: {message}")]
    Parse { module: String, message: String },

    /// A model given to [`crate::builder`] is incomplete or inconsistent:
    /// `symbol` names the coordinate, parameter or expression at fault.
    #[error("model `{model}`, {function}: `{symbol}`: {reason}")]
    Model {
        model: String,
        function: String,
        symbol: String,
        reason: String,
    },

    /// Reading or writing an output file failed.
    #[error("cannot write {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}
