//! What can go wrong building or running the 3-D pressure solver, and what a solve reports.
use thiserror::Error;

/// A rejected input or a failed solve of [`super::Poisson3`].
#[derive(Debug, Error, Clone, PartialEq)]
pub enum PoissonError {
    /// A grid with no cells, or one whose cell count overflows.
    #[error("the grid has {nx} × {ny} × {nz} cells: each count must be at least 1 and the product fit in memory")]
    BadShape {
        /// Cells along x.
        nx: usize,
        /// Cells along y.
        ny: usize,
        /// Cells along z.
        nz: usize,
    },
    /// An array whose length does not match the grid.
    #[error("{what} has {found} entries, the grid needs {expected}")]
    SizeMismatch {
        /// Which array.
        what: &'static str,
        /// The length the grid needs.
        expected: usize,
        /// The length given.
        found: usize,
    },
    /// A NaN or infinite entry.
    #[error("{what} has a non-finite entry at index {index}")]
    NonFinite {
        /// Which array.
        what: &'static str,
        /// The first offending index.
        index: usize,
    },
    /// A cell width that is not positive, or a face coefficient that is negative.
    #[error("{what} has an invalid entry {value} at index {index} (widths must be > 0, coefficients ≥ 0)")]
    OutOfRange {
        /// Which array.
        what: &'static str,
        /// The first offending index.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A tolerance that is not a finite number in (0, 1).
    #[error("the relative tolerance must lie in (0, 1), got {0}")]
    BadTolerance(f64),
    /// The coarsest level's matrix could not be factored (it is not positive definite).
    #[error("the coarsest level's matrix ({0} unknowns) is not positive definite")]
    Coarsest(usize),
    /// Conjugate gradients met a non-positive curvature p·Ap (the operator or the preconditioner
    /// is not positive definite on the problem's range).
    #[error("conjugate gradients broke down at iteration {iterations} (p·Ap = {curvature})")]
    Breakdown {
        /// Iterations done.
        iterations: usize,
        /// The offending p·Ap.
        curvature: f64,
    },
    /// The iteration limit was reached before the tolerance.
    #[error("no convergence in {iterations} iterations: relative residual {residual:.3e}")]
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// The relative residual reached.
        residual: f64,
    },
}

/// What one [`super::Poisson3::solve`] did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveStats {
    /// Conjugate-gradient iterations (one V-cycle each); 0 when the warm start already met the
    /// tolerance.
    pub iterations: usize,
    /// The final relative residual ‖b̂ − A x‖₂ / ‖b̂‖₂ (b̂: the right-hand side projected onto the
    /// operator's range), recomputed from x.
    pub residual: f64,
}
