//! platefall: a thin plate falling freely through a viscous fluid.
//!
//! The physics core (`grid`, `flow`, `body`, `sim`) is free of I/O and of Rerun types;
//! `post` turns raw fields into pictures and `record` turns plain messages into Rerun.
pub mod analysis;
pub mod bench;
pub mod body;
pub mod config;
pub mod flow;
pub mod grid;
pub mod post;
pub mod record;
pub mod sim;
pub mod summary;
pub mod sweep;

pub mod cli;
