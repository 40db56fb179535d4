//! The run description above the physics: where a run's numbers come from (docs/physics.md §2, §8) and the
//! constructors that describe each case. [`RunBuilder`] fills in a
//! [`crate::sim::RunConfig`] for each case with the command line's defaults and
//! validates it; this layer also holds the dissertation's card ([`PhysicalPlate`]), plates described
//! physically ([`Strip`]) in named fluids ([`Fluid`]), the plate of a coupled run ([`Plate`]),
//! and the conversion of results back to physical units ([`Units`]).
mod build;
mod end_time;
mod fluid;
mod plate;
mod preset;
mod strip;
mod strip3;
mod units;

pub use build::{defaults, ForcedRotation, FreeFall, PinnedPlate, RunBuilder, StaticPlate};
pub use end_time::EndTime;
pub use fluid::{Fluid, FLUID_NAMES};
pub use plate::Plate;
pub use preset::{NonDimensional, PhysicalPlate, FOOT_M};
pub use strip::Strip;
pub use units::Units;

use crate::sim::{PlateSource, RunConfig};

/// The dissertation's card behind a run, when it uses the card preset (for its feet-based report keys).
pub fn physical(config: &RunConfig) -> Option<PhysicalPlate> {
    match config.body.as_ref()?.source {
        PlateSource::Card => Some(PhysicalPlate::card()),
        _ => None,
    }
}
