//! Runs without files: a [`Capture`] stands for an output directory that
//! exists only in memory.
//!
//! A scene writes its outputs through [`super::csv::CsvWriter`],
//! [`super::plot::Figure::save`] and [`super::atomic::write`] into paths
//! under `RunContext::out_dir`. When that directory is a capture's
//! [`Capture::dir`], the CSV writer keeps the rows in memory (or drops
//! them) instead of creating a file, a figure is checked (an empty panel is
//! refused as when drawing) but not drawn, and `atomic::write` writes
//! nothing. Every scene kind that writes through these three therefore runs
//! in memory without knowing it, with the same checks as on disk: a
//! non-finite value is refused naming column and row, exactly as for a file.
//!
//! A captured number is the `f64` the scene computed; a file holds its
//! shortest round-trip decimal, which parses back to the same bits, so a
//! table read back from the file equals the captured one value for value.
//!
//! ```
//! use pegdyn::output::memory::{Capture, Column, Keep};
//! use pegdyn::scene::{self, Progress, RunContext};
//!
//! let text = "kind = \"pendulum\"\n[pendulum]\nlength = 1.0\nmass = 1.0\ntheta0_deg = 30.0\n\
//!             [integrator]\nmethod = \"dopri5\"\nt_end = 0.5\noutput_interval = 0.25\n";
//! let loaded = scene::parse_named(text, "swing").unwrap();
//! let capture = Capture::new(Keep::Tables);
//! let mut ctx = RunContext {
//!     out_dir: capture.dir().to_path_buf(),
//!     name: loaded.name.clone(),
//!     progress: Progress::silent(),
//! };
//! loaded.scene.run(&mut ctx).unwrap();
//! let tables = capture.into_tables();
//! assert_eq!(tables[0].stem(), "swing");
//! assert_eq!(tables[0].header[0], "t_s");
//! assert_eq!(tables[0].columns[0], Column::Numbers(vec![0.0, 0.25, 0.5]));
//! assert!(!capture_dir_exists(&ctx.out_dir));
//! # fn capture_dir_exists(p: &std::path::Path) -> bool { p.exists() }
//! ```

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

use super::csv::format_f64;

/// What a [`Capture`] keeps of the tables written into it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Keep {
    /// Every CSV table, column by column.
    Tables,
    /// Nothing: rows are checked as for a file and dropped (a sweep that
    /// wants only the run summaries).
    Nothing,
}

/// One column of a captured table: numbers when every cell is a number
/// (as a reader of the CSV file would type it), else text.
#[derive(Debug, Clone, PartialEq)]
pub enum Column {
    /// Every cell a number.
    Numbers(Vec<f64>),
    /// Some cell is not a number (e.g. a label column): every cell as the
    /// file would print it.
    Text(Vec<String>),
}

/// A table a run wrote into a [`Capture`].
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The path the file would have had (under [`Capture::dir`]).
    pub path: PathBuf,
    /// Column names, as in the file's header line.
    pub header: Vec<String>,
    /// The columns, in header order.
    pub columns: Vec<Column>,
}

impl Table {
    /// The file stem, e.g. `pendulum` for `<dir>/pendulum.csv`.
    pub fn stem(&self) -> String {
        self.path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    }
}

#[derive(Debug)]
struct Store {
    keep: Keep,
    tables: Mutex<Vec<Table>>,
}

type Registry = Mutex<HashMap<PathBuf, Arc<Store>>>;

fn registry() -> &'static Registry {
    static REGISTRY: OnceLock<Registry> = OnceLock::new();
    REGISTRY.get_or_init(Registry::default)
}

/// An output directory held in memory; registered while the value lives.
///
/// Its [`Capture::dir`] contains a NUL character, so it can never name a
/// directory on disk: a file operation on it fails rather than touching
/// the file system.
#[derive(Debug)]
pub struct Capture {
    dir: PathBuf,
    store: Arc<Store>,
}

impl Capture {
    /// A new, empty in-memory output directory.
    pub fn new(keep: Keep) -> Self {
        static NEXT: AtomicU64 = AtomicU64::new(0);
        let k = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = PathBuf::from(format!("\0pegdyn-memory-{}-{k}", std::process::id()));
        let store = Arc::new(Store {
            keep,
            tables: Mutex::new(Vec::new()),
        });
        registry()
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .insert(dir.clone(), Arc::clone(&store));
        Capture { dir, store }
    }

    /// The directory to give a run as `RunContext::out_dir`.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The tables written so far, in the order they were finished (none
    /// with [`Keep::Nothing`]); ends the capture.
    pub fn into_tables(self) -> Vec<Table> {
        std::mem::take(
            &mut *self
                .store
                .tables
                .lock()
                .unwrap_or_else(PoisonError::into_inner),
        )
    }
}

impl Drop for Capture {
    fn drop(&mut self) {
        registry()
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .remove(&self.dir);
    }
}

fn store_for(path: &Path) -> Option<Arc<Store>> {
    let dir = path.parent()?;
    registry()
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .get(dir)
        .cloned()
}

/// Whether `path` lies in a live [`Capture`] directory (a file there is
/// never written to disk).
pub fn is_memory(path: &Path) -> bool {
    store_for(path).is_some()
}

#[derive(Debug)]
enum Cell {
    Number(f64),
    Text(String),
}

/// The rows of one table bound for a [`Capture`] (the CSV writer's sink).
#[derive(Debug)]
pub(crate) struct TableSink {
    store: Arc<Store>,
    path: PathBuf,
    header: Vec<String>,
    cells: Vec<Vec<Cell>>,
}

impl TableSink {
    /// A sink for `path` when it lies in a capture directory.
    pub(crate) fn for_path(path: &Path, header: &[String]) -> Option<TableSink> {
        let store = store_for(path)?;
        Some(TableSink {
            store,
            path: path.to_path_buf(),
            header: header.to_vec(),
            cells: header.iter().map(|_| Vec::new()).collect(),
        })
    }

    fn keeps(&self) -> bool {
        self.store.keep == Keep::Tables
    }

    /// Appends a row of numbers (already checked by the writer).
    pub(crate) fn numbers(&mut self, values: &[f64]) {
        if self.keeps() {
            for (c, v) in self.cells.iter_mut().zip(values) {
                c.push(Cell::Number(*v));
            }
        }
    }

    /// Appends a row of pre-formatted cells (already checked by the writer).
    pub(crate) fn text(&mut self, cells: &[&str]) {
        if self.keeps() {
            for (c, v) in self.cells.iter_mut().zip(cells) {
                c.push(Cell::Text((*v).to_owned()));
            }
        }
    }

    /// Types the columns and hands the table to its capture.
    pub(crate) fn finish(self) {
        if !self.keeps() {
            return;
        }
        let columns = self.cells.into_iter().map(typed).collect();
        let table = Table {
            path: self.path,
            header: self.header,
            columns,
        };
        self.store
            .tables
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .push(table);
    }
}

/// A column typed as a reader of the file types it: numbers when every
/// printed cell parses as `f64`.
fn typed(cells: Vec<Cell>) -> Column {
    let number = |c: &Cell| match c {
        Cell::Number(v) => Some(*v),
        Cell::Text(s) => s.parse::<f64>().ok(),
    };
    match cells.iter().map(number).collect::<Option<Vec<f64>>>() {
        Some(v) => Column::Numbers(v),
        None => Column::Text(
            cells
                .into_iter()
                .map(|c| match c {
                    Cell::Number(v) => format_f64(v),
                    Cell::Text(s) => s,
                })
                .collect(),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::csv::CsvWriter;

    #[test]
    fn writer_into_a_capture_keeps_typed_columns_and_touches_no_disk() {
        let capture = Capture::new(Keep::Tables);
        let path = capture.dir().join("t.csv");
        let mut w = CsvWriter::create(&path, &["x", "label", "y"]).unwrap();
        w.row_cells(&["0.5", "a", "1e-12"]).unwrap();
        w.row_cells(&[&format_f64(1.0 / 3.0), "b", "-inf"])
            .unwrap_err();
        w.row_cells(&[&format_f64(1.0 / 3.0), "b", "2"]).unwrap();
        assert_eq!(w.finish().unwrap(), path);
        assert!(!path.exists());
        let t = capture.into_tables();
        assert_eq!(t.len(), 1);
        assert_eq!(t[0].header, ["x", "label", "y"]);
        assert_eq!(t[0].columns[0], Column::Numbers(vec![0.5, 1.0 / 3.0]));
        assert_eq!(t[0].columns[1], Column::Text(vec!["a".into(), "b".into()]));
        assert_eq!(t[0].columns[2], Column::Numbers(vec![1e-12, 2.0]));
    }

    #[test]
    fn non_finite_values_are_refused_as_for_a_file() {
        let capture = Capture::new(Keep::Nothing);
        let mut w = CsvWriter::create(&capture.dir().join("n.csv"), &["t_s", "x_m"]).unwrap();
        w.row(&[0.0, 1.0]).unwrap();
        let e = w.row(&[0.1, f64::NAN]).unwrap_err().to_string();
        assert!(e.contains("x_m") && e.contains("NaN"), "{e}");
        assert_eq!(w.rows(), 1);
        w.finish().unwrap();
        assert!(capture.into_tables().is_empty());
    }

    #[test]
    fn a_dropped_capture_is_no_longer_memory() {
        let capture = Capture::new(Keep::Tables);
        let path = capture.dir().join("a.csv");
        assert!(is_memory(&path));
        drop(capture);
        assert!(!is_memory(&path));
        assert!(!is_memory(Path::new("out/a.csv")));
    }
}
