//! platefall: a thin plate falling freely through a viscous fluid.
//!
//! The workspace's crates are its layers, each using only those before it:
//!
//! 1. `platefall-core` — physics, the run description and its constructors (no I/O, no clock,
//!    no viewer).
//! 2. `platefall-post` — the summary and report of a run, pictures of its fields, phase
//!    diagrams' data.
//! 3. `platefall-record` — the logger thread, atomic output files, CSV, progress and (feature
//!    `viewer`) everything Rerun.
//! 4. this crate — [`cli`], the command line (the only layer that knows clap), above the sweep
//!    (parameter sweeps: many runs of this program, locally or as a Slurm job array), the bench,
//!    the worker pool, the exit codes and the program's version.
#![warn(missing_docs)]

pub mod cli;

mod bench;
mod bench3;
mod exit;
mod pool;
mod sweep;
pub mod version;
