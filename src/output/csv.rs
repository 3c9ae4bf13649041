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

/// Writes a CSV file row by row.
#[derive(Debug)]
pub struct CsvWriter {
    path: PathBuf,
    out: BufWriter<File>,
    columns: usize,
    rows: usize,
    line: String,
}

impl CsvWriter {
    /// Creates (truncates) `path` and writes the header. Column names should
    /// carry their unit, e.g. `theta_rad`, `t_s`.
    pub fn create(path: &Path, header: &[&str]) -> Result<Self, OutputError> {
        let io = |source| OutputError::Io {
            path: path.to_path_buf(),
            source,
        };
        let file = File::create(path).map_err(io)?;
        let mut w = CsvWriter {
            path: path.to_path_buf(),
            out: BufWriter::new(file),
            columns: header.len(),
            rows: 0,
            line: String::new(),
        };
        writeln!(w.out, "{}", header.join(",")).map_err(io)?;
        Ok(w)
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
        self.line.clear();
        for (i, v) in values.iter().enumerate() {
            if i > 0 {
                self.line.push(',');
            }
            self.line.push_str(&format_f64(*v));
        }
        self.line.push('\n');
        self.rows += 1;
        self.out
            .write_all(self.line.as_bytes())
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
        self.line.clear();
        self.line.push_str(&cells.join(","));
        self.line.push('\n');
        self.rows += 1;
        self.out
            .write_all(self.line.as_bytes())
            .map_err(|source| OutputError::Io {
                path: self.path.clone(),
                source,
            })
    }

    /// Number of data rows written so far.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Flushes the file; returns its path.
    pub fn finish(mut self) -> Result<PathBuf, OutputError> {
        self.out.flush().map_err(|source| OutputError::Io {
            path: self.path.clone(),
            source,
        })?;
        Ok(self.path)
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
