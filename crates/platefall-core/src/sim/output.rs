//! What a run produces, as the solver's own plain-data types: one sample per step, field
//! snapshots, and how the run ended. Nothing here knows about files or viewers.
use super::history::History;
use super::SimError;
use crate::flow::Frame;

/// A flow snapshot on the MAC grid.
///
/// Velocities are the **inertial** velocity components along the body axes (docs/physics.md §3).
#[derive(Clone, Debug)]
pub struct FieldSnapshot {
    /// Steps taken so far.
    pub step: u64,
    /// Convective time of the snapshot.
    pub t: f64,
    /// X of the plate's centre at this instant.
    pub x: f64,
    /// Y of the centre.
    pub y: f64,
    /// Pitch angle θ.
    pub theta: f64,
    /// The plate's motion in body axes: the grid-point velocity is g = (u0 − θ̇ y, v0 + θ̇ x).
    pub frame: Frame,
    /// x-velocity on vertical faces (xn\[i\], yc\[j\]); length (nx + 1) * ny, index i + (nx + 1) * j.
    pub u: Vec<f64>,
    /// y-velocity on horizontal faces (xc\[i\], yn\[j\]); length nx * (ny + 1), index i + nx * j.
    pub v: Vec<f64>,
    /// Pressure at cell centres; length nx * ny, index i + nx * j. Zero far away.
    pub p: Vec<f64>,
}

/// How a run ended.
#[derive(Clone, Debug, PartialEq)]
pub enum RunStatus {
    /// The run reached its end time or its number of turns.
    Completed,
    /// The solution blew up; the error says where and when.
    Diverged(SimError),
    /// Stopped from outside (the observer asked to stop: Ctrl-C).
    Interrupted,
    /// Stopped because an output could not be written (disk full, file removed, …); the message
    /// names the output.
    OutputFailed(String),
}

/// How a run ended, without the details: what summaries, CSV trailers and sweep tables record.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StatusKind {
    /// `completed`.
    Completed,
    /// `diverged`.
    Diverged,
    /// `interrupted`.
    Interrupted,
    /// `output_failed`.
    OutputFailed,
}

impl StatusKind {
    /// The name written in outputs: `completed`, `diverged`, `interrupted` or `output_failed`.
    pub fn name(self) -> &'static str {
        match self {
            StatusKind::Completed => "completed",
            StatusKind::Diverged => "diverged",
            StatusKind::Interrupted => "interrupted",
            StatusKind::OutputFailed => "output_failed",
        }
    }
}

impl std::fmt::Display for StatusKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl RunStatus {
    /// The kind of ending, without its details.
    pub fn kind(&self) -> StatusKind {
        match self {
            RunStatus::Completed => StatusKind::Completed,
            RunStatus::Diverged(_) => StatusKind::Diverged,
            RunStatus::Interrupted => StatusKind::Interrupted,
            RunStatus::OutputFailed(_) => StatusKind::OutputFailed,
        }
    }

    /// "completed", "diverged", "interrupted" or "output_failed".
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }
}

/// How a run ended, with its time series.
pub struct RunRecord {
    /// How the run ended.
    pub status: RunStatus,
    /// The per-step history, bounded in memory: it dereferences to the retained samples
    /// (`&[StepSample]`, every step until it is full, then evenly thinned) and keeps exact
    /// running integrals and extremes of every step; see [`History`].
    pub samples: History,
    /// Time of release (coupled cases) or of the end of spin-up (forced); 0 for static.
    pub t_release: f64,
    /// Cells of the grid.
    pub cells: usize,
    /// A static plate's recirculation length at the end of the run (chords; see
    /// `FlowSolver::recirculation_length`).
    pub recirculation_length: Option<f64>,
}
