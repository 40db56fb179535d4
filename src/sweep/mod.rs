//! `platefall sweep`: parameter sweeps of one case, run locally as child processes or on a Slurm
//! cluster as a job array, merged into one results table and a phase diagram.
//!
//! A sweep directory `DIR` holds the plan (`plan.toml`), the expanded case list (`sweep.json`),
//! one directory per case (`cases/<id>/`: `summary.json`, `run.csv`, `log.txt`, `status.json`,
//! optionally `run.rrd`) and the merged outputs (`results.csv`, `results.json`, `phase.png`,
//! `phase.svg`, `phase.rrd`). A case is done when its summary exists at its final name and says
//! `completed` or `diverged`; everything else is run again by the next sweep over the same plan.
//!
//! Files: `args` (command line), `plan`, `values` and `cases` (the plan format and its cases),
//! `validate` (the CLI's own validation of each case: the one file that calls into the CLI layer),
//! `layout` (paths, manifest, lock), `fsutil` (atomic writes, times), `json` (ordered objects),
//! `child` (one case as a child process), `runner` (the local pool), `progress`, `results`,
//! `diagram` and `plot` (the figure), `recording` (the Rerun phase diagram, behind the `viewer`
//! feature), `slurm`, `commands` (the entry points).
pub mod args;
pub mod cases;
pub mod child;
pub mod commands;
pub mod diagram;
pub mod fsutil;
pub mod json;
pub mod layout;
pub mod plan;
#[cfg(test)]
mod plan_tests;
pub mod plot;
pub mod progress;
#[cfg(feature = "viewer")]
pub mod recording;
pub mod results;
pub mod runner;
pub mod slurm;
pub mod validate;
pub mod values;

pub use args::SweepArgs;
pub use commands::main;

/// A sweep that stops: the process exit code and one line saying why.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    pub code: u8,
    pub message: String,
}

/// Exit code of a bad plan or bad command line (nothing is run or written).
pub const EXIT_BAD_INPUT: u8 = 2;
/// Exit code when the sweep finished but some cases did not complete (diverged, failed, missing).
pub const EXIT_INCOMPLETE: u8 = 3;
/// Exit code when an output of the sweep could not be written.
pub const EXIT_OUTPUT: u8 = 4;
/// Exit code after Ctrl-C (the running cases are finalised and the results merged first).
pub const EXIT_INTERRUPTED: u8 = 130;

impl Failure {
    /// Bad input: exit 2.
    pub fn input(message: impl Into<String>) -> Self {
        Failure {
            code: EXIT_BAD_INPUT,
            message: message.into(),
        }
    }
    /// An output that could not be written: exit 4.
    pub fn output(message: impl Into<String>) -> Self {
        Failure {
            code: EXIT_OUTPUT,
            message: message.into(),
        }
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Failure {}
