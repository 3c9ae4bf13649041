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

use super::memory::TableSink;
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

/// Writes a CSV file row by row, under a temporary name that
/// [`CsvWriter::finish`] renames into place ([`super::atomic`]): a file that
/// is not finished (an error, a non-finite value) never appears.
///
/// Every value must be finite: a NaN or infinity is refused with
/// [`OutputError::NonFinite`] naming the column and row, so that no CSV of
/// NaN is ever left behind.
///
/// A path in a [`super::memory::Capture`] directory is never created: the
/// rows (checked the same way) go to the capture instead.
#[derive(Debug)]
pub struct CsvWriter {
    path: PathBuf,
    tmp: PathBuf,
    out: Sink,
    header: Vec<String>,
    columns: usize,
    rows: usize,
    line: String,
    done: bool,
    infinite_ok: Vec<bool>,
}

/// Where the rows go: a file, or a table held in memory.
#[derive(Debug)]
enum Sink {
    File(BufWriter<File>),
    Memory(Option<TableSink>),
}

impl Drop for CsvWriter {
    fn drop(&mut self) {
        if !self.done && matches!(self.out, Sink::File(_)) {
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
        let header: Vec<String> = header.iter().map(|h| (*h).to_owned()).collect();
        if let Some(sink) = TableSink::for_path(path, &header) {
            return Ok(Self::with_sink(
                path,
                path.to_path_buf(),
                Sink::Memory(Some(sink)),
                header,
            ));
        }
        if super::atomic::is_protected(path) {
            return Err(OutputError::WouldOverwriteScene {
                path: path.to_path_buf(),
            });
        }
        let tmp = super::atomic::temp_path(path);
        let file = File::create(&tmp).map_err(io)?;
        let mut w = Self::with_sink(path, tmp, Sink::File(BufWriter::new(file)), header);
        if let Sink::File(out) = &mut w.out {
            writeln!(out, "{}", w.header.join(",")).map_err(io)?;
        }
        Ok(w)
    }

    /// A writer with no row yet: every column refuses ±infinity.
    fn with_sink(path: &Path, tmp: std::path::PathBuf, out: Sink, header: Vec<String>) -> Self {
        CsvWriter {
            path: path.to_path_buf(),
            tmp,
            out,
            columns: header.len(),
            infinite_ok: vec![false; header.len()],
            header,
            rows: 0,
            line: String::new(),
            done: false,
        }
    }

    /// Lets column `name` hold ±infinity where the table means it (e.g. "no
    /// finite angle exists"); NaN stays refused.
    pub fn allow_infinite(&mut self, name: &str) {
        for (ok, h) in self.infinite_ok.iter_mut().zip(&self.header) {
            *ok |= h == name;
        }
    }

    /// Appends one row; it must have as many values as the header.
    pub fn row(&mut self, values: &[f64]) -> Result<(), OutputError> {
        if values.len() != self.columns {
            return Err(OutputError::RowWidth {
                path: self.path.clone(),
                row: self.rows,
                got: values.len(),
                expected: self.columns,
            });
        }
        let bad = |(i, v): (usize, &f64)| {
            v.is_nan() || (v.is_infinite() && !self.infinite_ok.get(i).copied().unwrap_or(false))
        };
        if let Some(i) = values.iter().enumerate().position(bad) {
            return Err(self.non_finite(i, &format_f64(values[i]), &format_f64(values[0])));
        }
        if let Sink::Memory(Some(m)) = &mut self.out {
            m.numbers(values);
            self.rows += 1;
            return Ok(());
        }
        self.line.clear();
        for (i, v) in values.iter().enumerate() {
            if i > 0 {
                self.line.push(',');
            }
            self.line.push_str(&format_f64(*v));
        }
        self.line.push('\n');
        self.rows += 1;
        self.write_line()
    }

    fn write_line(&mut self) -> Result<(), OutputError> {
        let Sink::File(out) = &mut self.out else {
            return Ok(());
        };
        out.write_all(self.line.as_bytes())
            .map_err(|source| OutputError::Io {
                path: self.path.clone(),
                source,
            })
    }

    /// Appends one row of pre-formatted cells, e.g. a label column beside
    /// numbers formatted with [`format_f64`]. Same width rule as
    /// [`CsvWriter::row`]; cells must not contain commas or newlines.
    pub fn row_cells(&mut self, cells: &[&str]) -> Result<(), OutputError> {
        if cells.len() != self.columns {
            return Err(OutputError::RowWidth {
                path: self.path.clone(),
                row: self.rows,
                got: cells.len(),
                expected: self.columns,
            });
        }
        let bad = |(i, c): (usize, &&str)| {
            let c = c.trim_start_matches(['-', '+']).to_ascii_lowercase();
            let infinite = c == "inf" || c == "infinity";
            c == "nan" || (infinite && !self.infinite_ok.get(i).copied().unwrap_or(false))
        };
        if let Some(i) = cells.iter().enumerate().position(bad) {
            return Err(self.non_finite(i, cells[i], cells[0]));
        }
        if let Sink::Memory(Some(m)) = &mut self.out {
            m.text(cells);
            self.rows += 1;
            return Ok(());
        }
        self.line.clear();
        self.line.push_str(&cells.join(","));
        self.line.push('\n');
        self.rows += 1;
        self.write_line()
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

    /// Number of data rows written so far.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Flushes the file and renames it into place; returns its path.
    pub fn finish(mut self) -> Result<PathBuf, OutputError> {
        let out = match &mut self.out {
            Sink::File(out) => out,
            Sink::Memory(m) => {
                if let Some(m) = m.take() {
                    m.finish();
                }
                self.done = true;
                return Ok(self.path.clone());
            }
        };
        out.flush().map_err(|source| OutputError::Io {
            path: self.path.clone(),
            source,
        })?;
        self.done = true;
        if let Err(e) = super::atomic::commit(&self.tmp, &self.path) {
            let _ = std::fs::remove_file(&self.tmp);
            return Err(e);
        }
        Ok(self.path.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::format_f64;

    #[test]
    fn round_trips_awkward_values() {
        for v in [
            0.1,
            -1.0 / 3.0,
            1e-300,
            f64::MIN_POSITIVE,
            5e-324,
            1.7976931348623157e308,
            123456789.12345679,
            1e15,
            9.999999999999998e14,
            -0.0,
            2.5e-4,
            9.99e-5,
        ] {
            let s = format_f64(v);
            let back: f64 = s.parse().unwrap();
            assert_eq!(back.to_bits(), v.to_bits(), "{v:?} -> {s}");
            assert!(s.len() <= 24, "{s}");
        }
        assert_eq!(format_f64(f64::NAN), "NaN");
        assert_eq!(format_f64(f64::NEG_INFINITY), "-inf");
    }
}
