//! What a running scene gets from its caller.

use crate::error::OutputError;
use crate::output::names::Part;
use crate::output::plot::Figure;
use crate::output::sink::{Sink, TableWriter};
use crate::scene::progress::Progress;

/// What a running scene gets from the caller: the sink its outputs go to
/// (a directory or memory; the only way a scene writes a file), a
/// progress reporter, and whether replay pages are wanted.
#[derive(Debug)]
pub struct RunContext {
    sink: Sink,
    /// Progress reporter.
    pub progress: Progress,
    replay: bool,
}

impl RunContext {
    /// A context writing into `sink`; replay pages are made when the sink
    /// keeps files ([`Sink::keeps_files`]: not for a sweep's runs).
    pub fn new(sink: Sink, progress: Progress) -> Self {
        let replay = sink.keeps_files();
        RunContext {
            sink,
            progress,
            replay,
        }
    }

    /// The same context making no replay page (`pegdyn run --no-replay`),
    /// whatever the scene's `[replay]` table says.
    #[must_use]
    pub fn without_replay(mut self) -> Self {
        self.replay = false;
        self
    }

    /// Whether the caller wants replay pages: a kind that makes one writes
    /// it when this and its scene's `replay.page` are true.
    pub fn replay_wanted(&self) -> bool {
        self.replay
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
