//! platefall: parse the command line and run the subcommand (see `cli`).
//!
//! Exit codes (`cli::EXIT_CODES`, also in `--help`): 0 completed; 2 bad input (nothing is run or
//! written); 3 the solution diverged; 4 an output could not be written; 130 interrupted.
use std::process::ExitCode;

use clap::Parser;

use platefall::cli::{bench::run_bench, run::run_case, Cli, Command};
use platefall_record::output::OutputError;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Bench(args) => run_bench(args).map(|_| ExitCode::SUCCESS),
        Command::Sweep(args) => return platefall::sweep::main(args),
        Command::Converge(args) => return platefall::converge::main(args),
        cmd => run_case(cmd),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            // An output that could not be created is not bad input.
            let output = e.chain().any(|c| c.is::<OutputError>());
            ExitCode::from(if output { 4 } else { 2 })
        }
    }
}
