//! A run's saved state between two steps as plain data, and why a saved state may not fit a
//! run: below the simulation, which saves and restores it (`checkpoint.rs`).
use super::error::SimError;
use super::history::History;
use crate::body::{AbError, BodySnapshot, BodyState};
use crate::flow::{FlowState, StateMismatch};

/// A run's state between two steps; see `Simulation::save` and the `checkpoint` module.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SimState {
    /// The flow solver's fields and time levels.
    pub flow: FlowState,
    /// The plate's state.
    pub state: BodyState,
    /// The coupled plate's body (None for prescribed motion) and whether it is released.
    pub body: Option<(BodySnapshot, bool)>,
    /// θ at the release, for counting turns.
    pub theta_release: Option<f64>,
    /// Every step's samples so far (the summary's accumulators).
    pub history: History,
}

/// Why a saved state cannot be put back into a run of this configuration.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RestoreError {
    /// Building the run failed.
    #[error(transparent)]
    Build(#[from] SimError),
    /// The flow fields do not fit the grid.
    #[error(transparent)]
    Flow(#[from] StateMismatch),
    /// The plate's history does not fit.
    #[error(transparent)]
    Body(#[from] AbError),
    /// A prescribed motion with a saved free body, or the other way round.
    #[error("the saved state is of another motion law (prescribed versus coupled)")]
    Motion,
}
