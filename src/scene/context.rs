//! What a running scene gets from its caller.

use crate::error::OutputError;
use crate::output::names::Part;
use crate::output::plot::Figure;
use crate::output::sink::{Sink, TableWriter};
use crate::scene::progress::Progress;

/// What a running scene gets from the caller: the sink its outputs go to
/// (a directory or memory; the only way a scene writes a file) and a
/// progress reporter.
#[derive(Debug)]
pub struct RunContext {
    sink: Sink,
    /// Progress reporter.
    pub progress: Progress,
}

impl RunContext {
    /// A context writing into `sink`.
    pub fn new(sink: Sink, progress: Progress) -> Self {
        RunContext { sink, progress }
    }

    /// The scene's name (file stem), the stem of every output file.
    pub fn name(&self) -> &str {
        self.sink.scene()
    }

    /// Starts the CSV table of `part` ([`Sink::table`]), e.g.
    /// `ctx.table(Part::Main, &["t_s", "x_m"])` for `<name>.csv`.
    ///
    /// # Errors
    /// The file cannot be created, or would replace the scene file.
    pub fn table(&self, part: Part, header: &[&str]) -> Result<TableWriter, OutputError> {
        self.sink.table(part, header)
    }

    /// Draws `fig` as the SVG file of `part` ([`Sink::figure`]).
    ///
    /// # Errors
    /// A panel without a drawable point, or the file cannot be written.
    pub fn figure(&self, part: Part, fig: &Figure) -> Result<(), OutputError> {
        self.sink.figure(part, fig)
    }

    /// Writes `bytes` as the file of `part` with extension `ext`
    /// ([`Sink::file`]).
    ///
    /// # Errors
    /// The file cannot be written, or would replace the scene file.
    pub fn file(&self, part: Part, ext: &str, bytes: &[u8]) -> Result<(), OutputError> {
        self.sink.file(part, ext, bytes)
    }

    /// The sink: what the run has written so far ([`Sink::written`]).
    pub fn sink(&self) -> &Sink {
        &self.sink
    }

    /// Ends the run's context, handing back its sink (e.g. for the tables
    /// kept in memory, [`Sink::into_tables`]).
    pub fn into_sink(self) -> Sink {
        self.sink
    }
}
