//! Post-processing (docs/physics.md §7): statistics and the summary of a run's time series, and pictures of
//! its flow snapshots — vorticity, stream function, streamlines in the four observer frames, and
//! resampling from the stretched MAC grid onto uniform images.
//!
//! Everything here is a pure function of the solver's outputs ([`platefall_core::sim::StepSample`],
//! [`platefall_core::sim::FieldSnapshot`], [`platefall_core::grid::GridGeometry`]): no I/O, no Rerun types. The
//! logger thread (`record`) calls the painting, so that work runs beside the solver, not in it.
//!
//! - [`analysis`]: developed windows, means, the dominant lift frequency, turn counting, the lag
//!   of the drag peak, the projected width.
//! - [`stats`]: confidence intervals of time means of autocorrelated series (batch means,
//!   integrated autocorrelation times, Student's t); [`convergence`]: observed order, Richardson
//!   extrapolation and the grid-convergence index of a refinement study; [`ensemble`]: the
//!   mean and interval of an ensemble of independent members, their independence, the
//!   separation of two ensembles and the planner; [`rng`]: the seeded generator of the
//!   ensembles' perturbations and of the synthetic tests.
//! - [`keys`]: the run summary's data with its stable JSON keys; [`intervals`]: the batches of a
//!   run and the interval of every mean in its summary; [`summary`]: the summary of a run, its
//!   means and then their intervals; [`report`]: the end-of-run text; [`regime`]: what a falling
//!   plate is doing (steady, fluttering, tumbling, chaotic).
//! - [`fields`]: the staggered-grid quantities. [`vorticity_at_nodes`] (ω = ∂v/∂x − ∂u/∂y at cell
//!   corners), [`stream_function_at_nodes`] (ψ with u = ψ_y, v = −ψ_x, integrated from the MAC face
//!   fluxes: exact for a discretely divergence-free field), and [`StreamFrame`], the observer frames
//!   of docs/physics.md §7 with the velocity and stream function of each observer.
//! - [`resample`]: separable bilinear interpolation from a tensor-product (stretched) grid onto a
//!   uniform image ([`ImageGrid`], [`AxisWeights`]).
//! - [`contour`]: iso-lines of a scalar on a tensor grid (marching squares, joined into polylines).
//! - [`painter`]: [`FieldPainter`] puts it together: one call turns a snapshot into the three
//!   images (vorticity, pressure, speed) and the streamlines, with all interpolation weights
//!   precomputed once per run.
//! - [`phase`]: a sweep's phase diagram as data (cases placed by swept options, their regimes
//!   and a chosen value), drawn by the sweep's figure and the recording crate.
//! - [`wake`]: the same three fields over a long window that follows the plate along its path
//!   ([`WakePainter`], [`PathHeading`]).
//! - [`plot_range`]: the value ranges the viewer's plots open on ([`PlotRanges`]), chosen from
//!   the case so that the developed motion fills them and the start-up spike lies outside;
//!   [`view`]: those and the wake window, the viewer's defaults of a run ([`ViewDefaults`]).
#![warn(missing_docs)]

pub mod analysis;
pub mod contour;
pub mod convergence;
pub mod ensemble;
pub mod fields;
pub mod intervals;
pub mod keys;
pub mod painter;
pub mod phase;
pub mod plot_range;
pub mod precision;
pub mod regime;
pub mod report;
pub mod resample;
pub mod rng;
pub mod stats;
pub mod summary;
pub mod summary3;
pub mod view;
pub mod wake;

pub use contour::{isolines, simplify_polyline, Polyline};
pub use fields::{
    cell_centres, face_velocities, stream_function_at_nodes, vorticity_at_nodes, SnapshotFields,
    StreamFrame,
};
pub use painter::{FieldPainter, PaintedFields, PainterOptions, SnapshotMismatch};
pub use plot_range::PlotRanges;
pub use resample::{bilinear, bilinear_at_points, AxisWeights, FieldWindow, ImageGrid};
pub use view::ViewDefaults;
pub use wake::{default_wake_window, PathHeading, WakeImages, WakePainter};
