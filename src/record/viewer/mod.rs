//! The Rerun side of a recording (cargo feature `viewer`, on by default): the sinks (file,
//! `--serve`, `--connect`, `--spawn`), the scene (entities, documented in `record/mod.rs`) and the
//! default blueprint (sent by the scene when it starts). The logger thread drives a [`Viewer`] and knows nothing of Rerun.
mod blueprint;
mod curves;
mod images;
mod layout;
mod polar;
mod scene;
mod sinks;
mod statics;
mod text;
mod view_properties;
mod wake;

use std::path::PathBuf;
use std::str::FromStr as _;
use std::sync::atomic::Ordering;
use std::sync::Arc;
use std::time::Duration;

use anyhow::Context as _;
use rerun::RecordingStream;

use super::messages::{RunInfo, RunOutcome};
use super::options::RecordOptions;
use crate::sim::{FieldSnapshot, StepSample};
pub use layout::paths;
use scene::Scene;
use sinks::{open_sinks, ConnectStats};

/// This build can record for Rerun.
pub const AVAILABLE: bool = true;

/// Rerun application id of every recording.
pub const APPLICATION_ID: &str = "platefall";

/// What a --connect / --spawn stream did.
#[derive(Clone, Debug, PartialEq)]
pub struct ConnectReport {
    pub url: String,
    /// Messages handed to the gRPC client.
    pub sent: u64,
    /// Messages dropped because the viewer did not keep up (or was not there).
    pub dropped: u64,
    /// True if a viewer was connected at some point.
    pub ever_connected: bool,
}

/// What the viewer side produced, after [`Viewer::finish`].
pub struct ViewerReport {
    /// The finalised .rrd file and its size in bytes.
    pub rrd: Option<(PathBuf, u64)>,
    pub connect: Option<ConnectReport>,
    /// The --serve server, still up (None if not serving or after an error).
    pub server: Option<LiveServer>,
    pub notes: Vec<String>,
}

/// A --serve server kept up after the run so that late viewers still get the whole run.
pub struct LiveServer(RecordingStream);

impl LiveServer {
    /// Flushes to connected viewers (at most 2 s) and shuts the server down.
    pub fn shut_down(self) {
        let _ = self.0.flush_with_timeout(Duration::from_secs(2));
    }
}

/// The recording stream of one run and its scene.
pub struct Viewer {
    rec: RecordingStream,
    scene: Option<Scene>,
    save: Option<PathBuf>,
    serving: bool,
    connect: Option<(String, Arc<ConnectStats>)>,
    notes: Vec<String>,
}

impl Viewer {
    /// Opens every sink asked for in `opts`, sends the blueprint and the static parts of the
    /// scene. An error here means nothing was started.
    pub fn open(opts: &RecordOptions, info: &RunInfo) -> anyhow::Result<Viewer> {
        let set = open_sinks(opts)?;
        for n in &set.notes {
            eprintln!("platefall: warning: {n}");
        }
        if let Some(url) = &set.serve_url {
            eprintln!("platefall: serving the run at {url} (open it with `rerun {url}`)");
        }
        let rec = rerun::RecordingStreamBuilder::new(APPLICATION_ID)
            .recording_name(info.title.clone())
            .enabled(true)
            .set_sinks(set.sinks)
            .context("cannot start the Rerun recording")?;
        rec.set_log_tick_enabled(false);
        rec.set_log_time_enabled(false);
        let scene = Scene::start(rec.clone(), info, opts).context("recording")?;
        Ok(Viewer {
            rec,
            scene: Some(scene),
            save: opts.save.clone(),
            serving: set.serve_url.is_some(),
            connect: set.connect,
            notes: set.notes,
        })
    }

    /// Runs `f` on the scene; after a recording error the scene is dropped and the error returned.
    fn with_scene<T: Default>(
        &mut self,
        f: impl FnOnce(&mut Scene) -> rerun::RecordingStreamResult<T>,
    ) -> Result<T, String> {
        let Some(scene) = &mut self.scene else {
            return Ok(T::default());
        };
        f(scene).map_err(|e| {
            self.scene = None;
            format!("recording: {e}")
        })
    }

    pub fn step(&mut self, s: StepSample) -> Result<(), String> {
        self.with_scene(|sc| sc.step(s))
    }

    /// Paints and logs a snapshot; false if it did not fit the grid (reported in the recording).
    pub fn field(&mut self, f: &FieldSnapshot, skipped: u64) -> Result<bool, String> {
        self.with_scene(|sc| sc.field(f, skipped))
    }

    /// Called when the logger is idle: sends steps that have waited long enough.
    pub fn idle(&mut self) -> Result<(), String> {
        self.with_scene(|sc| sc.flush_if_stale())
    }

    /// The live-stream counters so far.
    pub fn connect_report(&self) -> Option<ConnectReport> {
        self.connect.as_ref().map(|(url, st)| ConnectReport {
            url: url.clone(),
            sent: st.sent.load(Ordering::Relaxed),
            dropped: st.dropped.load(Ordering::Relaxed),
            ever_connected: st.ever_connected.load(Ordering::Relaxed),
        })
    }

    /// Logs the outcome and `stats_md`, finalises the file (its footer) and keeps the --serve
    /// server up unless an error happened (`errors` gains what went wrong).
    pub fn finish(
        mut self,
        outcome: &RunOutcome,
        stats_md: &str,
        errors: &mut Vec<String>,
    ) -> ViewerReport {
        if let Err(e) = self.with_scene(|sc| sc.finish(outcome, stats_md)) {
            errors.push(e);
        }
        self.scene = None;
        let _ = self.rec.flush_with_timeout(Duration::from_secs(30));
        self.rec.finalize_deferred_sinks();
        let rrd = self.save.as_ref().and_then(|path| file_size(path, errors));
        let connect = self.connect_report();
        let mut notes = self.notes;
        if let Some(c) = &connect {
            notes.extend(connect_note(c, rrd.is_some()));
        }
        let server = (self.serving && errors.is_empty()).then(|| LiveServer(self.rec));
        ViewerReport {
            rrd,
            connect,
            server,
            notes,
        }
    }
}

/// The size of the finalised file, or an error if it is missing or empty.
fn file_size(path: &PathBuf, errors: &mut Vec<String>) -> Option<(PathBuf, u64)> {
    match std::fs::metadata(path) {
        Ok(m) if m.len() > 0 => Some((path.clone(), m.len())),
        Ok(_) => {
            errors.push(format!("--save {}: the file is empty", path.display()));
            None
        }
        Err(e) => {
            errors.push(format!("--save {}: {e}", path.display()));
            None
        }
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
pub fn check_memory_limit(limit: &str) -> Result<(), String> {
    rerun::MemoryLimit::parse(limit).map(|_| ())
}

/// Is `url` a Rerun proxy URL (`rerun+http://host:port/proxy`)?
pub fn check_proxy_url(url: &str) -> Result<(), String> {
    rerun::external::re_uri::ProxyUri::from_str(url)
        .map(|_| ())
        .map_err(|e| e.to_string())
}
