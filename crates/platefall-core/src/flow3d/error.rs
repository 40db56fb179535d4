//! Why the three-dimensional flow solver could not start or stopped.

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
    /// A body that ends within the span on a periodic span.
    #[error("the body {shape:?} ends within the span, which a periodic span does not allow: a periodic span (periodic:P) takes the plate or a cylinder along the span (rect, ellipse, circle); give a finite span")]
    ShapeNotPeriodic {
        /// The shape given.
        shape: super::shape::Shape3,
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
    /// The pressure solver could not be built for this grid.
    #[error("the pressure solver could not be built: {0}")]
    PressureSetup(#[from] crate::poisson3::PoissonError),
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
    /// A saved flow state does not fit this solver (checkpoints, docs/three-d.md "On the command
    /// line").
    #[error("the saved 3-D flow state does not fit this solver: {what} is {saved}, this solver's is {ours}")]
    StateMismatch {
        /// What differs.
        what: &'static str,
        /// The saved state's.
        saved: String,
        /// This solver's.
        ours: String,
    },
}

/// Velocities beyond this multiple of (1 + |g|max) mean the solution has blown up.
pub const BLOWUP_FACTOR: f64 = 25.0;
