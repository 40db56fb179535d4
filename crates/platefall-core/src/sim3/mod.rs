//! The three-dimensional flow around a plate in prescribed planar motion — the static and
//! forced cases of docs/physics.md §1 (A, B) with a finite or periodic span (docs/three-d.md
//! "Cases") — and in flight (docs/three-d.md "Free flight").
//!
//! The plate moves exactly as in 2-D — the centre along +X at U, the pitch θ(t) about the span
//! axis z ([`planar_frame`]) — and [`run_prescribed`] steps a [`crate::flow3d::FlowSolver3`]
//! through it, handing each step's [`Sample3`] to an observer. [`Flight3`] flies a plate with six
//! degrees of freedom (or planar, or pinned) through the 3-D flow, strongly coupled; its state
//! between two steps is [`FlightState`] (`saved.rs`).
mod case3;
mod flight;
mod planar;
mod run;
mod saved;

pub use case3::{unwrapped_pitch, Run3, EXTENT3, GROWTH3};
pub use flight::{frame_of, Flight3, Flight3Error, Sample6};
pub use planar::planar_frame;
pub use run::{run_prescribed, Sample3};
pub use saved::FlightState;
