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
//! it: `commands` (the entry points), `request` (what the command line asks), `slurm`, `runner` (the local pool), `progress`, `results`,
//! `diagram` (the phase diagram's data from the results) and `plot` (the figure; `phase.rrd` is
//! the recording crate's), `child` (one case as a child process), `layout` (paths, manifest,
//! lock), `cases`, `plan`, `options` and `values` (the plan format and its cases), `plan_error`, `json`
//! (ordered objects), `failure` (exit codes, atomic writes), `clock`; `slurm_time` (Slurm's time limits) below
//! `plan` and `slurm`. `converge` is a refinement
//! study: a sweep over one refined option, analysed for the observed order of convergence;
//! `ensemble` runs members branched from one checkpoint as a sweep and pools their means.
mod cases;
mod child;
mod clock;
mod commands;
pub(crate) mod converge;
mod diagram;
pub(crate) mod ensemble;
mod failure;
mod figure;
mod json;
mod layout;
mod options;
mod plan;
mod plan_error;
#[cfg(test)]
mod plan_tests;
mod plot;
mod progress;
mod request;
mod results;
mod runner;
mod slurm;
mod slurm_time;
mod values;

pub(crate) use commands::main;
pub(crate) use options::{CaseCommands, OptionInfo};
pub use plan_error::PlanError;
pub(crate) use progress::ProgressMode;
pub(crate) use request::SweepRequest;
pub(crate) use slurm::SlurmOverrides;
