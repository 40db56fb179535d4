//! Stand-in for the Rerun side of a recording when platefall is built without the `viewer`
//! feature: nothing can be opened, so every sink option is refused before a run starts
//! (`src/cli/record_args.rs`), and the logger records CSV and progress only.
use std::path::{Path, PathBuf};

use super::messages::{ConnectReport, RecordingError, RunInfo, RunOutcome, ViewerRefusal};
use super::options::RecordOptions;
use super::output::OutputError;
use platefall_core::sim::{FieldSnapshot, StepSample};
use platefall_post::phase::DiagramData;

/// Recordings cannot be read in this build.
pub fn read_recording(
    _path: &Path,
) -> Result<crate::recorded::Recorded, crate::recorded::ReadError> {
    Err(crate::recorded::ReadError::NoViewer)
}

/// This build cannot record for Rerun.
pub const AVAILABLE: bool = false;

/// This build cannot serve the web viewer.
pub const WEB_AVAILABLE: bool = false;

/// A --serve server (none can exist in this build).
pub enum LiveServer {}

impl LiveServer {
    /// Shuts the server down (never called: there is none).
    pub fn shut_down(self) {
        match self {}
    }
}

/// What the viewer side produced (nothing, in this build).
pub struct ViewerReport {
    /// The finalised .rrd file and its size in bytes (always None here).
    pub rrd: Option<(PathBuf, u64)>,
    /// What the --connect / --spawn stream did (always None here).
    pub connect: Option<ConnectReport>,
    /// The --serve server (always None here).
    pub server: Option<LiveServer>,
    /// Warnings for the end-of-run report.
    pub notes: Vec<String>,
}

/// No recording stream can be opened in this build.
pub enum Viewer {}

impl Viewer {
    /// Fails: this build cannot open a recording stream.
    pub fn open(_opts: &RecordOptions, _info: &RunInfo) -> anyhow::Result<Viewer> {
        anyhow::bail!("this platefall was built without the `viewer` feature")
    }
    /// Logs one step (unreachable: no `Viewer` exists).
    pub fn step(&mut self, _s: StepSample) -> Result<(), RecordingError> {
        match *self {}
    }
    /// Paints and logs a snapshot (unreachable).
    pub fn field(&mut self, _f: &FieldSnapshot, _skipped: u64) -> Result<bool, RecordingError> {
        match *self {}
    }
    /// Sends waiting steps while the logger is idle (unreachable).
    pub fn idle(&mut self) -> Result<(), RecordingError> {
        match *self {}
    }
    /// The live-stream counters so far (unreachable).
    pub fn connect_report(&self) -> Option<ConnectReport> {
        match *self {}
    }
    /// The first write error of the .rrd file so far (unreachable).
    pub fn output_error(&self) -> Option<OutputError> {
        match *self {}
    }
    /// Checks that the .rrd file is still on disk (unreachable).
    pub fn check_outputs(&self) -> Option<OutputError> {
        match *self {}
    }
    /// Logs the outcome and commits the outputs (unreachable).
    pub fn finish(self, _o: &RunOutcome, _stats: &str, _errors: &mut Vec<String>) -> ViewerReport {
        match self {}
    }
}

/// Stand-in for the 3-D recording: cannot be opened.
pub enum Viewer3 {}

impl Viewer3 {
    /// Refuses: no viewer in this build.
    pub fn open(
        _opts: &RecordOptions,
        _info: &crate::messages3::RunInfo3,
    ) -> anyhow::Result<Viewer3> {
        anyhow::bail!("this platefall was built without the `viewer` feature")
    }
    /// Never called.
    pub fn step(&mut self, _s: &crate::messages3::Step3) -> Result<(), RecordingError> {
        match *self {}
    }
    /// Never called.
    pub fn field(
        &mut self,
        _f: &platefall_core::flow3d::FieldSnapshot3,
    ) -> Result<(), RecordingError> {
        match *self {}
    }
    /// Never called.
    pub fn finish(self, _o: &RunOutcome, _errors: &mut Vec<String>) -> ViewerReport {
        match self {}
    }
}

/// Refuses every --serve memory limit: this build has no viewer.
///
/// # Errors
///
/// Always: [`ViewerRefusal`] "this build has no viewer".
pub fn check_memory_limit(_limit: &str) -> Result<(), ViewerRefusal> {
    Err(ViewerRefusal("this build has no viewer".into()))
}

/// Refuses every --connect URL: this build has no viewer.
///
/// # Errors
///
/// Always: [`ViewerRefusal`] "this build has no viewer".
pub fn check_proxy_url(_url: &str) -> Result<(), ViewerRefusal> {
    Err(ViewerRefusal("this build has no viewer".into()))
}

/// An ensemble's members overlaid in a recording: nothing is written in this build (`None`).
pub fn write_ensemble_recording(
    _path: &Path,
    _title: &str,
    _traces: &[platefall_post::ensemble::MemberTrace],
    _table: &str,
) -> Result<Option<(PathBuf, u64)>, OutputError> {
    Ok(None)
}

/// A sweep's phase diagram as a recording: nothing is written in this build (`None`).
pub fn write_phase_recording(
    _path: &Path,
    _data: &DiagramData,
) -> Result<Option<(PathBuf, u64)>, OutputError> {
    Ok(None)
}
