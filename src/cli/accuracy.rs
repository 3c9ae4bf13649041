//! `pegdyn accuracy [--csv FILE] [--only TEXT]`: the rounding error of every generated
//! function, `f64` against double-double on the hard grid
//! ([`pegdyn::accuracy`]). Exit 1 if the grid is incomplete or the CSV
//! cannot be written.

use std::path::Path;
use std::process::ExitCode;

use pegdyn::accuracy::measure;
use pegdyn::generated::registry::FUNCTIONS;

/// Measures, prints the table, writes the CSV if asked.
pub fn accuracy(csv: Option<&Path>, only: Option<&str>) -> ExitCode {
    let report = match measure(&FUNCTIONS, only) {
        Ok(r) => r,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    if let Some(sub) = only
        && report.functions.is_empty()
    {
        errln!(
            "error: --only {sub:?} matches no grid point label: nothing to measure \
             (labels are printed in the table's `worst at` column of a full run)"
        );
        return ExitCode::FAILURE;
    }
    if !pegdyn::generated::SOURCE.contains("Stable numerical rewrites: OFF") {
        outln!("stable numerical rewrites: on");
    } else {
        outln!("stable numerical rewrites: OFF (built with PEGDYN_NAIVE_FORMS=1)");
    }
    outln!("rounding error of the f64 evaluation against double-double, same f64 inputs\n");
    outln!("{report}");
    if let Some(path) = csv
        && let Err(e) = pegdyn::output::atomic::write(path, report.to_csv().as_bytes())
    {
        errln!("error: cannot write {}: {e}", path.display());
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}
