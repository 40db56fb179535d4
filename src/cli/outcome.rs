//! The exit code of a finished run (2-D or 3-D) and its one-line messages on stderr.
use std::path::Path;

use crate::exit::Exit;
use platefall_core::sim::RunStatus;
use platefall_post::summary::Summary;
use platefall_record::output::write_atomically;

/// Writes the `--summary` JSON at `path` (if asked): its line for the end-of-run list of outputs,
/// or the failure added to `failures`.
pub fn write_summary(
    path: Option<&Path>,
    json: &str,
    failures: &mut Vec<String>,
) -> Option<String> {
    let path = path?;
    match write_atomically("--summary", path, json.as_bytes()) {
        Ok(_) => Some(format!("summary: {}", path.display())),
        Err(e) => {
            failures.push(e.to_string());
            None
        }
    }
}

/// The exit code of a finished run, with its one-line messages on stderr; `checkpointed`: the
/// checkpoint a stopped run wrote.
pub fn exit_code(
    status: &RunStatus,
    summary: &Summary,
    failures: &[String],
    checkpointed: Option<&Path>,
) -> Exit {
    if !failures.is_empty() {
        let stopped = match status {
            RunStatus::OutputFailed(_) => {
                format!("; the run stopped at t = {:.3}", summary.t_reached)
            }
            _ => String::new(),
        };
        eprintln!(
            "error: could not write {}{stopped}; nothing incomplete was left at a final name",
            failures.join("; ")
        );
    }
    match status {
        RunStatus::Interrupted => eprintln!(
            "interrupted: the outputs hold the run up to t = {:.3} and say so{}",
            summary.t_reached,
            checkpointed.map_or(String::new(), |p| format!(
                "; `platefall resume {}` goes on from there",
                p.display()
            ))
        ),
        RunStatus::OutputFailed(msg) if failures.is_empty() => eprintln!("error: {msg}"),
        RunStatus::Diverged(e) if failures.is_empty() => {
            eprintln!("error: {e}; try a smaller --cfl or a finer --resolution")
        }
        _ => {}
    }
    match status {
        RunStatus::Interrupted if checkpointed.is_some() && failures.is_empty() => {
            Exit::Checkpointed
        }
        RunStatus::Interrupted | RunStatus::OutputFailed(_) => Exit::of_status(status),
        _ if !failures.is_empty() => Exit::OutputFailed,
        _ => Exit::of_status(status),
    }
}
