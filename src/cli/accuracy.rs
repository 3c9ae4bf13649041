//! `pegdyn accuracy [--csv FILE] [--only TEXT]`: the rounding error of every generated
//! function, `f64` against double-double on the hard grid
//! ([`pegdyn::accuracy`]). Exit 1 if the grid is incomplete or the CSV
//! cannot be written.
//!
//! Only with the Cargo feature `accuracy`: the double-double reference
//! instantiates every generated function a second time, at `Dd`, which
//! costs the binary most of its compile time. Without the feature the
//! command says how to build it and exits 1.

use std::path::Path;
use std::process::ExitCode;

/// Without the `accuracy` feature: how to build the command.
#[cfg(not(feature = "accuracy"))]
pub fn accuracy(_csv: Option<&Path>, _only: Option<&str>) -> ExitCode {
    errln!(
        "error: this pegdyn was built without the `accuracy` feature \
         (the double-double reference doubles the binary's compile time); \
         run `cargo run --release --features accuracy -- accuracy`"
    );
    ExitCode::FAILURE
}

/// Measures, prints the table, writes the CSV if asked.
#[cfg(feature = "accuracy")]
pub fn accuracy(csv: Option<&Path>, only: Option<&str>) -> ExitCode {
    use pegdyn::accuracy::measure;
    use pegdyn::generated::registry::DD_FUNCTIONS;
    let report = match measure(&DD_FUNCTIONS, only) {
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
