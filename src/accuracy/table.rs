//! [`Report`] as a fixed-width table and as CSV.

use std::fmt;

use super::Report;

/// Ulps as printed: integers below 1e6, else scientific; `inf` for ∞.
fn ulps(u: f64) -> String {
    if u.is_infinite() {
        "inf".to_owned()
    } else if u < 1e6 {
        format!("{u:.1}")
    } else {
        format!("{u:.2e}")
    }
}

impl Report {
    /// CSV: `function,points,entries,max_ulps,max_relative,non_finite,worst_at`.
    pub fn to_csv(&self) -> String {
        let mut s =
            String::from("function,points,entries,max_ulps,max_relative,non_finite,worst_at\n");
        for f in &self.functions {
            s.push_str(&format!(
                "{},{},{},{:e},{:e},{},\"{}\"\n",
                f.path, f.points, f.entries, f.max_ulps, f.max_relative, f.non_finite, f.worst_at
            ));
        }
        s
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{:<34} {:>6} {:>8} {:>10} {:>10} {:>10} {:>5}  worst ulps at",
            "function", "points", "entries", "max ulps", "max rel", "normwise", "nonf"
        )?;
        for r in &self.functions {
            writeln!(
                f,
                "{:<34} {:>6} {:>8} {:>10} {:>10.2e} {:>10.2e} {:>5}  {}",
                r.path,
                r.points,
                r.entries,
                ulps(r.max_ulps),
                r.max_relative,
                r.max_normwise,
                r.non_finite,
                r.worst_at
            )?;
        }
        for m in &self.skipped {
            writeln!(
                f,
                "(no hard grid for module `{m}`: add one in src/accuracy/grid.rs)"
            )?;
        }
        Ok(())
    }
}
