//! Rigid-body flight mechanics of the plate (docs/physics.md §6): the Cartesian equations of motion, the
//! variable-step Adams–Bashforth integrator, the strong (added-mass implicit) coupling and the
//! advisory for explicit coupling; [`six`]: the six-degree-of-freedom body of the 3-D flight.

mod adams;
mod coupling;
mod rigid;
pub mod six;
mod strong;

pub use adams::{ab_weights, AbError, AbHistory, AbStart, AdamsBashforth, MAX_ORDER};
pub use coupling::{coupling_advice, ADVICE_MARGIN, PLATE_ADDED_INERTIA, PLATE_ADDED_MASS};
pub use rigid::{
    advance, body_to_inertial, inertial_to_body, state_derivative, wrap_angle, BodySnapshot,
    BodyState, Dof, InertialLoads, PlateProps, RigidBody,
};
pub use strong::{Coupling, StrongCoupling};
