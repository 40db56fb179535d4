//! The far-field scheme a solver starts with (docs/physics.md §3): the split lines and, for the
//! implicit scheme, its workspaces.
use super::error::{FlowError, SetupError};
use super::implicit::State;
use super::metrics::Metrics;
use super::params::{FarFieldScheme, FlowParams};
use super::zones::Zones;
use crate::grid::Grid;

/// The split lines and the implicit workspaces for the far-field scheme of `params` (none for
/// the explicit scheme).
///
/// # Errors
/// [`SetupError::NearField`] when a split line would cross the plate.
pub fn far_field_state(
    grid: &Grid,
    params: &FlowParams,
    metrics: &Metrics,
) -> Result<(Zones, Option<Box<State>>), FlowError> {
    match params.far_field {
        FarFieldScheme::Explicit => Ok((Zones::none(grid), None)),
        FarFieldScheme::Implicit => {
            let z = Zones::new(grid, params.near_x, params.near_y);
            z.check_plate(grid).map_err(SetupError::NearField)?;
            let state = State::new(grid.nx, grid.ny, metrics);
            Ok((z, Some(Box::new(state))))
        }
    }
}
