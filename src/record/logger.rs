//! The logger thread and its handle ([`Logger`]); see `record/mod.rs` for the contract.
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::Duration;

use anyhow::Context as _;
use crossbeam_channel::{bounded, Receiver, RecvTimeoutError, Sender, TrySendError};
use rerun::RecordingStream;

use super::csv::CsvWriter;
use super::messages::{FieldSnapshot, Message, RunInfo, RunOutcome, RunStatus, StepSample};
use super::options::RecordOptions;
use super::progress::Progress;
use super::scene::Scene;
use super::sinks::{open_sinks, ConnectStats};

/// Rerun application id of every recording.
pub const APPLICATION_ID: &str = "platefall";

/// State shared by the solver-side handle and the logger thread.
#[derive(Debug, Default)]
struct Shared {
    fields_in_flight: AtomicUsize,
    fields_skipped: AtomicU64,
    /// Held by the logger thread while it handles a message; see [`Logger::pause`].
    gate: Mutex<()>,
}

/// The solver's handle on the logger thread. Created by [`spawn_logger`].
///
/// Dropping it without [`Logger::finish`] (an error path or a panic) still stops the thread and
/// finalises every sink, recording the run as interrupted.
pub struct Logger {
    tx: Option<Sender<Message>>,
    thread: Option<JoinHandle<anyhow::Result<LoggerReport>>>,
    shared: Arc<Shared>,
    field_every: f64,
    next_field_t: f64,
    max_fields_in_flight: usize,
}

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

/// The result of a finished logger: counts, outputs, and (with --serve) the live server.
pub struct LoggerReport {
    /// Steps received (all of them are in the recording and the CSV).
    pub steps: u64,
    /// Field snapshots painted and recorded.
    pub fields_logged: u64,
    /// Field snapshots dropped because the logger was behind.
    pub fields_skipped: u64,
    /// The finalised .rrd file and its size in bytes.
    pub rrd: Option<(PathBuf, u64)>,
    /// The CSV file and its number of data rows.
    pub csv: Option<(PathBuf, u64)>,
    /// URL of the --serve server.
    pub serve_url: Option<String>,
    pub connect: Option<ConnectReport>,
    /// Warnings for the end-of-run report (part of [`LoggerReport::lines`]; problems found when
    /// the sinks were opened were also printed then).
    pub notes: Vec<String>,
    /// Keeps the --serve server alive after the run; dropped by `serve_until_interrupted`.
    server: Option<RecordingStream>,
}

impl std::fmt::Debug for LoggerReport {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LoggerReport")
            .field("steps", &self.steps)
            .field("fields_logged", &self.fields_logged)
            .field("fields_skipped", &self.fields_skipped)
            .field("rrd", &self.rrd)
            .field("csv", &self.csv)
            .field("serve_url", &self.serve_url)
            .field("connect", &self.connect)
            .field("notes", &self.notes)
            .field("serving", &self.server.is_some())
            .finish()
    }
}

impl LoggerReport {
    /// True while the --serve server is up (until `serve_until_interrupted` returns).
    pub fn is_serving(&self) -> bool {
        self.server.is_some()
    }

    /// Human-readable lines for the end-of-run report.
    pub fn lines(&self) -> Vec<String> {
        let mut out = Vec::new();
        if let Some((path, bytes)) = &self.rrd {
            out.push(format!(
                "recording: {} ({:.1} MB, {} steps, {} field snapshots{})",
                path.display(),
                *bytes as f64 / 1e6,
                self.steps,
                self.fields_logged,
                if self.fields_skipped > 0 {
                    format!(", {} skipped", self.fields_skipped)
                } else {
                    String::new()
                }
            ));
        } else if self.fields_skipped > 0 {
            out.push(format!("field snapshots skipped: {}", self.fields_skipped));
        }
        if let Some((path, rows)) = &self.csv {
            out.push(format!("csv: {} ({rows} rows)", path.display()));
        }
        if let Some(url) = &self.serve_url {
            out.push(format!("served at {url}"));
        }
        if let Some(c) = self.connect.as_ref().filter(|c| c.ever_connected) {
            out.push(format!(
                "streamed to {}: {} messages sent, {} dropped",
                c.url, c.sent, c.dropped
            ));
        }
        out.extend(self.notes.iter().cloned());
        out
    }

    /// With --serve: keeps the server up until `stop` becomes true (set it from a Ctrl-C handler),
    /// so a viewer that connects late still receives the whole run (within the server's memory
    /// limit); then shuts it down. Returns at once if not serving or if `stop` is already set.
    pub fn serve_until_interrupted(mut self, stop: &AtomicBool) -> anyhow::Result<()> {
        let Some(server) = self.server.take() else {
            return Ok(());
        };
        if !stop.load(Ordering::SeqCst) {
            eprintln!(
                "platefall: run finished; still serving it at {} (open it with `rerun {}`). Press Ctrl-C to stop.",
                self.serve_url.as_deref().unwrap_or("?"),
                self.serve_url.as_deref().unwrap_or("?"),
            );
            while !stop.load(Ordering::SeqCst) {
                std::thread::sleep(Duration::from_millis(100));
            }
        }
        let _ = server.flush_with_timeout(Duration::from_secs(2));
        drop(server);
        Ok(())
    }

    /// Shuts a --serve server down now (same as `serve_until_interrupted` with `stop` set).
    pub fn stop_serving(&mut self) {
        self.server.take();
    }
}

/// Starts the logger thread: opens every sink (an error here means nothing was started), writes
/// the static parts of the recording, and returns the solver's handle.
pub fn spawn_logger(opts: RecordOptions, info: RunInfo) -> anyhow::Result<Logger> {
    if !(opts.field_every.is_finite() && opts.field_every > 0.0) {
        anyhow::bail!(
            "--field-every {}: must be a finite number > 0",
            opts.field_every
        );
    }
    let csv = match &opts.csv {
        Some(path) => Some(CsvWriter::create(path)?),
        None => None,
    };
    let mut notes = Vec::new();
    let mut connect = None;
    let mut serve_url = None;
    let rec = if opts.has_rerun_sink() {
        let set = open_sinks(&opts)?;
        for n in &set.notes {
            eprintln!("platefall: warning: {n}");
        }
        notes.extend(set.notes);
        connect = set.connect;
        serve_url = set.serve_url;
        if let Some(url) = &serve_url {
            eprintln!("platefall: serving the run at {url} (open it with `rerun {url}`)");
        }
        let rec = rerun::RecordingStreamBuilder::new(APPLICATION_ID)
            .recording_name(info.title.clone())
            .enabled(true)
            .set_sinks(set.sinks)
            .context("cannot start the Rerun recording")?;
        rec.set_log_tick_enabled(false);
        rec.set_log_time_enabled(false);
        super::blueprint::default_blueprint()
            .send(&rec, rerun::blueprint::BlueprintActivation::default())
            .context("cannot send the viewer layout")?;
        Some(rec)
    } else {
        None
    };

    let (tx, rx) = bounded(opts.channel_capacity.max(2));
    let shared = Arc::new(Shared::default());
    let field_every = opts.field_every;
    let max_fields_in_flight = opts.max_fields_in_flight;
    let thread = {
        let shared = shared.clone();
        std::thread::Builder::new()
            .name("platefall-logger".into())
            .spawn(move || {
                run_logger(LoggerThread {
                    rx,
                    shared,
                    opts,
                    info,
                    rec,
                    csv,
                    connect,
                    serve_url,
                    notes,
                })
            })
            .context("cannot start the logger thread")?
    };
    Ok(Logger {
        tx: Some(tx),
        thread: Some(thread),
        shared,
        field_every,
        next_field_t: f64::NEG_INFINITY,
        max_fields_in_flight,
    })
}

impl Logger {
    /// Convective time between field snapshots (`--field-every`).
    pub fn field_every(&self) -> f64 {
        self.field_every
    }

    /// The field cadence: true if a snapshot is due at simulated time `t` (the first call always
    /// is; then at every multiple of `field_every`). A true answer advances the cadence, so ask
    /// once per step and, when true, build a snapshot and [`offer_field`](Self::offer_field) it.
    pub fn field_due(&mut self, t: f64) -> bool {
        let fe = self.field_every;
        let eps = 1e-9 * fe.max(1.0);
        if t + eps >= self.next_field_t {
            self.next_field_t = ((t + eps) / fe).floor() * fe + fe;
            true
        } else {
            false
        }
    }

    /// Sends one step (blocking when the channel is full: time series are never dropped).
    /// Fails only if the logger thread has stopped.
    pub fn step(&self, sample: StepSample) -> anyhow::Result<()> {
        let tx = self.tx.as_ref().context("the logger has finished")?;
        tx.send(Message::Step(sample))
            .map_err(|_| anyhow::anyhow!("the logger thread stopped unexpectedly"))
    }

    /// Offers a field snapshot without blocking. Returns false (and counts it as skipped) when
    /// the logger is behind: the channel is full or `max_fields_in_flight` snapshots are queued.
    pub fn offer_field(&self, snapshot: FieldSnapshot) -> bool {
        let Some(tx) = self.tx.as_ref() else {
            return false;
        };
        let skip = || {
            self.shared.fields_skipped.fetch_add(1, Ordering::Relaxed);
            false
        };
        if self.shared.fields_in_flight.load(Ordering::Acquire) >= self.max_fields_in_flight {
            return skip();
        }
        self.shared.fields_in_flight.fetch_add(1, Ordering::AcqRel);
        match tx.try_send(Message::Field(Box::new(snapshot))) {
            Ok(()) => true,
            Err(TrySendError::Full(_)) | Err(TrySendError::Disconnected(_)) => {
                self.shared.fields_in_flight.fetch_sub(1, Ordering::AcqRel);
                skip()
            }
        }
    }

    /// Field snapshots skipped so far.
    pub fn skipped_fields(&self) -> u64 {
        self.shared.fields_skipped.load(Ordering::Relaxed)
    }

    /// Ends the run: sends the outcome, waits for the logger to write everything, finalises
    /// every sink (the .rrd footer), flushes the CSV, and returns the report. With --serve the
    /// server is still up afterwards; see [`LoggerReport::serve_until_interrupted`].
    pub fn finish(mut self, outcome: RunOutcome) -> anyhow::Result<LoggerReport> {
        let tx = self.tx.take().context("the logger has finished")?;
        let _ = tx.send(Message::Finish(outcome));
        drop(tx);
        self.join()
    }

    fn join(&mut self) -> anyhow::Result<LoggerReport> {
        let thread = self.thread.take().context("the logger has finished")?;
        match thread.join() {
            Ok(result) => result,
            Err(_) => Err(anyhow::anyhow!("the logger thread panicked")),
        }
    }

    /// Test hook: while the returned guard lives, the logger thread handles no message, so the
    /// channel fills up. Not for production use.
    #[doc(hidden)]
    pub fn pause(&self) -> MutexGuard<'_, ()> {
        self.shared.gate.lock().unwrap_or_else(|e| e.into_inner())
    }
}

impl Drop for Logger {
    fn drop(&mut self) {
        if let Some(tx) = self.tx.take() {
            // No outcome: the thread sees the channel close and finalises as interrupted.
            drop(tx);
            if let Err(e) = self.join() {
                eprintln!("platefall: warning: recording not finished cleanly: {e:#}");
            }
        }
    }
}

struct LoggerThread {
    rx: Receiver<Message>,
    shared: Arc<Shared>,
    opts: RecordOptions,
    info: RunInfo,
    rec: Option<RecordingStream>,
    csv: Option<CsvWriter>,
    connect: Option<(String, Arc<ConnectStats>)>,
    serve_url: Option<String>,
    notes: Vec<String>,
}

fn run_logger(t: LoggerThread) -> anyhow::Result<LoggerReport> {
    let LoggerThread {
        rx,
        shared,
        opts,
        info,
        rec,
        mut csv,
        connect,
        serve_url,
        mut notes,
    } = t;
    let mut errors: Vec<String> = Vec::new();
    let mut progress = Progress::new(opts.progress, opts.t_end);
    let mut scene = match &rec {
        Some(rec) => match Scene::start(rec.clone(), &info, &opts) {
            Ok(s) => Some(s),
            Err(e) => {
                errors.push(format!("recording: {e}"));
                None
            }
        },
        None => None,
    };
    let mut steps = 0u64;
    let mut fields = 0u64;

    let outcome = loop {
        let msg = match rx.recv_timeout(Duration::from_millis(200)) {
            Ok(m) => m,
            Err(RecvTimeoutError::Timeout) => {
                progress.tick();
                if let Some(s) = &mut scene {
                    if let Err(e) = s.flush_if_stale() {
                        errors.push(format!("recording: {e}"));
                        scene = None;
                    }
                }
                continue;
            }
            Err(RecvTimeoutError::Disconnected) => {
                break RunOutcome {
                    status: RunStatus::Interrupted,
                    summary_json: "{}".into(),
                    report:
                        "The solver stopped without reporting an outcome (an error or a panic); \
                             the recording ends at the last step received."
                            .into(),
                };
            }
        };
        let _gate = shared.gate.lock().unwrap_or_else(|e| e.into_inner());
        match msg {
            Message::Start(_) => {} // spawn_logger already has the RunInfo
            Message::Step(s) => {
                steps += 1;
                progress.update(&s);
                if let Some(w) = &mut csv {
                    if let Err(e) = w.write(&s) {
                        errors.push(format!("{e:#}"));
                        csv = None;
                    }
                }
                if let Some(sc) = &mut scene {
                    if let Err(e) = sc.step(s) {
                        errors.push(format!("recording: {e}"));
                        scene = None;
                    }
                }
            }
            Message::Field(f) => {
                shared.fields_in_flight.fetch_sub(1, Ordering::AcqRel);
                if let Some(sc) = &mut scene {
                    let skipped = shared.fields_skipped.load(Ordering::Relaxed);
                    match sc.field(&f, skipped) {
                        Ok(true) => fields += 1,
                        Ok(false) => {}
                        Err(e) => {
                            errors.push(format!("recording: {e}"));
                            scene = None;
                        }
                    }
                } else {
                    fields += 1;
                }
            }
            Message::Finish(o) => break o,
        }
    };

    // --- Finalise every sink, whatever happened above. ---
    let skipped = shared.fields_skipped.load(Ordering::Relaxed);
    let status_word = match &outcome.status {
        RunStatus::Completed => "completed",
        RunStatus::Diverged(_) => "diverged",
        RunStatus::Interrupted => "interrupted",
    };
    progress.finish(status_word);

    let connect_report = connect.as_ref().map(|(url, st)| ConnectReport {
        url: url.clone(),
        sent: st.sent.load(Ordering::Relaxed),
        dropped: st.dropped.load(Ordering::Relaxed),
        ever_connected: st.ever_connected.load(Ordering::Relaxed),
    });
    if let Some(sc) = &mut scene {
        let mut stats = format!(
            "- steps recorded: {steps}\n- field snapshots recorded: {fields} (every {} c/U)\n\
             - field snapshots skipped because the logger fell behind: {skipped}\n",
            opts.field_every
        );
        if let Some(c) = &connect_report {
            stats.push_str(&format!(
                "- live stream to {}: {} messages dropped\n",
                c.url, c.dropped
            ));
        }
        if let Err(e) = sc.finish(&outcome, &stats) {
            errors.push(format!("recording: {e}"));
        }
    }
    drop(scene);

    let csv_out = match csv.take() {
        Some(w) => match w.finish() {
            Ok(r) => Some(r),
            Err(e) => {
                errors.push(format!("{e:#}"));
                None
            }
        },
        None => None,
    };

    let mut server = None;
    let mut rrd = None;
    if let Some(rec) = rec {
        // Everything down the sinks, then the file's footer (drops only the file sink).
        let _ = rec.flush_with_timeout(Duration::from_secs(30));
        rec.finalize_deferred_sinks();
        if let Some(path) = &opts.save {
            match std::fs::metadata(path) {
                Ok(m) if m.len() > 0 => rrd = Some((path.clone(), m.len())),
                Ok(_) => errors.push(format!("--save {}: the file is empty", path.display())),
                Err(e) => errors.push(format!("--save {}: {e}", path.display())),
            }
        }
        if serve_url.is_some() && errors.is_empty() {
            server = Some(rec);
        } else {
            drop(rec);
        }
    }
    if let Some(c) = &connect_report {
        let file_note = if rrd.is_some() {
            " (the .rrd file is complete)"
        } else {
            ""
        };
        if !c.ever_connected {
            notes.push(format!(
                "--connect {}: no viewer was reachable; nothing was streamed there{file_note}",
                c.url
            ));
        } else if c.dropped > 0 {
            notes.push(format!(
                "--connect {}: the viewer did not keep up; {} messages were dropped for it{file_note}",
                c.url, c.dropped
            ));
        }
    }

    if !errors.is_empty() {
        anyhow::bail!("{}", errors.join("; "));
    }
    Ok(LoggerReport {
        steps,
        fields_logged: fields,
        fields_skipped: skipped,
        rrd,
        csv: csv_out,
        serve_url,
        connect: connect_report,
        notes,
        server,
    })
}
