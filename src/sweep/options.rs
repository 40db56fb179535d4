//! What the sweep needs to know of the case subcommands — their options, and the run an argument
//! vector describes — asked of the command line through [`CaseCommands`], and the options the
//! sweep sets itself.
use platefall_core::sim::{CaseKind, RunConfig, RunRecord, RunStatus, ValidatedConfig};
use platefall_post::summary::summarize;

use super::json;
use super::plan_error::PlanError;

/// Options the sweep sets itself for every case; a plan may not set them.
pub(crate) const MANAGED: [&str; 15] = [
    "summary",
    "csv",
    "save",
    "no-save",
    "progress",
    "quiet",
    "serve",
    "web",
    "web-port",
    "bind",
    "port",
    "server-memory-limit",
    "connect",
    "spawn",
    "vtk",
];

/// One option of a case subcommand.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct OptionInfo {
    /// The long name without `--`.
    pub(crate) name: String,
    /// False for a flag (`--seed-grid`), given in a plan as `true` or `false`.
    pub(crate) takes_value: bool,
}

/// The case subcommands as the sweep sees them; the command line implements it.
pub(crate) trait CaseCommands {
    /// The long options of `case`, in `--help` order.
    fn options(&self, case: CaseKind) -> Vec<OptionInfo>;

    /// The run an argument vector of a case subcommand (`[case, --opt=value, ...]`) describes,
    /// checked exactly as the command line checks it; the error is one line.
    fn config(&self, args: &[String]) -> Result<ValidatedConfig, PlanError>;
}

/// The keys of the summary of a run of `config` (as `--summary` writes them), in order.
pub(crate) fn summary_keys(config: &RunConfig) -> Result<Vec<String>, PlanError> {
    let empty = RunRecord {
        status: RunStatus::Completed,
        samples: Default::default(),
        t_release: 0.0,
        cells: 0,
        recirculation_length: None,
    };
    let summary = summarize(config, &empty, 0.0);
    let text = serde_json::to_string(&summary).map_err(|e| PlanError(e.to_string()))?;
    let object = json::parse_object(&text).map_err(|e| PlanError(e.to_string()))?;
    Ok(object.into_iter().map(|(k, _)| k).collect())
}
