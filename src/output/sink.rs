//! Where a run's outputs go: a [`Sink`] is a directory or memory, named
//! after the scene, and is the only way a scene writes a table, a figure
//! or any other file (through its run context, `scene::RunContext`).
//!
//! - **Directory**: each file is written whole or not at all
//!   ([`super::atomic`]), named by [`super::names`], refused if it would
//!   replace a protected path (the scene file a run was started from), and
//!   recorded in the order it was completed ([`Sink::written`]).
//! - **Memory**: nothing touches the file system. Tables are checked row by
//!   row exactly as for a file (a non-finite value is refused naming column
//!   and row) and kept column by column ([`Keep::Tables`]) or dropped
//!   ([`Keep::Nothing`]); a figure is checked (an empty panel is refused as
//!   when drawing) but not drawn; other files are dropped.
//!
//! ```
//! use pegdyn::output::memory::{Column, Keep};
//! use pegdyn::output::sink::Sink;
//! use pegdyn::scene::{self, Progress, RunContext};
//!
//! let text = "kind = \"pendulum\"\n[pendulum]\nlength = 1.0\nmass = 1.0\ntheta0_deg = 30.0\n\
//!             [integrator]\nmethod = \"dopri5\"\nt_end = 0.5\noutput_interval = 0.25\n";
//! let loaded = scene::parse_named(text, "swing").unwrap();
//! let mut ctx = RunContext::new(Sink::memory(&loaded.name, Keep::Tables), Progress::silent());
//! let summary = loaded.run(&mut ctx).unwrap();
//! assert!(summary.outputs.is_empty()); // no file was written
//! let tables = ctx.into_sink().into_tables();
//! assert_eq!(tables[0].stem(), "swing");
//! assert_eq!(tables[0].header[0], "t_s");
//! assert_eq!(tables[0].columns[0], Column::Numbers(vec![0.0, 0.25, 0.5]));
//! ```

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};

use super::atomic;
use super::csv::{CsvWriter, RowCheck};
use super::memory::{Keep, KeptFile, Table, TableBuilder};
use super::names::Part;
use super::plot::Figure;
use crate::error::OutputError;

#[derive(Debug)]
enum Target {
    Directory(PathBuf),
    Memory(Keep),
}

/// What a run has written so far.
#[derive(Debug, Default)]
struct Record {
    /// Files completed in a directory, in order.
    written: Vec<PathBuf>,
    /// Tables kept in memory, in the order they were finished.
    tables: Vec<Table>,
    /// Other files kept in memory, in the order they were written.
    files: Vec<KeptFile>,
}

type Shared = Arc<Mutex<Record>>;

fn lock(record: &Shared) -> std::sync::MutexGuard<'_, Record> {
    record.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The outputs of one run of one scene: a directory or memory.
#[derive(Debug)]
pub struct Sink {
    target: Target,
    scene: String,
    protected: Vec<PathBuf>,
    record: Shared,
}

impl Sink {
    /// Files in `dir` (which must exist), named after `scene`.
    pub fn directory(dir: impl Into<PathBuf>, scene: &str) -> Self {
        Self::new(Target::Directory(dir.into()), scene)
    }

    /// No file: tables kept or dropped as `keep` says.
    pub fn memory(scene: &str, keep: Keep) -> Self {
        Self::new(Target::Memory(keep), scene)
    }

    fn new(target: Target, scene: &str) -> Self {
        Sink {
            target,
            scene: scene.to_owned(),
            protected: Vec::new(),
            record: Shared::default(),
        }
    }

    /// The same sink, refusing to replace `path` (e.g. the scene file the
    /// run was started from) with [`OutputError::WouldOverwriteScene`].
    #[must_use]
    pub fn protecting(mut self, path: &Path) -> Self {
        self.protected.push(atomic::resolved(path));
        self
    }

    /// The scene's name, the stem of its output files.
    pub fn scene(&self) -> &str {
        &self.scene
    }

    /// Where the file of `part` with extension `ext` goes: its path in the
    /// directory, or its bare file name in memory.
    pub fn path(&self, part: Part, ext: &str) -> PathBuf {
        let name = part.file_name(&self.scene, ext);
        match &self.target {
            Target::Directory(dir) => dir.join(name),
            Target::Memory(_) => PathBuf::from(name),
        }
    }

    fn allowed(&self, path: &Path) -> Result<(), OutputError> {
        if self.protected.contains(&atomic::resolved(path)) {
            return Err(OutputError::WouldOverwriteScene {
                path: path.to_path_buf(),
            });
        }
        Ok(())
    }

    fn wrote(&self, path: PathBuf) {
        lock(&self.record).written.push(path);
    }

    /// Starts the CSV table of `part` (`.csv`) with `header`; column names
    /// carry their unit, e.g. `theta_rad`, `t_s`.
    ///
    /// # Errors
    /// A protected path, or the file cannot be created.
    pub fn table(&self, part: Part, header: &[&str]) -> Result<TableWriter, OutputError> {
        let path = self.path(part, "csv");
        let out = match &self.target {
            Target::Directory(_) => {
                self.allowed(&path)?;
                TableOut::File(CsvWriter::create(&path, header)?)
            }
            Target::Memory(keep) => {
                let check = RowCheck::new(path.clone(), header);
                let table = (*keep == Keep::Tables).then(|| {
                    TableBuilder::new(path.to_string_lossy().into_owned(), check.header())
                });
                TableOut::Memory { check, table }
            }
        };
        Ok(TableWriter {
            out,
            record: Arc::clone(&self.record),
        })
    }

    /// Draws `fig` into the SVG file of `part` (in memory: checks that it
    /// can be drawn).
    ///
    /// # Errors
    /// A panel without a drawable point, a drawing or I/O error, or a
    /// protected path.
    pub fn figure(&self, part: Part, fig: &Figure) -> Result<(), OutputError> {
        let path = self.path(part, "svg");
        match &self.target {
            Target::Directory(_) => {
                self.allowed(&path)?;
                let svg = fig.render_for(&path)?;
                atomic::write(&path, svg.as_bytes())?;
                self.wrote(path);
                Ok(())
            }
            Target::Memory(_) => fig.check_drawable(&path),
        }
    }

    /// Writes `bytes` as the file of `part` with extension `ext` (e.g. an
    /// HTML page); in memory, keeps them with [`Keep::Tables`]
    /// ([`Sink::take_files`]) and drops them with [`Keep::Nothing`].
    ///
    /// # Errors
    /// An I/O error or a protected path.
    pub fn file(&self, part: Part, ext: &str, bytes: &[u8]) -> Result<(), OutputError> {
        let path = self.path(part, ext);
        match &self.target {
            Target::Directory(_) => {
                self.allowed(&path)?;
                atomic::write(&path, bytes)?;
                self.wrote(path);
                Ok(())
            }
            Target::Memory(Keep::Tables) => {
                lock(&self.record).files.push(KeptFile {
                    file: path.to_string_lossy().into_owned(),
                    bytes: bytes.to_vec(),
                });
                Ok(())
            }
            Target::Memory(Keep::Nothing) => Ok(()),
        }
    }

    /// Whether a file handed to [`Sink::file`] is kept (written to the
    /// directory, or kept in memory): false for [`Keep::Nothing`], so that
    /// a run can skip making a file nobody will see.
    pub fn keeps_files(&self) -> bool {
        !matches!(self.target, Target::Memory(Keep::Nothing))
    }

    /// The files other than tables kept in memory so far, in the order
    /// they were written, taken out of the sink (none in a directory or
    /// with [`Keep::Nothing`]).
    pub fn take_files(&self) -> Vec<KeptFile> {
        std::mem::take(&mut lock(&self.record).files)
    }

    /// The files completed so far, in the order they were completed (none
    /// in memory).
    pub fn written(&self) -> Vec<PathBuf> {
        lock(&self.record).written.clone()
    }

    /// The tables kept in memory, in the order they were finished (none in
    /// a directory or with [`Keep::Nothing`]).
    pub fn into_tables(self) -> Vec<Table> {
        std::mem::take(&mut lock(&self.record).tables)
    }
}

#[derive(Debug)]
enum TableOut {
    File(CsvWriter),
    Memory {
        check: RowCheck,
        table: Option<TableBuilder>,
    },
}

/// A CSV table being written through a [`Sink`]: to a file under a
/// temporary name that [`TableWriter::finish`] renames into place, or to
/// memory. A table that is not finished (an error, a non-finite value)
/// never appears.
///
/// Every value must be finite: a NaN or infinity is refused with
/// [`OutputError::NonFinite`] naming the column and row, so that no CSV of
/// NaN is ever left behind.
#[derive(Debug)]
pub struct TableWriter {
    out: TableOut,
    record: Shared,
}

impl TableWriter {
    /// Lets column `name` hold ±infinity where the table means it (e.g. "no
    /// finite angle exists"); NaN stays refused.
    pub fn allow_infinite(&mut self, name: &str) {
        match &mut self.out {
            TableOut::File(w) => w.allow_infinite(name),
            TableOut::Memory { check, .. } => check.allow_infinite(name),
        }
    }

    /// Appends one row; it must have as many values as the header.
    ///
    /// # Errors
    /// A wrong width, a refused non-finite value, or an I/O error.
    pub fn row(&mut self, values: &[f64]) -> Result<(), OutputError> {
        match &mut self.out {
            TableOut::File(w) => w.row(values),
            TableOut::Memory { check, table } => {
                check.numbers(values)?;
                if let Some(t) = table {
                    t.numbers(values);
                }
                Ok(())
            }
        }
    }

    /// Appends one row of pre-formatted cells, e.g. a label column beside
    /// numbers formatted with [`super::csv::format_f64`]. Same width rule
    /// as [`TableWriter::row`]; cells must not contain commas or newlines.
    ///
    /// # Errors
    /// As [`TableWriter::row`].
    pub fn row_cells(&mut self, cells: &[&str]) -> Result<(), OutputError> {
        match &mut self.out {
            TableOut::File(w) => w.row_cells(cells),
            TableOut::Memory { check, table } => {
                check.cells(cells)?;
                if let Some(t) = table {
                    t.text(cells);
                }
                Ok(())
            }
        }
    }

    /// Number of data rows written so far.
    pub fn rows(&self) -> usize {
        match &self.out {
            TableOut::File(w) => w.rows(),
            TableOut::Memory { check, .. } => check.rows(),
        }
    }

    /// Completes the table: renames the file into place, or hands the
    /// table to memory; records it with the sink.
    ///
    /// # Errors
    /// An I/O error.
    pub fn finish(self) -> Result<(), OutputError> {
        match self.out {
            TableOut::File(w) => {
                let path = w.finish()?;
                lock(&self.record).written.push(path);
            }
            TableOut::Memory { table, .. } => {
                if let Some(t) = table {
                    lock(&self.record).tables.push(t.finish());
                }
            }
        }
        Ok(())
    }
}
