//! The three-dimensional flow around a plate in prescribed planar motion: the static and forced
//! cases of docs/physics.md §1 (A, B) with a finite or periodic span (docs/three-d.md "Cases").
//!
//! The plate moves exactly as in 2-D — the centre along +X at U, the pitch θ(t) about the span
//! axis z ([`planar_frame`]) — and [`run_prescribed`] steps a [`crate::flow3d::FlowSolver3`]
//! through it, handing each step's [`Sample3`] to an observer. Free flight in 3-D (six degrees of
//! freedom) is not here yet.
mod planar;
mod run;

pub use planar::planar_frame;
pub use run::{run_prescribed, Sample3};
