//! `platefall sweep`: parameter sweeps of one case, run locally as child processes or on a Slurm
//! cluster as a job array, merged into one results table and a phase diagram.
//!
//! A sweep directory `DIR` holds the plan (`plan.toml`), the expanded case list (`sweep.json`),
//! one directory per case (`cases/<id>/`: `summary.json`, `run.csv`, `log.txt`, `status.json`,
//! optionally `run.rrd`) and the merged outputs (`results.csv`, `results.json`, `phase.png`,
//! `phase.svg`, `phase.rrd`). A case is done when its summary exists at its final name and says
//! `completed` or `diverged`; everything else is run again by the next sweep over the same plan.
//!
//! The sweep knows no clap: the command line gives it a [`SweepRequest`] and answers what it
//! needs to know of the case subcommands ([`CaseCommands`]). Files, each using only those after
//! it: `commands` (the entry points), `slurm`, `runner` (the local pool), `progress`, `results`,
//! `diagram` (the phase diagram's data from the results) and `plot` (the figure; `phase.rrd` is
//! the recording crate's), `child` (one case as a child process), `layout` (paths, manifest,
//! lock), `cases`, `plan`, `options` and `values` (the plan format and its cases), `json`
//! (ordered objects), `failure` (exit codes, atomic writes), `clock`. `converge` is a refinement
//! study: a sweep over one refined option, analysed for the observed order of convergence.
mod cases;
mod child;
mod clock;
mod commands;
pub(crate) mod converge;
mod diagram;
mod failure;
mod json;
mod layout;
mod options;
mod plan;
#[cfg(test)]
mod plan_tests;
mod plot;
mod progress;
mod results;
mod runner;
mod slurm;
mod values;

use std::path::PathBuf;

pub(crate) use commands::main;
pub(crate) use options::{CaseCommands, OptionInfo};
pub(crate) use plan::PlanError;
pub(crate) use progress::ProgressMode;
pub(crate) use slurm::SlurmOverrides;

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
