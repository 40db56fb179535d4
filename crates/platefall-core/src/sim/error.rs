//! Why a run could not be built or could not go on.
use crate::body::AbError;
use crate::flow::FlowError;
use crate::param::InputError;
use crate::sim3::Flight3Error;

/// Why a run could not be built or could not go on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    /// A bad input.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The flow solver could not be set up, or its solution diverged.
    #[error(transparent)]
    Flow(#[from] FlowError),
    /// The 3-D flow or flight could not be set up, or its solution diverged
    /// (docs/three-d.md "Cases").
    #[error(transparent)]
    Flight3(#[from] Flight3Error),
    /// The plate's integrator refused its input.
    #[error(transparent)]
    Body(#[from] AbError),
    /// The plate's motion became non-finite.
    #[error("the plate's motion is not finite at t = {t:.4}")]
    MotionNotFinite {
        /// The time of the step.
        t: f64,
    },
    /// The stable time step fell to round-off of t (the motion runs away, e.g. explicit coupling
    /// of a light plate).
    #[error(
        "the time step fell to {dt:.3e} at t = {t:.4}: the motion runs away (as explicit \
         coupling of a plate lighter than its added mass does)"
    )]
    StepCollapsed {
        /// The time reached.
        t: f64,
        /// The step the limits allowed.
        dt: f64,
    },
}
