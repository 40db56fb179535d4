//! The Rerun side of a recording (cargo feature `viewer`, on by default): the sinks (file,
//! `--serve` and its `--web` viewer, `--connect`, `--spawn`), the scene (entities, documented in the crate docs (`lib.rs`)) and the
//! default blueprint (sent by the scene when it starts). The logger thread drives a [`Viewer`]
//! and knows nothing of Rerun. Also a sweep's phase diagram as a recording
//! ([`write_phase_recording`]).
mod blueprint;
mod curves;
mod extent;
mod images;
mod layout;
mod legend;
mod members;
mod phase;
mod polar;
mod read;
mod rrd_file;
mod scene;
mod section;
mod sinks;
mod space;
mod statics;
mod stream;
mod text;
mod view_properties;
mod wake;
mod web;

use std::str::FromStr as _;

use anyhow::Context as _;

use super::messages::{ConnectReport, RecordingError, RunInfo, RunOutcome, ViewerRefusal};
use super::options::RecordOptions;
use super::output::OutputError;
pub use layout::{paths, APPLICATION_ID};
pub use members::write_ensemble_recording;
pub use phase::write_phase_recording;
use platefall_core::sim::{FieldSnapshot, StepSample};
pub use read::read_recording;
use scene::Scene;
pub use space::{paths3, Viewer3};
use stream::Stream;
pub use stream::{LiveServer, ViewerReport};
pub use web::WEB_AVAILABLE;

/// This build can record for Rerun.
pub const AVAILABLE: bool = true;

/// The recording stream of one run and its scene.
pub struct Viewer {
    stream: Stream,
    scene: Option<Scene>,
}

impl Viewer {
    /// Opens every sink asked for in `opts`, sends the blueprint and the static parts of the
    /// scene. An error here means nothing was started.
    pub fn open(opts: &RecordOptions, info: &RunInfo) -> anyhow::Result<Viewer> {
        let stream = Stream::open(opts, &info.title)?;
        let scene = Scene::start(stream.rec().clone(), info, opts).context("recording")?;
        Ok(Viewer {
            stream,
            scene: Some(scene),
        })
    }

    /// Runs `f` on the scene; after a recording error the scene is dropped and the error returned.
    fn with_scene<T: Default>(
        &mut self,
        f: impl FnOnce(&mut Scene) -> rerun::RecordingStreamResult<T>,
    ) -> Result<T, RecordingError> {
        let Some(scene) = &mut self.scene else {
            return Ok(T::default());
        };
        f(scene).map_err(|e| {
            self.scene = None;
            RecordingError(e.to_string())
        })
    }

    /// Logs one step.
    pub fn step(&mut self, s: StepSample) -> Result<(), RecordingError> {
        self.with_scene(|sc| sc.step(s))
    }

    /// Paints and logs a snapshot; false if it did not fit the grid (reported in the recording).
    pub fn field(&mut self, f: &FieldSnapshot, skipped: u64) -> Result<bool, RecordingError> {
        self.with_scene(|sc| sc.field(f, skipped))
    }

    /// Called when the logger is idle: sends steps that have waited long enough.
    pub fn idle(&mut self) -> Result<(), RecordingError> {
        self.with_scene(|sc| sc.flush_if_stale())
    }

    /// The live-stream counters so far.
    pub fn connect_report(&self) -> Option<ConnectReport> {
        self.stream.connect_report()
    }

    /// The first write error of the .rrd file so far (cheap).
    pub fn output_error(&self) -> Option<OutputError> {
        self.stream.output_error()
    }

    /// Checks that the .rrd file being written is still on disk.
    pub fn check_outputs(&self) -> Option<OutputError> {
        self.stream.check_outputs()
    }

    /// Logs the outcome and `stats_md`, commits the file (footer, sync, rename) and keeps the
    /// --serve server up unless an error happened (`errors` gains what went wrong).
    pub fn finish(
        mut self,
        outcome: &RunOutcome,
        stats_md: &str,
        errors: &mut Vec<String>,
    ) -> ViewerReport {
        if let Err(e) = self.with_scene(|sc| sc.finish(outcome, stats_md)) {
            errors.push(e.to_string());
        }
        self.scene = None;
        self.stream.finish(errors)
    }
}

/// Is `limit` a memory limit Rerun's server accepts ("25%", "2GB", "unlimited")?
pub fn check_memory_limit(limit: &str) -> Result<(), ViewerRefusal> {
    rerun::MemoryLimit::parse(limit)
        .map(|_| ())
        .map_err(ViewerRefusal)
}

/// Is `url` a Rerun proxy URL (`rerun+http://host:port/proxy`)?
pub fn check_proxy_url(url: &str) -> Result<(), ViewerRefusal> {
    rerun::external::re_uri::ProxyUri::from_str(url)
        .map(|_| ())
        .map_err(|e| ViewerRefusal(e.to_string()))
}
