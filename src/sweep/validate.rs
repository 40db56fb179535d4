//! The command line's own validation applied to each case of a plan, and what the plan may name.
//!
//! This is the one place that calls into the CLI layer (`Cli::try_parse_from`, `run_config`,
//! `summarize`): when their signatures change, only this file changes.
use clap::{CommandFactory, Parser};

use crate::cli::{run_config, Cli};
use platefall_core::sim::RunRecord;
use platefall_post::summary::summarize;

/// The case subcommands a plan may name.
pub const CASES: [&str; 4] = ["static", "forced", "pinned", "free"];

/// Options the sweep sets itself for every case; a plan may not set them.
pub const MANAGED: [&str; 12] = [
    "summary",
    "csv",
    "save",
    "no-save",
    "progress",
    "quiet",
    "serve",
    "bind",
    "port",
    "server-memory-limit",
    "connect",
    "spawn",
];

/// One option of a case subcommand.
#[derive(Clone, Debug, PartialEq)]
pub struct OptionInfo {
    /// The long name without `--`.
    pub name: String,
    /// False for a flag (`--seed-grid`), given in a plan as `true` or `false`.
    pub takes_value: bool,
}

/// The long options of a case subcommand, in `--help` order.
pub fn case_options(case: &str) -> Option<Vec<OptionInfo>> {
    let cmd = Cli::command();
    let sub = cmd.find_subcommand(case)?;
    let opts = sub
        .get_arguments()
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
        .collect();
    Some(opts)
}

/// Checks one case's argument vector (`[case, --opt=value, ...]`) exactly as the command line
/// would: clap's parsing and the run configuration's validation. The error is one line.
pub fn validate_case(argv: &[String]) -> Result<(), String> {
    config_of(argv).map(|_| ())
}

/// The validated run configuration of an argument vector.
fn config_of(argv: &[String]) -> Result<platefall_core::sim::RunConfig, String> {
    let full = std::iter::once("platefall".to_string()).chain(argv.iter().cloned());
    let cli = Cli::try_parse_from(full).map_err(|e| clap_one_line(&e))?;
    run_config(&cli.command).map_err(|e| e.to_string())
}

/// The keys of a case's summary (as in `--summary`), in order, for a valid argument vector.
pub fn summary_keys(argv: &[String]) -> Result<Vec<String>, String> {
    let config = config_of(argv)?;
    let empty = RunRecord {
        status: platefall_core::sim::RunStatus::Completed,
        samples: Default::default(),
        t_release: 0.0,
        cells: 0,
        recirculation_length: None,
    };
    let summary = summarize(&config, &empty, 0.0);
    let text = serde_json::to_string(&summary).map_err(|e| e.to_string())?;
    let object = super::json::parse_object(&text)?;
    Ok(object.into_iter().map(|(k, _)| k).collect())
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
