//! A case subcommand's run: its options turned into the library's validated run description,
//! and what to tell the user about it before it starts.
use super::command::Command;
use super::flags::ArgError;
use platefall_core::param::{check_whole, Param};
use platefall_core::sim::ValidatedConfig;

/// The validated run of a case subcommand.
pub fn run_config(cmd: &Command) -> Result<ValidatedConfig, ArgError> {
    let config = match cmd {
        Command::Static(a) => a.config()?,
        Command::Forced(a) => a.config()?,
        Command::Pinned(a) => a.config()?,
        Command::Free(a) => a.config()?,
        Command::Bench(_) => return Err(ArgError::NotACase("bench")),
        Command::Sweep(_) => return Err(ArgError::NotACase("sweep")),
        Command::Converge(_) => return Err(ArgError::NotACase("converge")),
        Command::Resume(_) => return Err(ArgError::NotACase("resume")),
    };
    if let Some((solver, _)) = cmd.case_args() {
        check_whole(Param::Threads, solver.threads, 0, 256)?;
    }
    Ok(config)
}

/// What to tell the user about the plate before a run (see `BodyArgs::notes`).
pub fn plate_notes(cmd: &Command, config: &ValidatedConfig) -> Vec<String> {
    match cmd {
        Command::Pinned(a) => a.body.notes(config),
        Command::Free(a) => a.body.notes(config),
        _ => Vec::new(),
    }
}
