//! The run description above the physics: where a run's numbers come from (SPEC §2, §8). A
//! [`RunConfig`](crate::sim::RunConfig) is the typed description the solver runs; this layer holds
//! the seed's card ([`PhysicalPlate`]), plates described physically ([`Strip`]) in named fluids
//! ([`Fluid`]), and the conversion of results back to physical units ([`Units`]).
pub mod fluid;
pub mod preset;
pub mod strip;
pub mod units;

pub use fluid::{Fluid, FLUID_NAMES};
pub use preset::{NonDimensional, PhysicalPlate};
pub use strip::Strip;
pub use units::Units;

use crate::sim::RunConfig;

/// The seed's card behind a run, when it uses the card preset (for its feet-based report keys).
pub fn physical(config: &RunConfig) -> Option<PhysicalPlate> {
    match config.body.as_ref()?.preset.as_deref() {
        Some("card") => Some(PhysicalPlate::card()),
        _ => None,
    }
}
