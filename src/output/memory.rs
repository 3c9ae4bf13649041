//! Tables held in memory: what a run into a memory sink
//! ([`super::sink::Sink::memory`]) keeps instead of CSV files.
//!
//! A captured number is the `f64` the scene computed; a file holds its
//! shortest round-trip decimal, which parses back to the same bits, so a
//! table read back from the file equals the captured one value for value.
//! A column is typed as a reader of the file would type it: numbers when
//! every cell parses as a number, else text.

use super::csv::format_f64;

/// What a memory sink keeps of the tables written into it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Keep {
    /// Every CSV table, column by column, and every other file's bytes
    /// (e.g. the replay page) as written.
    Tables,
    /// Nothing: rows are checked as for a file and dropped (a sweep that
    /// wants only the run summaries).
    Nothing,
}

/// A file other than a table that a run wrote into memory (e.g. the
/// replay page `<scene>.html`), kept with [`Keep::Tables`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KeptFile {
    /// The name the file would have had, e.g. `insert_rcc.html`.
    pub file: String,
    /// Its bytes.
    pub bytes: Vec<u8>,
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

/// A table a run wrote into memory.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The name the file would have had, e.g. `pendulum.csv`.
    pub file: String,
    /// Column names, as in the file's header line.
    pub header: Vec<String>,
    /// The columns, in header order.
    pub columns: Vec<Column>,
}

impl Table {
    /// The column headed `name`, if the table has one.
    pub fn column(&self, name: &str) -> Option<&Column> {
        let k = self.header.iter().position(|h| h == name)?;
        self.columns.get(k)
    }

    /// The file stem, e.g. `pendulum` for `pendulum.csv`.
    pub fn stem(&self) -> String {
        std::path::Path::new(&self.file)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    }
}

#[derive(Debug)]
enum Cell {
    Number(f64),
    Text(String),
}

/// The rows of one table being written into memory (rows already checked
/// by the writer).
#[derive(Debug)]
pub(crate) struct TableBuilder {
    file: String,
    header: Vec<String>,
    cells: Vec<Vec<Cell>>,
}

impl TableBuilder {
    /// An empty table named `file` with `header`.
    pub(crate) fn new(file: String, header: &[String]) -> Self {
        TableBuilder {
            file,
            header: header.to_vec(),
            cells: header.iter().map(|_| Vec::new()).collect(),
        }
    }

    /// Appends a row of numbers.
    pub(crate) fn numbers(&mut self, values: &[f64]) {
        for (c, v) in self.cells.iter_mut().zip(values) {
            c.push(Cell::Number(*v));
        }
    }

    /// Appends a row of pre-formatted cells.
    pub(crate) fn text(&mut self, cells: &[&str]) {
        for (c, v) in self.cells.iter_mut().zip(cells) {
            c.push(Cell::Text((*v).to_owned()));
        }
    }

    /// The table with its columns typed.
    pub(crate) fn finish(self) -> Table {
        Table {
            file: self.file,
            header: self.header,
            columns: self.cells.into_iter().map(typed).collect(),
        }
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
