//! Why the flow solver stopped or could not start.
use super::pressure::PressureError;
use super::zones::PlateCrossing;

/// Why the flow solver stopped or could not start.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FlowError {
    /// The solution blew up at time `t` (after `step` steps); `reason` says what was seen.
    #[error("the flow solution diverged at t = {t:.4} (step {step}): {reason}")]
    Diverged {
        /// The time of the last good step.
        t: f64,
        /// Steps taken.
        step: u64,
        /// What was seen.
        reason: String,
    },
    /// The solver could not be set up.
    #[error("the flow solver could not be set up: {0}")]
    Setup(SetupError),
}

/// Why the flow solver could not be set up.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SetupError {
    /// The pressure operator could not be assembled or factored.
    #[error("the pressure operator: {0}")]
    Pressure(PressureError),
    /// A line of the implicit far field would cross the plate (its line solves know no wall
    /// inside the domain): the near field must contain the plate.
    #[error(transparent)]
    NearField(PlateCrossing),
}

impl From<SetupError> for FlowError {
    fn from(e: SetupError) -> FlowError {
        FlowError::Setup(e)
    }
}
