//! What `platefall resume` checks before it goes on with a 2-D or a 3-D run: the run
//! description the checkpoint's command line builds, and why a checkpoint cannot be resumed as
//! asked.
use std::path::PathBuf;

use super::command::Command;
use super::config::run_config;
use super::end_time;
use super::resume_args::ResumeArgs;
use platefall_core::config::Units;
use platefall_core::sim::ValidatedConfig;
use platefall_record::checkpoint::ResumeInfo;

/// Why a checkpoint cannot be resumed as asked (besides a bad file).
#[derive(Debug, thiserror::Error)]
pub enum ResumeRefusal {
    /// The checkpoint's command line no longer describes a case.
    #[error("checkpoint {}: its command line does not describe a run any more: {why}", .file.display())]
    CommandLine {
        /// The checkpoint.
        file: PathBuf,
        /// Why.
        why: String,
    },
    /// The command line builds another run description than the checkpoint's.
    #[error("checkpoint {}: its command line now builds another run than the checkpoint holds (a file it reads changed, or run it from the directory it was started in)", .0.display())]
    ConfigChanged(PathBuf),
    /// The earlier CSV does not hold the rows up to the checkpoint.
    #[error("--csv: cannot resume it: {0}")]
    Csv(String),
    /// `--csv-from` for a run that writes no CSV.
    #[error("--csv-from {}: the run writes no CSV; give --csv FILE too", .0.display())]
    CsvFromWithoutCsv(PathBuf),
    /// The run would already be over under the end asked for.
    #[error("{end}: the checkpoint is at t = {t:.4} c/U; the run would already be over (give a later --t-end or more --turns)")]
    AlreadyOver {
        /// The end, e.g. "--t-end 3" or "the run's end".
        end: String,
        /// The checkpoint's time.
        t: f64,
    },
}

/// The refusal of a checkpoint at time `t` that the end asked for has passed.
pub fn already_over(args: &ResumeArgs, t: f64) -> ResumeRefusal {
    let end = match (args.t_end, args.turns) {
        (Some(te), _) => format!("--t-end {te}"),
        (None, Some(n)) => format!("--turns {n}"),
        (None, None) => "the run's end".into(),
    };
    ResumeRefusal::AlreadyOver { end, t }
}

/// The run description: the checkpoint's command line rebuilt, checked against the checkpoint,
/// with the end asked for.
pub fn resumed_config(
    cmd: &Command,
    resume: &ResumeInfo,
    args: &ResumeArgs,
) -> anyhow::Result<ValidatedConfig> {
    let config = run_config(cmd)?;
    if serde_json::to_string_pretty(&config)? != resume.config_json {
        anyhow::bail!(ResumeRefusal::ConfigChanged(args.file.clone()));
    }
    let mut c = config.config().clone();
    let scales = Units::of(&c).map(|u| u.scales);
    c.time.t_end = match args.t_end {
        Some(t) => end_time::convective(t, scales)?,
        None => resume.t_end,
    };
    c.time.turns = args.turns.or(resume.turns);
    c.time.average_from_turn = args.average_from_turn.unwrap_or(c.time.average_from_turn);
    Ok(c.validate().map_err(super::flags::ArgError::from)?)
}
