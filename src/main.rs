//! platefall: parse the command line and run the subcommand (see `cli`); the exit codes are
//! `exit::Exit` (also in `--help`).
fn main() -> std::process::ExitCode {
    platefall::cli::main()
}
