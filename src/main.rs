//! platefall: parse the command line and run the subcommand (see `cli`).
//!
//! Exit codes: 0 completed; 2 bad input (nothing is run or written); 3 the solution diverged
//! (the recording and summary up to that point are still finalised); 130 interrupted (Ctrl-C).
use std::process::ExitCode;

use clap::Parser;

use platefall::cli::{bench::run_bench, run::run_case, Cli, Command};

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Bench(args) => run_bench(args).map(|_| ExitCode::SUCCESS),
        Command::Sweep(args) => return platefall::sweep::main(args),
        cmd => run_case(cmd),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
