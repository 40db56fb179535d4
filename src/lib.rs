//! platefall: a thin plate falling freely through a viscous fluid.
//!
//! Layers, each using only those above it in this list:
//!
//! 1. Physics — [`param`] (named inputs and their errors), [`grid`], [`flow`], [`body`], and
//!    [`sim`] (the coupled time loop, the motion laws, the run description and the solver's own
//!    outputs). No I/O, no clock, no viewer.
//! 2. Run description — [`config`]: presets and physical units behind a run's numbers.
//! 3. Post-processing — [`post`]: the summary and report of a run, pictures of its fields.
//! 4. Recording — [`record`]: the logger thread, CSV, progress and (feature `viewer`) Rerun.
//! 5. Command line — [`cli`] (the only layer that knows clap), [`bench`], and [`sweep`] (parameter
//!    sweeps: many runs of this program, locally or as a Slurm job array).
//!
//! Run a case from Rust with [`sim::Simulation`]; see `examples/static_drag.rs`.
pub mod param;

pub mod body;
pub mod flow;
pub mod grid;
pub mod sim;

pub mod config;

pub mod post;

pub mod record;

pub mod bench;
pub mod cli;
pub mod sweep;
