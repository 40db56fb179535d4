//! The command line: one subcommand per case (docs/physics.md §1) plus `bench`, `sweep`, `converge`, `ensemble` and `resume`. The
//! only layer that knows clap; it turns flags into the library's typed descriptions (the case options into
//! [`RunBuilder`](platefall_core::config::RunBuilder)s, the sweep's into a sweep request) and
//! typed errors into one-line messages that name the flag and an exit code (`Exit`).
//!
//! Files, each using only those after it: `command` (the grammar), `config` (a case's run),
//! `run` (running it), `sweep_args` and `sweep_cases` (the sweep's options and what it needs to
//! know of the case subcommands), `converge_args` (a refinement study's options), `ensemble_args`
//! (an ensemble's), `info` and `reproduce` (reading a recording back; `provenance`: what a run
//! records of how it was started; `shell`: command lines quoted for the shell), `bench_args`,
//! `args`, `plate_args` and `shape_args` (the case options: solver, plate, section),
//! `record_args`, `limits`, `signals`, `flags` (flag names and the argument error). A run's
//! checkpoints: `checkpointer`; `resume` (going on from one) over `resume_checks`; the 3-D runs
//! (`--span`): `span_run` over `span_steps` and `span_outputs`, and `span_resume`; `outcome`
//! (a finished run's exit code).
mod args;
mod bench_args;
mod branch;
mod checkpointer;
mod command;
mod config;
mod continued;
mod converge_args;
mod end_time;
mod ensemble_args;
mod flags;
mod info;
mod limits;
mod outcome;
mod plate_args;
mod provenance;
mod record_args;
mod reproduce;
mod reproduce_args;
mod resume;
mod resume_args;
mod resume_checks;
mod run;
mod shape_args;
mod shell;
mod signals;
mod span_arg;
mod span_cost;
mod span_outputs;
mod span_plate;
mod span_recording;
mod span_resume;
mod span_run;
mod span_steps;
mod sweep_args;
mod sweep_cases;
mod whole;

use std::process::ExitCode;

use crate::exit::Exit;
use command::Command;
use platefall_record::output::OutputError;

pub use crate::sweep::PlanError;
pub use command::{parse, Cli};

/// The run a case's argument vector describes (`args` without the program name, e.g.
/// `["free", "--resolution", "16"]`), parsed and validated exactly as the command line does it:
/// for reproducing a run in-process (the tests compare its fields with the files a run wrote).
///
/// # Errors
/// [`PlanError`] (one line, as the command line prints it) when `args` are not a case's command
/// line or describe no valid run.
pub fn case_config(args: &[String]) -> Result<platefall_core::sim::ValidatedConfig, PlanError> {
    use crate::sweep::CaseCommands as _;
    sweep_cases::CommandLineCases.config(args)
}

/// The program and version that checkpoints record, e.g. "platefall 0.1.0".
pub fn program_version() -> String {
    crate::version::program_version()
}

#[cfg(test)]
pub(crate) use sweep_cases::CommandLineCases;

/// Parses the process's command line, runs the subcommand and returns its exit code.
pub fn main() -> ExitCode {
    let cli = match parse(std::env::args_os()) {
        Ok(cli) => cli,
        Err(e) => e.exit(),
    };
    let result = match &cli.command {
        Command::Bench(args) => bench_args::run_bench(args).map(|()| Exit::Completed),
        Command::Sweep(args) => return sweep_cases::run_sweep(args).into(),
        Command::Converge(args) => return sweep_cases::run_converge(args).into(),
        Command::Ensemble(args) => return ensemble_args::run_ensemble(args).into(),
        Command::Resume(args) => resume::run_resume(args),
        Command::Info(args) => info::run_info(args),
        Command::Reproduce(args) => return reproduce::run_reproduce(args),
        cmd => run::run_case(cmd),
    };
    match result {
        Ok(code) => code.into(),
        Err(e) => {
            eprintln!("error: {e:#}");
            // An output that could not be written is not bad input.
            let output = e.chain().any(|c| c.is::<OutputError>());
            if output {
                Exit::OutputFailed
            } else {
                Exit::BadInput
            }
            .into()
        }
    }
}
