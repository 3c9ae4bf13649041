//! A small CSV writer for numeric tables: one header line, then rows of
//! `f64`, each printed in the shortest form that parses back to the same
//! bits (Rust's `Display`/`LowerExp` for `f64` are shortest-round-trip).
//!
//! ```
//! use pegdyn::output::csv::{CsvWriter, format_f64};
//! let dir = std::env::temp_dir().join(format!("pegdyn-csv-doc-{}", std::process::id()));
//! std::fs::create_dir_all(&dir).unwrap();
//! let path = dir.join("t.csv");
//! let mut w = CsvWriter::create(&path, &["t_s", "x_m"]).unwrap();
//! w.row(&[0.1, 1.0 / 3.0]).unwrap();
//! w.finish().unwrap();
//! let text = std::fs::read_to_string(&path).unwrap();
//! let x: f64 = text.lines().nth(1).unwrap().split(',').nth(1).unwrap().parse().unwrap();
//! assert_eq!(x, 1.0 / 3.0);
//! assert_eq!(format_f64(1e-12), "1e-12");
//! # std::fs::remove_dir_all(&dir).unwrap();
//! ```

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use super::{atomic, names};
use crate::error::OutputError;

/// Formats `v` so that `v.to_string().parse::<f64>() == v` bit for bit:
/// plain decimal for `1e-4 <= |v| < 1e15` (and zero), scientific otherwise.
/// NaN and infinities print as `NaN`, `inf`, `-inf`.
pub fn format_f64(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || !v.is_finite() || (1e-4..1e15).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// The rules every row of a table obeys, wherever the table goes (a file
/// or memory): as many cells as the header, and no NaN, nor ±infinity
/// outside the columns that allow it. Errors name the table by `path`.
#[derive(Debug)]
pub(crate) struct RowCheck {
    path: PathBuf,
    header: Vec<String>,
    infinite_ok: Vec<bool>,
    rows: usize,
}

impl RowCheck {
    /// Rules for a table with `header`, named `path` in errors; every
    /// column refuses ±infinity.
    pub(crate) fn new(path: PathBuf, header: &[&str]) -> Self {
        RowCheck {
            path,
            header: header.iter().map(|h| (*h).to_owned()).collect(),
            infinite_ok: vec![false; header.len()],
            rows: 0,
        }
    }

    /// The column names.
    pub(crate) fn header(&self) -> &[String] {
        &self.header
    }

    /// See [`CsvWriter::allow_infinite`].
    pub(crate) fn allow_infinite(&mut self, name: &str) {
        for (ok, h) in self.infinite_ok.iter_mut().zip(&self.header) {
            *ok |= h == name;
        }
    }

    fn width(&self, got: usize) -> Result<(), OutputError> {
        if got == self.header.len() {
            Ok(())
        } else {
            Err(OutputError::RowWidth {
                path: self.path.clone(),
                row: self.rows,
                got,
                expected: self.header.len(),
            })
        }
    }

    /// Checks a row of numbers and counts it.
    pub(crate) fn numbers(&mut self, values: &[f64]) -> Result<(), OutputError> {
        self.width(values.len())?;
        let bad = |(i, v): (usize, &f64)| {
            v.is_nan() || (v.is_infinite() && !self.infinite_ok.get(i).copied().unwrap_or(false))
        };
        if let Some(i) = values.iter().enumerate().position(bad) {
            return Err(self.non_finite(i, &format_f64(values[i]), &format_f64(values[0])));
        }
        self.rows += 1;
        Ok(())
    }

    /// Checks a row of pre-formatted cells and counts it.
    pub(crate) fn cells(&mut self, cells: &[&str]) -> Result<(), OutputError> {
        self.width(cells.len())?;
        let bad = |(i, c): (usize, &&str)| {
            let c = c.trim_start_matches(['-', '+']).to_ascii_lowercase();
            let infinite = c == "inf" || c == "infinity";
            c == "nan" || (infinite && !self.infinite_ok.get(i).copied().unwrap_or(false))
        };
        if let Some(i) = cells.iter().enumerate().position(bad) {
            return Err(self.non_finite(i, cells[i], cells[0]));
        }
        self.rows += 1;
        Ok(())
    }

    fn non_finite(&self, column: usize, value: &str, first: &str) -> OutputError {
        OutputError::NonFinite {
            path: self.path.clone(),
            column: self.header.get(column).cloned().unwrap_or_default(),
            value: value.to_owned(),
            row: self.rows,
            first: first.to_owned(),
        }
    }

    /// Data rows accepted so far.
    pub(crate) fn rows(&self) -> usize {
        self.rows
    }
}

/// Writes a CSV file row by row, under a temporary name that
/// [`CsvWriter::finish`] renames into place ([`super::atomic`]): a file that
/// is not finished (an error, a non-finite value) never appears.
///
/// Every value must be finite: a NaN or infinity is refused with
/// [`OutputError::NonFinite`] naming the column and row, so that no CSV of
/// NaN is ever left behind.
///
/// A scene writes its tables through its run context
/// ([`super::sink::Sink::table`]), which uses this writer for a directory.
#[derive(Debug)]
pub struct CsvWriter {
    path: PathBuf,
    tmp: PathBuf,
    out: BufWriter<File>,
    check: RowCheck,
    line: String,
    done: bool,
}

impl Drop for CsvWriter {
    fn drop(&mut self) {
        if !self.done {
            // Best effort: an unfinished temporary file is garbage.
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

impl CsvWriter {
    /// Creates (truncates) `path` and writes the header. Column names should
    /// carry their unit, e.g. `theta_rad`, `t_s`.
    pub fn create(path: &Path, header: &[&str]) -> Result<Self, OutputError> {
        let io = |source| OutputError::Io {
            path: path.to_path_buf(),
            source,
        };
        let tmp = names::temporary(path);
        let file = File::create(&tmp).map_err(io)?;
        let mut w = CsvWriter {
            path: path.to_path_buf(),
            tmp,
            out: BufWriter::new(file),
            check: RowCheck::new(path.to_path_buf(), header),
            line: String::new(),
            done: false,
        };
        writeln!(w.out, "{}", w.check.header().join(",")).map_err(io)?;
        Ok(w)
    }

    /// Lets column `name` hold ±infinity where the table means it (e.g. "no
    /// finite angle exists"); NaN stays refused.
    pub fn allow_infinite(&mut self, name: &str) {
        self.check.allow_infinite(name);
    }

    /// Appends one row; it must have as many values as the header.
    pub fn row(&mut self, values: &[f64]) -> Result<(), OutputError> {
        self.check.numbers(values)?;
        self.line.clear();
        for (i, v) in values.iter().enumerate() {
            if i > 0 {
                self.line.push(',');
            }
            self.line.push_str(&format_f64(*v));
        }
        self.line.push('\n');
        self.write_line()
    }

    /// Appends one row of pre-formatted cells, e.g. a label column beside
    /// numbers formatted with [`format_f64`]. Same width rule as
    /// [`CsvWriter::row`]; cells must not contain commas or newlines.
    pub fn row_cells(&mut self, cells: &[&str]) -> Result<(), OutputError> {
        self.check.cells(cells)?;
        self.line.clear();
        self.line.push_str(&cells.join(","));
        self.line.push('\n');
        self.write_line()
    }

    fn write_line(&mut self) -> Result<(), OutputError> {
        self.out
            .write_all(self.line.as_bytes())
            .map_err(|source| OutputError::Io {
                path: self.path.clone(),
                source,
            })
    }

    /// Number of data rows written so far.
    pub fn rows(&self) -> usize {
        self.check.rows()
    }

    /// Flushes the file and renames it into place; returns its path.
    pub fn finish(mut self) -> Result<PathBuf, OutputError> {
        self.out.flush().map_err(|source| OutputError::Io {
            path: self.path.clone(),
            source,
        })?;
        self.done = true;
        atomic::commit(&self.tmp, &self.path)?;
        Ok(self.path.clone())
    }
}
