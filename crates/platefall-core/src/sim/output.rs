//! What a run produces, as the solver's own plain-data types: one sample per step, field
//! snapshots, and how the run ended. Nothing here knows about files or viewers.
use super::history::History;
use crate::flow::Frame;

/// One time step's scalars.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepSample {
    pub step: u64,
    /// Convective time t U / c at the end of the step.
    pub t: f64,
    /// The step just taken.
    pub dt: f64,
    /// Lift, drag, moment coefficients on the reference speed (SPEC §5).
    pub cl: f64,
    pub cd: f64,
    pub cm: f64,
    /// Plate centre in the inertial frame (Y up) and pitch angle θ (CCW positive).
    pub x: f64,
    pub y: f64,
    pub theta: f64,
    /// Inertial velocity of the centre and pitch rate θ̇.
    pub xdot: f64,
    pub ydot: f64,
    pub omega: f64,
    /// Derived: speed V, flight-path angle γ = atan2(Ẏ, Ẋ), angle of attack α = θ − γ (wrapped to (−π, π]).
    pub speed: f64,
    pub gamma: f64,
    pub alpha: f64,
}

/// A flow snapshot on the MAC grid.
///
/// Velocities are the **inertial** velocity components along the body axes (SPEC §3).
#[derive(Clone, Debug)]
pub struct FieldSnapshot {
    pub step: u64,
    pub t: f64,
    /// Plate pose at this instant: centre (X, Y) and θ.
    pub x: f64,
    pub y: f64,
    pub theta: f64,
    /// The plate's motion in body axes: the grid-point velocity is g = (u0 − θ̇ y, v0 + θ̇ x).
    pub frame: Frame,
    /// x-velocity on vertical faces (xn[i], yc[j]); length (nx + 1) * ny, index i + (nx + 1) * j.
    pub u: Vec<f64>,
    /// y-velocity on horizontal faces (xc[i], yn[j]); length nx * (ny + 1), index i + nx * j.
    pub v: Vec<f64>,
    /// Pressure at cell centres; length nx * ny, index i + nx * j. Zero far away.
    pub p: Vec<f64>,
}

/// How a run ended.
#[derive(Clone, Debug, PartialEq)]
pub enum RunStatus {
    Completed,
    /// The solution blew up; the message says where and when.
    Diverged(String),
    /// Stopped from outside (the observer asked to stop: Ctrl-C).
    Interrupted,
    /// Stopped because an output could not be written (disk full, file removed, …); the message
    /// names the output.
    OutputFailed(String),
}

impl RunStatus {
    /// "completed", "diverged", "interrupted" or "output_failed".
    pub fn name(&self) -> &'static str {
        match self {
            RunStatus::Completed => "completed",
            RunStatus::Diverged(_) => "diverged",
            RunStatus::Interrupted => "interrupted",
            RunStatus::OutputFailed(_) => "output_failed",
        }
    }
}

/// How a run ended, with its time series.
pub struct RunRecord {
    pub status: RunStatus,
    /// The per-step history, bounded in memory: it dereferences to the retained samples
    /// (`&[StepSample]`, every step until it is full, then evenly thinned) and keeps exact
    /// running integrals and extremes of every step; see [`History`].
    pub samples: History,
    /// Time of release (coupled cases) or of the end of spin-up (forced); 0 for static.
    pub t_release: f64,
    pub cells: usize,
    /// A static plate's recirculation length at the end of the run (chords; see
    /// `FlowSolver::recirculation_length`).
    pub recirculation_length: Option<f64>,
}
