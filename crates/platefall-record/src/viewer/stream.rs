//! The recording stream of a run and its sinks (the .rrd file, --serve and its --web viewer,
//! --connect, --spawn), whatever its scene: opened before the run, committed after it.
use std::path::PathBuf;
use std::sync::atomic::Ordering;
use std::sync::Arc;
use std::time::Duration;

use anyhow::Context as _;
use rerun::RecordingStream;

use super::layout::APPLICATION_ID;
use super::rrd_file::{commit_file, RrdFile, FLUSH_LIMIT};
use super::sinks::{open_sinks, ConnectStats};
use super::web::WebServer;
use crate::messages::ConnectReport;
use crate::options::RecordOptions;
use crate::output::OutputError;

/// What the viewer side produced, after `Viewer::finish`.
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
