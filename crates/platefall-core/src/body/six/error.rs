//! Typed errors of the six-degree-of-freedom body (docs/physics.md §9).

use thiserror::Error;

use crate::body::AbError;

/// What is wrong with a 6-DOF plate, state, added-mass matrix or checkpoint.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SixError {
    /// The mass is not finite and positive.
    #[error("the mass m* must be finite and > 0, got {0}")]
    Mass(f64),
    /// The inertia tensor is not finite, symmetric and positive definite.
    #[error("the inertia tensor must be finite, symmetric and positive definite, got {0:?}")]
    Inertia([[f64; 3]; 3]),
    /// Gravity is not finite and non-negative.
    #[error("g* must be finite and >= 0, got {0}")]
    Gravity(f64),
    /// The displaced fluid mass is not finite and non-negative.
    #[error("the displaced fluid mass m_f* must be finite and >= 0, got {0}")]
    Displaced(f64),
    /// A physical dimension (chord, span, density, …) is not finite and positive.
    #[error("the {name} must be finite and > 0, got {value}")]
    Dimension {
        /// Which dimension.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A component of the state is NaN or infinite.
    #[error("the state's {0} is not finite")]
    NotFinite(&'static str),
    /// The orientation quaternion is not of unit norm.
    #[error("the orientation quaternion must have unit norm (within 1e-12), got norm {0}")]
    Orientation(f64),
    /// Planar, the centre moves along Z.
    #[error("in planar flight the centre's velocity along Z must be 0, got {0}")]
    PlanarVelocity(f64),
    /// Pinned about the span, the angular velocity has components off the span.
    #[error("pinned about the span, the angular velocity must lie along body z, got {0:?}")]
    PinnedSpin([f64; 3]),
    /// diag(m, m, m) ⊕ I − K is not positive definite.
    #[error(
        "the plate's mass matrix minus the added-mass matrix K must be positive definite; \
         the smallest eigenvalue of its symmetric part is {0}"
    )]
    AddedMass(f64),
    /// The saved derivative history does not fit.
    #[error(transparent)]
    History(#[from] AbError),
    /// The saved orientation history does not fit the saved derivative history.
    #[error("the saved orientation history does not fit the saved derivative history")]
    SpinHistory,
}
