//! Incompressible Navier–Stokes in three dimensions on a grid fixed to the body (docs/physics.md §9,
//! extending the mixed frame of §3).
//!
//! The unknowns are the inertial velocity along the body axes, u = Rᵀ U, on a staggered (MAC)
//! stretched Cartesian grid around a rectangular plate (chord along x, normal along y, span along
//! z). The grid moves with the body at g = Rᵀ Ẋ₀ + ω × x, and the equations are
//!
//! ```text
//!   u_t + ((u − g)·∇) u = −∇p + (1/Re) ∇²u − ω × u,      ∇·u = 0.
//! ```
//!
//! One step ([`FlowSolver3::advance`]) follows the two-dimensional solver's skeleton:
//! begin_step (ghost values and the explicit right-hand side Hⁿ) → predict (variable-step
//! Adams–Bashforth 2) → impose_boundaries (no slip on the plate, the outer boundary at tⁿ⁺¹) →
//! project (the discrete pressure equation, solved behind the [`PoissonSolve`] boundary) →
//! end_step → update_loads (force and moment as 3-vectors).
//!
//! Files: `grid.rs` (the stretched grid and its spec), `layout.rs` (the padded staggered
//! arrays), `metrics.rs` (stencil coefficients per axis), `frame.rs` (R, ω, Ẋ₀ and g),
//! `momentum.rs` (the right-hand side), `boundary.rs` (outer boundary), `plate.rs` (no slip and
//! the near-wall viscous stencils), `project.rs` (pressure operator, Jacobi CG, correction),
//! `multigrid.rs` (the default pressure solver, `poisson3` behind the same boundary),
//! `loads.rs` (forces and moments), `added_mass.rs` (the 6 × 6 added-mass matrix K), `coefficients.rs` (lift, drag, side force and the three
//! moments), `error.rs` and `params.rs`, `solver.rs` ([`FlowSolver3`]), `saved.rs` (its state between two
//! steps, for checkpoints).
//!
//! The step allocates nothing after [`FlowSolver3::new`]; the right-hand side and the pressure
//! solver's sweeps run in parallel over z-planes (rayon), with every reduction in a fixed order,
//! so the result does not depend on the number of threads.
mod added_mass;
mod boundary;
mod coefficients;
mod cut;
mod error;
mod frame;
mod grid;
mod layout;
mod loads;
mod metrics;
mod momentum;
mod multigrid;
mod params;
mod phases;
mod plate;
mod project;
mod saved;
mod shape;
mod snapshot;
mod solver;
mod wake;

pub use added_mass::AddedMass3;
pub use boundary::{OuterBc3, VelocityFn3};
pub use coefficients::Coefficients3;
pub use error::{Flow3Error, BLOWUP_FACTOR};
pub use frame::Frame3;
pub use grid::{Grid3, GridSpec3, Span, Stretch3, BYTES_PER_CELL};
pub use layout::Layout;
pub use loads::Loads3;
pub use metrics::Metrics3;
pub use multigrid::MultigridCg;
pub use params::FlowParams3;
pub use phases::{Phase3, PhaseMarker};
pub use project::{JacobiCg, PoissonOperator, PoissonSolve, SolveStats};
pub use saved::FlowState3;
pub use shape::Shape3;
pub use snapshot::FieldSnapshot3;
pub use solver::{FlowSolver3, ForceFn3};
