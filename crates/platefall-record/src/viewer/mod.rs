//! The Rerun side of a recording (cargo feature `viewer`, on by default): the sinks (file,
//! `--serve` and its `--web` viewer, `--connect`, `--spawn`), the scene (entities, documented in the crate docs (`lib.rs`)) and the
//! default blueprint (sent by the scene when it starts). The logger thread drives a [`Viewer`]
//! and knows nothing of Rerun. Also a sweep's phase diagram as a recording
//! ([`write_phase_recording`]).
mod blueprint;
mod curves;
mod images;
mod layout;
mod phase;
mod polar;
mod read;
mod rrd_file;
mod scene;
mod section;
mod sinks;
mod space;
mod statics;
mod text;
mod view_properties;
mod wake;
mod web;

use std::path::PathBuf;
use std::str::FromStr as _;
use std::sync::atomic::Ordering;
use std::sync::Arc;
use std::time::Duration;

use anyhow::Context as _;
use rerun::RecordingStream;

use super::messages::{ConnectReport, RecordingError, RunInfo, RunOutcome, ViewerRefusal};
use super::options::RecordOptions;
use super::output::OutputError;
pub use layout::{paths, APPLICATION_ID};
pub use phase::write_phase_recording;
use platefall_core::sim::{FieldSnapshot, StepSample};
pub use read::read_recording;
use rrd_file::{commit_file, RrdFile, FLUSH_LIMIT};
use scene::Scene;
use sinks::{open_sinks, ConnectStats};
pub use space::{paths3, Viewer3};
use web::WebServer;
pub use web::WEB_AVAILABLE;

/// This build can record for Rerun.
pub const AVAILABLE: bool = true;

/// What the viewer side produced, after [`Viewer::finish`].
pub struct ViewerReport {
    /// The finalised .rrd file and its size in bytes.
    pub rrd: Option<(PathBuf, u64)>,
    /// What the --connect / --spawn stream did (None without one).
    pub connect: Option<ConnectReport>,
    /// The --serve server, still up (None if not serving or after an error).
    pub server: Option<LiveServer>,
    /// Warnings for the end-of-run report.
    pub notes: Vec<String>,
}

/// A --serve server (and the --web viewer reading from it) kept up after the run so that late
/// viewers still get the whole run.
pub struct LiveServer {
    rec: RecordingStream,
    /// Serves the web viewer until dropped.
    _web: Option<WebServer>,
}

impl LiveServer {
    /// Flushes to connected viewers (at most 2 s) and shuts the servers down.
    pub fn shut_down(self) {
        let _ = self.rec.flush_with_timeout(Duration::from_secs(2));
    }
}

/// The recording stream of one run and its sinks (file, --serve, --web, --connect), whatever
/// its scene.
pub(crate) struct Stream {
    rec: RecordingStream,
    rrd: Option<Arc<RrdFile>>,
    serving: bool,
    web: Option<WebServer>,
    connect: Option<(String, Arc<ConnectStats>)>,
    notes: Vec<String>,
}

impl Stream {
    /// Opens every sink asked for in `opts` and the recording named `title`. An error here
    /// means nothing was started.
    pub(crate) fn open(opts: &RecordOptions, title: &str) -> anyhow::Result<Stream> {
        let set = open_sinks(opts)?;
        for n in &set.notes {
            eprintln!("platefall: warning: {n}");
        }
        if let Some(url) = &set.serve_url {
            eprintln!("platefall: serving the run at {url} (open it with `rerun {url}`)");
        }
        if let Some(url) = opts.serve.as_ref().and_then(|s| s.web_url()) {
            eprintln!("platefall: web viewer at {url} (open it in a browser)");
        }
        let mut builder = rerun::RecordingStreamBuilder::new(APPLICATION_ID);
        if let Some(id) = &opts.recording_id {
            builder = builder.recording_id(id.clone());
        }
        let rec = builder
            .recording_name(title.to_owned())
            .enabled(true)
            .set_sinks(set.sinks)
            .context("cannot start the Rerun recording")?;
        rec.set_log_tick_enabled(false);
        rec.set_log_time_enabled(false);
        Ok(Stream {
            rec,
            rrd: set.rrd,
            serving: set.serve_url.is_some(),
            web: set.web,
            connect: set.connect,
            notes: set.notes,
        })
    }

    /// The recording stream (scenes log through a clone).
    pub(crate) fn rec(&self) -> &RecordingStream {
        &self.rec
    }

    /// The live-stream counters so far.
    pub(crate) fn connect_report(&self) -> Option<ConnectReport> {
        self.connect.as_ref().map(|(url, st)| ConnectReport {
            url: url.clone(),
            sent: st.sent.load(Ordering::Relaxed),
            dropped: st.dropped.load(Ordering::Relaxed),
            ever_connected: st.ever_connected.load(Ordering::Relaxed),
        })
    }

    /// The first write error of the .rrd file so far (cheap).
    pub(crate) fn output_error(&self) -> Option<OutputError> {
        self.rrd.as_ref().and_then(|f| f.error())
    }

    /// Checks that the .rrd file being written is still on disk.
    pub(crate) fn check_outputs(&self) -> Option<OutputError> {
        self.rrd.as_ref().and_then(|f| f.check())
    }

    /// Commits the file (footer, sync, rename) and keeps the --serve server up unless an error
    /// happened (`errors` holds what went wrong, and gains the file's own error).
    pub(crate) fn finish(mut self, errors: &mut Vec<String>) -> ViewerReport {
        let rrd = match self.rrd.take() {
            Some(file) => commit_file(&self.rec, &file)
                .map_err(|e| errors.push(e.to_string()))
                .ok(),
            None => {
                let _ = self.rec.flush_with_timeout(FLUSH_LIMIT);
                None
            }
        };
        let connect = self.connect_report();
        let mut notes = self.notes;
        if let Some(c) = &connect {
            notes.extend(connect_note(c, rrd.is_some()));
        }
        let server = (self.serving && errors.is_empty()).then(|| LiveServer {
            rec: self.rec,
            _web: self.web,
        });
        ViewerReport {
            rrd,
            connect,
            server,
            notes,
        }
    }
}

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

/// A note for the report when the --connect viewer missed messages.
fn connect_note(c: &ConnectReport, file_complete: bool) -> Option<String> {
    let file_note = if file_complete {
        " (the .rrd file is complete)"
    } else {
        ""
    };
    if !c.ever_connected {
        Some(format!(
            "--connect {}: no viewer was reachable; nothing was streamed there{file_note}",
            c.url
        ))
    } else if c.dropped > 0 {
        Some(format!(
            "--connect {}: the viewer did not keep up; {} messages were dropped for it{file_note}",
            c.url, c.dropped
        ))
    } else {
        None
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
