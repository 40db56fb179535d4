//! platefall: a thin plate falling freely through a viscous fluid.
//!
//! The physics core (`grid`, `flow`, `body`, `sim`) is free of I/O and of Rerun types;
//! `post` turns raw fields into pictures and `record` turns plain messages into Rerun.
pub mod body;
pub mod post;
pub mod record;
pub mod flow;
pub mod grid;
pub mod analysis;
pub mod config;
pub mod sim;
pub mod summary;
pub mod bench;

pub mod cli;
