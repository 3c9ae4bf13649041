//! `pegdyn codegen [--report-only]`: print the code generated at build time
//! from the symbolic models, then the operation-count report.

use std::process::ExitCode;

use pegdyn::generated::{REPORT, SOURCE};

/// Prints the generated source (unless `report_only`) and the report.
pub fn codegen(report_only: bool) -> ExitCode {
    if !report_only {
        outln!("{SOURCE}");
    }
    outln!("{REPORT}");
    ExitCode::SUCCESS
}
