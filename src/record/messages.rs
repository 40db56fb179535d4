//! Plain-data messages from the solver thread to the logger thread.
//!
//! Nothing here knows about Rerun: the solver fills these, `record::logger` turns them into Rerun.
use std::sync::Arc;

/// Everything about a run that does not change while it runs; sent once, first.
#[derive(Clone, Debug)]
pub struct RunInfo {
    /// "static" | "forced" | "pinned" | "free".
    pub case: String,
    /// One-line human description, e.g. "free fall, card preset, Re 4770, N=32".
    pub title: String,
    /// The full resolved configuration as pretty JSON (enough to reproduce the run).
    pub config_json: String,
    /// The command line as typed (argv joined with shell quoting).
    pub command_line: String,
    /// Program version (`CARGO_PKG_VERSION` plus git describe when known).
    pub version: String,
    /// Plate thickness as a fraction of the chord (the plate is the rectangle
    /// [-0.5, 0.5] x [-t/2, t/2] in body coordinates, chord = 1).
    pub thickness: f64,
    /// Body-fixed grid geometry shared by every field snapshot.
    pub grid: Arc<GridGeometry>,
}

/// The body-fixed stretched Cartesian grid (SPEC §4), in chord units, body axes.
///
/// Layout is row-major with x fastest: cell (i, j) has index `i + nx * j`.
#[derive(Clone, Debug)]
pub struct GridGeometry {
    /// Node (cell-face) x coordinates, length nx + 1, increasing.
    pub xn: Vec<f64>,
    /// Node (cell-face) y coordinates, length ny + 1, increasing.
    pub yn: Vec<f64>,
    /// true where the cell is inside the plate (solid), length nx * ny.
    pub solid: Vec<bool>,
}

impl GridGeometry {
    pub fn nx(&self) -> usize {
        self.xn.len() - 1
    }
    pub fn ny(&self) -> usize {
        self.yn.len() - 1
    }
}

/// One time step's scalars; sent every step, never dropped.
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

/// A flow snapshot on the MAC grid; sent at the field cadence, may be thinned.
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
    /// Translation velocity of the plate centre in body axes (ẋ₀cosθ + ẏ₀sinθ, −ẋ₀sinθ + ẏ₀cosθ)
    /// and pitch rate θ̇: the grid-point velocity is g = (gx0 − θ̇ y, gy0 + θ̇ x).
    pub gx0: f64,
    pub gy0: f64,
    pub omega: f64,
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
    /// Ctrl-C (SIGINT/SIGTERM).
    Interrupted,
}

/// Sent once, last.
#[derive(Clone, Debug)]
pub struct RunOutcome {
    pub status: RunStatus,
    /// The summary JSON (pretty) as written by `--summary`.
    pub summary_json: String,
    /// The human-readable end-of-run report (markdown-ish plain text).
    pub report: String,
}

#[derive(Clone, Debug)]
pub enum Message {
    Start(RunInfo),
    Step(StepSample),
    Field(Box<FieldSnapshot>),
    Finish(RunOutcome),
}
