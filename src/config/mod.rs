//! The run description above the physics: physical presets and their non-dimensional parameters
//! (SPEC §2, §8). A [`RunConfig`](crate::sim::RunConfig) is the typed description the solver runs;
//! this layer says where its numbers come from.
pub mod preset;

pub use preset::{NonDimensional, PhysicalPlate};

use crate::sim::RunConfig;

/// The physical plate behind a run, when it uses a preset (for physical units in reports).
pub fn physical(config: &RunConfig) -> Option<PhysicalPlate> {
    match config.body.as_ref()?.preset.as_deref() {
        Some("card") => Some(PhysicalPlate::card()),
        _ => None,
    }
}
