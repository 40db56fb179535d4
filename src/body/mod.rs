//! Rigid-body flight mechanics of the plate (SPEC §6): the Cartesian equations of motion, the
//! variable-step Adams–Bashforth integrator, the added-mass coupling advisory and the seed's card.

pub mod adams;
pub mod coupling;
pub mod preset;
pub mod rigid;

pub use adams::{ab_weights, AbError, AbStart, AdamsBashforth, MAX_ORDER};
pub use coupling::{coupling_advice, coupling_check, PLATE_ADDED_INERTIA, PLATE_ADDED_MASS};
pub use preset::{NonDimensional, PhysicalPlate};
pub use rigid::{
    advance, body_to_inertial, inertial_to_body, state_derivative, wrap_angle, BodyState, Dof,
    Loads, PlateProps, RigidBody,
};
