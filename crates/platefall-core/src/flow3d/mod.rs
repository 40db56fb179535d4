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
//! the near-wall viscous stencils), `project.rs` (pressure operator, CG solver, correction),
//! `loads.rs` (forces and moments), `solver.rs` ([`FlowSolver3`]).
//!
//! The step allocates nothing after [`FlowSolver3::new`]; the right-hand side and the pressure
//! solver's sweeps run in parallel over z-planes (rayon), with every reduction in a fixed order,
//! so the result does not depend on the number of threads.
mod boundary;
mod frame;
mod grid;
mod layout;
mod loads;
mod metrics;
mod momentum;
mod plate;
mod project;
mod solver;

pub use boundary::{OuterBc3, VelocityFn3};
pub use frame::Frame3;
pub use grid::{Grid3, GridSpec3, Span, Stretch3, BYTES_PER_CELL};
pub use layout::Layout;
pub use loads::Loads3;
pub use metrics::Metrics3;
pub use project::{JacobiCg, PoissonOperator, PoissonSolve, SolveStats};
pub use solver::{FlowSolver3, ForceFn3};

/// Numerical parameters of the three-dimensional flow solver.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FlowParams3 {
    /// Reynolds number U c / ν.
    pub re: f64,
    /// Courant number of the convective limit.
    pub cfl: f64,
    /// Fraction of the explicit viscous stability limit used.
    pub visc_safety: f64,
    /// The pressure solve stops when every fluid cell's divergence after the correction is
    /// below this (non-dimensional, 1/time).
    pub div_tol: f64,
    /// Most iterations of the pressure solve per step.
    pub max_iterations: usize,
}

impl Default for FlowParams3 {
    fn default() -> Self {
        FlowParams3 {
            re: 5000.0,
            cfl: 0.5,
            visc_safety: 0.8,
            div_tol: 1e-11,
            max_iterations: 20_000,
        }
    }
}

impl FlowParams3 {
    /// Checks every value, naming the first bad one.
    pub fn validate(&self) -> Result<(), Flow3Error> {
        let bad = |name: &'static str, value: f64| Flow3Error::BadParameter { name, value };
        if !(self.re > 0.0 && self.re.is_finite()) {
            return Err(bad("re", self.re));
        }
        if !(self.cfl > 0.0 && self.cfl <= 1.0) {
            return Err(bad("cfl", self.cfl));
        }
        if !(self.visc_safety > 0.0 && self.visc_safety <= 1.0) {
            return Err(bad("visc_safety", self.visc_safety));
        }
        if !(self.div_tol > 0.0 && self.div_tol.is_finite()) {
            return Err(bad("div_tol", self.div_tol));
        }
        if self.max_iterations == 0 {
            return Err(bad("max_iterations", 0.0));
        }
        Ok(())
    }
}

/// Velocities beyond this multiple of (1 + |g|max) mean the solution has blown up.
pub const BLOWUP_FACTOR: f64 = 25.0;

/// Why the three-dimensional flow solver could not start or stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Flow3Error {
    /// The span is zero, negative or not a number.
    #[error("the span must be a positive number of chords, got {span}")]
    SpanNotPositive {
        /// The span given (chords).
        span: f64,
    },
    /// The span holds fewer than two cells at this resolution.
    #[error("a span of {span} chords holds fewer than 2 cells of h = 1/{resolution}: give a span of at least {min} chords or a finer resolution")]
    SpanTooShort {
        /// The span given (chords).
        span: f64,
        /// Cells per chord.
        resolution: usize,
        /// The shortest span accepted at this resolution.
        min: f64,
    },
    /// A grid input is out of range.
    #[error("grid input {name} = {value} is out of range ({range})")]
    BadGrid {
        /// Which input.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The accepted range.
        range: &'static str,
    },
    /// The grid would need more memory than allowed.
    #[error("the grid has {cells} cells, about {bytes:.3e} bytes, over the limit of {limit:.3e} bytes: coarsen the resolution, the extent or raise the growth cap")]
    GridTooLarge {
        /// Cells of the grid.
        cells: usize,
        /// Estimated memory of the solver (bytes).
        bytes: f64,
        /// The limit (bytes).
        limit: f64,
    },
    /// A numerical parameter is out of range.
    #[error("flow parameter {name} = {value} is out of range")]
    BadParameter {
        /// Which parameter.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// The time step is not positive and finite.
    #[error("the time step must be positive and finite, got {dt}")]
    BadStep {
        /// The step given.
        dt: f64,
    },
    /// The solution blew up.
    #[error("the 3-D flow solution diverged at t = {t:.4} (step {step}): {reason}")]
    Diverged {
        /// Time of the last good step.
        t: f64,
        /// Steps taken.
        step: u64,
        /// What was seen.
        reason: String,
    },
    /// The pressure solve did not reach its tolerance.
    #[error("the pressure solve stopped after {iterations} iterations at divergence {divergence:.3e} (tolerance {tolerance:.1e})")]
    PressureNotConverged {
        /// Iterations taken.
        iterations: usize,
        /// Largest cell divergence reached.
        divergence: f64,
        /// The tolerance asked.
        tolerance: f64,
    },
}
