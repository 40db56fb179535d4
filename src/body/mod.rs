//! Rigid-body flight mechanics of the plate (SPEC §6): the Cartesian equations of motion, the
//! variable-step Adams–Bashforth integrator and the added-mass coupling advisory.

pub mod adams;
pub mod coupling;
pub mod rigid;

pub use adams::{ab_weights, AbError, AbStart, AdamsBashforth, MAX_ORDER};
pub use coupling::{coupling_advice, coupling_check, PLATE_ADDED_INERTIA, PLATE_ADDED_MASS};
pub use rigid::{
    advance, body_to_inertial, inertial_to_body, state_derivative, wrap_angle, BodyState, Dof,
    InertialLoads, PlateProps, RigidBody,
};
