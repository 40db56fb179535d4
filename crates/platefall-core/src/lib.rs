//! platefall's physics: a thin plate falling freely through a viscous fluid — 2-D incompressible
//! Navier–Stokes on a grid fixed to the plate, in the dissertation's mixed frame (inertial velocity
//! components along the body axes), coupled to the plate's 3-degree-of-freedom flight mechanics.
//!
//! Describe a run with a [`config::RunBuilder`] (one constructor per case, with the command
//! line's defaults) and a [`config::Plate`], validate it into a [`sim::ValidatedConfig`], and
//! step a [`sim::Simulation`]:
//!
//! ```
//! use platefall_core::config::{Plate, RunBuilder};
//! use platefall_core::sim::{Silent, Simulation};
//!
//! // The dissertation's card released into free fall on a coarse grid, for one convective time.
//! let config = RunBuilder::free(Plate::card())
//!     .resolution(8)
//!     .develop(0.5)
//!     .t_end(1.0)
//!     .build()?;
//! let mut sim = Simulation::new(config)?;
//! let record = sim.run(&mut Silent);
//! let last = record.samples.last().expect("a step");
//! println!("t = {:.2}: V = {:.3}, θ̇ = {:.3}, C_L = {:.3}", last.t, last.speed, last.omega, last.cl);
//! assert!(last.t >= 1.0 - 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Modules, each using only those before it in this list:
//!
//! - [`param`]: named inputs and their errors.
//! - [`grid`], [`flow`], [`body`], [`sim`]: the body-fixed grid, the mixed-frame Navier–Stokes
//!   solver, the plate's flight mechanics, and the coupled time loop with the run description
//!   and the solver's own outputs.
//! - [`config`]: the constructors of runs, presets and physical units behind a run's numbers.
//!
//! No I/O, no clock, no viewer: results go to a [`sim::Observer`] step by step, as plain data.
#![warn(missing_docs)]

pub mod param;

pub mod body;
pub mod flow;
pub mod flow3d;
pub mod grid;
pub mod poisson3;
pub mod sim;
pub mod sim3;

pub mod config;
pub mod shape;
