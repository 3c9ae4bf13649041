//! The `pegdyn` command-line tool; see `pegdyn --help` and [`cli`].

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
