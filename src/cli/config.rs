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
        Command::Ensemble(_) => return Err(ArgError::NotACase("ensemble")),
        Command::Resume(_) => return Err(ArgError::NotACase("resume")),
        Command::Info(_) => return Err(ArgError::NotACase("info")),
        Command::Reproduce(_) => return Err(ArgError::NotACase("reproduce")),
    };
    if let Some((solver, _)) = cmd.case_args() {
        check_whole(Param::Threads, solver.threads, 0, 256)?;
    }
    Ok(config)
}

/// What to tell the user about the plate before a run (see `BodyArgs::notes`) and about how
/// the grid resolves its section ([`section_note`]).
pub fn plate_notes(cmd: &Command, config: &ValidatedConfig) -> Vec<String> {
    let mut notes = match cmd {
        Command::Pinned(a) => a.body.notes(config),
        Command::Free(a) => a.body.notes(config),
        _ => Vec::new(),
    };
    notes.extend(section_note(config));
    notes
}

/// Rounded edges narrower than this many cells are not resolved: a thin ellipse's regime
/// changed between N = 32 (tip radius ¼ cell) and N = 64 (½ cell), and N = 64 and 128 agreed
/// (docs/validation.md, "Falling plates").
const RESOLVED_EDGE_CELLS: f64 = 0.5;

/// A note when the section's rounded edges span less than half a cell at the run's N: the
/// flow's separation from them, which decides whether a falling section flutters or tumbles,
/// may then change with N.
fn section_note(config: &ValidatedConfig) -> Option<String> {
    let radius = config.grid.shape.edge_radius()?;
    let n = config.grid.resolution;
    let cells = radius * n as f64;
    if cells >= RESOLVED_EDGE_CELLS {
        return None;
    }
    let needed = (RESOLVED_EDGE_CELLS / radius).ceil();
    Some(format!(
        "note: the section's edges have a radius of curvature of {radius:.4} c, {cells:.2} of a \
         cell at N = {n}: below half a cell (from N = {needed} on here) the flow's separation from \
         them, and whether a falling section flutters or tumbles, can depend on N"
    ))
}
