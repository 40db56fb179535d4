//! What the command line asks of the sweep, below the entry points that do it (`commands`).
use std::path::PathBuf;

use super::progress::ProgressMode;
use super::slurm::SlurmOverrides;

/// What the command line asks of the sweep.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum SweepRequest {
    /// Run a plan's cases (or only list them, or write a Slurm script for them).
    Run {
        /// The plan file.
        plan: PathBuf,
        /// Cases run at once (None: one per core).
        jobs: Option<usize>,
        /// List the cases without running anything.
        dry_run: bool,
        /// The output directory (None: the plan's).
        output: Option<PathBuf>,
        /// The progress display.
        progress: ProgressMode,
        /// Write a Slurm job-array script with these resources instead of running the cases.
        slurm: Option<SlurmOverrides>,
    },
    /// Merge whatever has finished in a sweep directory.
    Collect {
        /// The sweep directory.
        dir: PathBuf,
    },
    /// Run one case of a prepared sweep directory (what each Slurm array task runs).
    RunCase {
        /// The sweep directory.
        dir: PathBuf,
        /// The case's index.
        index: usize,
    },
}
