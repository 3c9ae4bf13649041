//! Command-line interface: argument definitions (clap derive) and dispatch.
//!
//! Exit codes: 0 success, 1 a scene or run failed, 2 usage error, 128 +
//! the signal for a run stopped by SIGINT (130) or SIGTERM (143).
//! One file per subcommand; `bench` will join them.

/// `println!` that does not panic when stdout is closed early (`| head`):
/// output is best effort, a failed write is dropped.
macro_rules! outln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

/// `eprintln!` that does not panic when stderr is closed.
macro_rules! errln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

mod accuracy;
mod check;
mod codegen;
mod run;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Symbolic-to-code generator and solver for peg-in-hole assembly dynamics.
#[derive(Debug, Parser)]
#[command(name = "pegdyn", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a scene: write OUT/<scene>.csv and OUT/<scene>.svg, print a summary.
    Run {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Output directory (created if missing).
        #[arg(long, short, default_value = "out")]
        out: PathBuf,
        /// No progress line on stderr.
        #[arg(long, short)]
        quiet: bool,
        /// Raise a work limit, KEY=VALUE with the keys of the scene's
        /// [limits] table (e.g. max_output_samples=1e8; the max_ prefix may
        /// be left out). Repeatable; replaces the scene's own value.
        #[arg(long = "limit", value_name = "KEY=VALUE")]
        limits: Vec<String>,
        /// Write no replay page (OUT/<scene>.html), whatever the scene's
        /// [replay] table says.
        #[arg(long)]
        no_replay: bool,
    },
    /// Validate scene files without running them.
    Check {
        /// Scene files (TOML).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Raise a work limit, as for `run`.
        #[arg(long = "limit", value_name = "KEY=VALUE")]
        limits: Vec<String>,
    },
    /// Print the generated model code, then its operation-count report.
    Codegen {
        /// Print only the operation-count report.
        #[arg(long)]
        report_only: bool,
    },
    /// List the scene kinds this build knows.
    Kinds,
    /// Rounding error of every generated function: f64 against double-double
    /// on a grid of hard points (see docs/ACCURACY.md; needs the `accuracy`
    /// feature).
    Accuracy {
        /// Also write the table as CSV to this file.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Only the grid points whose label contains this text (e.g. "theta=0e0").
        #[arg(long)]
        only: Option<String>,
    },
}

/// The `--limit` arguments, or `None` after printing why they are unusable
/// (a usage error).
fn limit_overrides(args: &[String]) -> Option<pegdyn::scene::limits::LimitOverrides> {
    match pegdyn::scene::limits::LimitOverrides::parse(args) {
        Ok(o) => Some(o),
        Err(e) => {
            errln!("error: {e}");
            None
        }
    }
}

/// Parses the arguments and runs the subcommand.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version go to stdout with success; usage errors to
            // stderr with exit code 2.
            let code = if e.use_stderr() { 2 } else { 0 };
            // If printing fails there is nowhere left to report it.
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    match cli.command {
        Command::Run {
            scene,
            out,
            quiet,
            limits,
            no_replay,
        } => match limit_overrides(&limits) {
            Some(o) => run::run(&scene, &out, quiet, &o, no_replay),
            None => ExitCode::from(2),
        },
        Command::Check { scenes, limits } => match limit_overrides(&limits) {
            Some(o) => check::check(&scenes, &o),
            None => ExitCode::from(2),
        },
        Command::Codegen { report_only } => codegen::codegen(report_only),
        Command::Accuracy { csv, only } => accuracy::accuracy(csv.as_deref(), only.as_deref()),
        Command::Kinds => {
            for k in pegdyn::scene::KINDS {
                outln!("{:<20} {}", k.name, k.about);
            }
            ExitCode::SUCCESS
        }
    }
}
