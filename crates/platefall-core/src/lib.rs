//! platefall's physics: a thin plate falling freely through a viscous fluid.
//!
//! Modules, each using only those before it in this list:
//!
//! - [`param`]: named inputs and their errors.
//! - [`grid`], [`flow`], [`body`], [`sim`]: the body-fixed grid, the mixed-frame Navier–Stokes
//!   solver, the plate's flight mechanics, and the coupled time loop with the run description
//!   and the solver's own outputs.
//! - [`config`]: presets and physical units behind a run's numbers.
//!
//! No I/O, no clock, no viewer: results go to a [`sim::Observer`] step by step. Run a case with
//! [`sim::Simulation`]; see `examples/static_drag.rs`.
pub mod param;

pub mod body;
pub mod flow;
pub mod grid;
pub mod sim;

pub mod config;
pub mod shape;
