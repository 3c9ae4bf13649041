//! Operation counts of generated functions and the generation report.

use std::fmt;
use std::ops::AddAssign;

use crate::graph::Cost;

/// Floating-point operations one call of a generated function performs, as
/// emitted (each `let` counted once, inlined expressions once).
///
/// Functions and powers are charged their [`Cost`] from the one table of
/// [`crate::graph::func`]; `sin_cos` (emitted when a sine and a cosine of
/// the same argument are both used) is one call, not two.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCounts {
    /// Additions and subtractions.
    pub add: usize,
    /// Multiplications.
    pub mul: usize,
    /// Divisions.
    pub div: usize,
    /// Square roots.
    pub sqrt: usize,
    /// Calls of transcendental functions.
    pub transcendental: usize,
    /// `if` conditions.
    pub branch: usize,
}

impl OpCounts {
    /// Adds the cost of one function application (from the table of
    /// [`crate::graph::func`]).
    pub fn charge(&mut self, c: Cost) {
        self.mul += c.mul;
        self.div += c.div;
        self.sqrt += c.sqrt;
        self.transcendental += c.transcendental;
        self.branch += c.branch;
    }

    /// Total of all counted operations.
    pub fn total(&self) -> usize {
        self.add + self.mul + self.div + self.sqrt + self.transcendental + self.branch
    }
}

impl AddAssign for OpCounts {
    fn add_assign(&mut self, o: OpCounts) {
        self.add += o.add;
        self.mul += o.mul;
        self.div += o.div;
        self.sqrt += o.sqrt;
        self.transcendental += o.transcendental;
        self.branch += o.branch;
    }
}

impl fmt::Display for OpCounts {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} add/sub, {} mul, {} div, {} sqrt, {} transcendental, {} branches",
            self.add, self.mul, self.div, self.sqrt, self.transcendental, self.branch
        )
    }
}

/// One generated function in the report.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReportRow {
    /// The module (model) name.
    pub module: String,
    /// The function name.
    pub function: String,
    /// Operations of one call, as emitted.
    pub ops: OpCounts,
    /// Number of `let` bindings of intermediate values.
    pub lets: usize,
}

/// What was generated: one row per function, in emission order.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Report {
    /// One row per function, modules in declaration order.
    pub rows: Vec<ReportRow>,
}

impl fmt::Display for Report {
    /// A plain-text table, one function per line.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let header = [
            "module", "function", "add/sub", "mul", "div", "sqrt", "transc", "branch", "lets",
        ];
        let rows: Vec<[String; 9]> = self
            .rows
            .iter()
            .map(|r| {
                let o = r.ops;
                [
                    r.module.clone(),
                    r.function.clone(),
                    o.add.to_string(),
                    o.mul.to_string(),
                    o.div.to_string(),
                    o.sqrt.to_string(),
                    o.transcendental.to_string(),
                    o.branch.to_string(),
                    r.lets.to_string(),
                ]
            })
            .collect();
        let mut width = header.map(str::len);
        for r in &rows {
            for (w, c) in width.iter_mut().zip(r) {
                *w = (*w).max(c.len());
            }
        }
        let line = |f: &mut fmt::Formatter<'_>, cells: &[&str]| -> fmt::Result {
            let mut s = String::new();
            for (k, (c, w)) in cells.iter().zip(width).enumerate() {
                if k < 2 {
                    s.push_str(&format!("{c:<w$}  "));
                } else {
                    s.push_str(&format!("{c:>w$}  "));
                }
            }
            writeln!(f, "{}", s.trim_end())
        };
        line(f, &header)?;
        for r in &rows {
            line(f, &r.iter().map(String::as_str).collect::<Vec<_>>())?;
        }
        Ok(())
    }
}
