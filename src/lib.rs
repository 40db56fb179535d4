//! platefall: a thin plate falling freely through a viscous fluid.
//!
//! The workspace's crates are its layers, each using only those before it:
//!
//! 1. `platefall-core` — physics and the run description (no I/O, no clock, no viewer).
//! 2. `platefall-post` — the summary and report of a run, pictures of its fields.
//! 3. `platefall-record` — the logger thread, CSV, progress and (feature `viewer`) Rerun.
//! 4. this crate — the command line: [`cli`] (the only layer that knows clap), [`bench`], and
//!    [`sweep`] (parameter sweeps: many runs of this program, locally or as a Slurm job array),
//!    and [`converge`] (refinement studies: a sweep over one refined option, analysed for the
//!    observed order, Richardson extrapolation and GCI).
pub mod bench;
pub mod cli;
pub mod converge;
pub mod sweep;
