//! What the sweep needs to know of the case subcommands, answered by the command line: the
//! options each one takes (clap's own definitions), and the run an argument vector describes
//! (parsed and validated exactly as a typed command line, a 3-D flight's plate included; it is
//! the argument vector the case's child process is started with); and running `platefall sweep` and `platefall converge` with
//! those answers.
use clap::CommandFactory;

use super::command::{parse, Cli};
use super::config::run_config;
use super::converge_args::ConvergeArgs;
use super::span_plate::flight_plate;
use super::sweep_args::SweepArgs;
use crate::exit::Exit;
use crate::sweep::{self, converge};
use crate::sweep::{CaseCommands, OptionInfo, PlanError};
use platefall_core::sim::{CaseKind, ValidatedConfig};

/// The case subcommands of this command line.
pub(crate) struct CommandLineCases;

impl CaseCommands for CommandLineCases {
    fn options(&self, case: CaseKind) -> Vec<OptionInfo> {
        let cmd = Cli::command();
        let Some(sub) = cmd.find_subcommand(case.name()) else {
            return Vec::new();
        };
        sub.get_arguments()
            .filter_map(|a| {
                let name = a.get_long()?;
                if name == "help" || name == "version" {
                    return None;
                }
                Some(OptionInfo {
                    name: name.to_string(),
                    takes_value: a.get_action().takes_values(),
                })
            })
            .collect()
    }

    fn config(&self, args: &[String]) -> Result<ValidatedConfig, PlanError> {
        let argv = std::iter::once("platefall".to_string()).chain(args.iter().cloned());
        let cli = parse(argv).map_err(|e| PlanError(clap_one_line(&e)))?;
        let config = run_config(&cli.command).map_err(|e| PlanError(e.to_string()))?;
        // A 3-D flight's plate (its span in millimetres against --span), as the case will check it.
        if let Some(span) = cli.command.case_args().and_then(|(s, _)| s.span) {
            flight_plate(&cli.command, span).map_err(|e| PlanError(e.to_string()))?;
        }
        Ok(config)
    }
}

/// clap's error (several lines with usage and tips) as one line.
fn clap_one_line(e: &clap::Error) -> String {
    let text = e.render().to_string();
    let mut lines = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("Usage:") && !l.starts_with("For more"));
    let first = lines.next().unwrap_or("invalid arguments");
    let first = first.strip_prefix("error: ").unwrap_or(first);
    match lines.find(|l| l.starts_with("tip:")) {
        Some(tip) => format!("{first} ({tip})"),
        None => first.to_string(),
    }
}

/// Runs `platefall sweep ...`.
pub fn run_sweep(args: &SweepArgs) -> Exit {
    match args.request() {
        Ok(request) => sweep::main(&request, &CommandLineCases),
        Err(message) => {
            eprintln!("error: {message}");
            Exit::BadInput
        }
    }
}

/// Runs `platefall converge ...`.
pub fn run_converge(args: &ConvergeArgs) -> Exit {
    converge::main(&args.request(), &CommandLineCases)
}
