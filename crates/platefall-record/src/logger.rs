//! The logger thread and its handle ([`Logger`]); see the crate docs (`lib.rs`) for the contract.
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use anyhow::Context as _;
use crossbeam_channel::{bounded, Receiver, RecvTimeoutError, Sender, TrySendError};

use super::cadence::Cadence;
use super::csv::CsvWriter;
use super::messages::{ConnectReport, FieldUse, Message, RecordingError, RunInfo, RunOutcome};
use super::options::RecordOptions;
use super::output::{LinkCheck, OutputError};
use super::progress::Progress;
use super::viewer::{LiveServer, Viewer};
use super::vtk::{VtkReport, VtkSeries};
use platefall_core::sim::{FieldSnapshot, RunStatus, StepSample};

/// State shared by the solver-side handle and the logger thread.
#[derive(Debug, Default)]
struct Shared {
    fields_in_flight: AtomicUsize,
    fields_skipped: AtomicU64,
    /// Held by the logger thread while it handles a message; see [`Logger::pause`].
    gate: Mutex<()>,
    /// The first output that could not be written: the solver stops at its next step.
    failure: Mutex<Option<String>>,
    failed: AtomicBool,
}

/// How often the logger checks that the files being written are still on disk.
const LINK_CHECK_EVERY: Duration = Duration::from_secs(1);

/// The solver's handle on the logger thread. Created by [`spawn_logger`].
///
/// Dropping it without [`Logger::finish`] (an error path or a panic) still stops the thread and
/// finalises every sink, recording the run as interrupted.
pub struct Logger {
    tx: Option<Sender<Message>>,
    thread: Option<JoinHandle<anyhow::Result<LoggerReport>>>,
    shared: Arc<Shared>,
    fields: Cadence,
    vtk: Option<Cadence>,
    /// What a snapshot offered now is for: as the last [`Logger::field_due`] decided (the
    /// recording only before the first).
    due: FieldUse,
    max_fields_in_flight: usize,
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
    /// The VTK series (`--vtk`): its collection, snapshots and bytes.
    pub vtk: Option<VtkReport>,
    /// URL of the --serve server.
    pub serve_url: Option<String>,
    /// The page of the --web viewer.
    pub web_url: Option<String>,
    /// What the --connect / --spawn stream did (messages sent and dropped).
    pub connect: Option<ConnectReport>,
    /// Warnings for the end-of-run report (part of [`LoggerReport::lines`]; problems found when
    /// the sinks were opened were also printed then).
    pub notes: Vec<String>,
    /// Outputs that could not be written (one line each, naming the option and the file); each
    /// left nothing at its final name. Not part of `lines`: the caller reports them as errors.
    pub errors: Vec<String>,
    /// Keeps the --serve server alive after the run; dropped by `serve_until_interrupted`.
    server: Option<LiveServer>,
}

impl std::fmt::Debug for LoggerReport {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LoggerReport")
            .field("steps", &self.steps)
            .field("fields_logged", &self.fields_logged)
            .field("fields_skipped", &self.fields_skipped)
            .field("rrd", &self.rrd)
            .field("csv", &self.csv)
            .field("vtk", &self.vtk)
            .field("serve_url", &self.serve_url)
            .field("web_url", &self.web_url)
            .field("connect", &self.connect)
            .field("notes", &self.notes)
            .field("errors", &self.errors)
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
        let skipped = if self.fields_skipped > 0 {
            format!(", {} skipped", self.fields_skipped)
        } else {
            String::new()
        };
        if let Some((path, bytes)) = &self.rrd {
            out.push(format!(
                "recording: {} ({:.1} MB, {} steps, {} field snapshots{skipped})",
                path.display(),
                *bytes as f64 / 1e6,
                self.steps,
                self.fields_logged,
            ));
        } else if self.fields_skipped > 0 {
            out.push(format!("field snapshots skipped: {}", self.fields_skipped));
        }
        if let Some((path, rows)) = &self.csv {
            out.push(format!("csv: {} ({rows} rows)", path.display()));
        }
        if let Some(v) = &self.vtk {
            out.push(format!(
                "vtk: {} ({} snapshots, {:.1} MB)",
                v.pvd.display(),
                v.snapshots,
                v.bytes as f64 / 1e6
            ));
        }
        if let Some(url) = &self.serve_url {
            out.push(format!("served at {url}"));
        }
        if let Some(url) = &self.web_url {
            out.push(format!("web viewer at {url}"));
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
            let url = self.serve_url.as_deref().unwrap_or("?");
            let web = match &self.web_url {
                Some(page) => format!(", or in a browser at {page}"),
                None => String::new(),
            };
            eprintln!(
                "platefall: run finished; still serving it at {url} (open it with `rerun {url}`{web}). Press Ctrl-C to stop."
            );
            while !stop.load(Ordering::SeqCst) {
                std::thread::sleep(Duration::from_millis(100));
            }
        }
        server.shut_down();
        Ok(())
    }

    /// Shuts a --serve server down now (same as `serve_until_interrupted` with `stop` set).
    pub fn stop_serving(&mut self) {
        if let Some(s) = self.server.take() {
            s.shut_down();
        }
    }
}

/// Starts the logger thread: opens every sink (an error here means nothing was started), writes
/// the static parts of the recording, and returns the solver's handle.
pub fn spawn_logger(opts: RecordOptions, info: RunInfo) -> anyhow::Result<Logger> {
    if !(opts.field_every.is_finite() && opts.field_every > 0.0) {
        anyhow::bail!(
            "field snapshot interval {}: must be a finite number > 0",
            opts.field_every
        );
    }
    let csv = match (&opts.csv, &opts.csv_prefix) {
        (Some(path), Some((earlier, rows))) => Some(CsvWriter::resume(path, earlier, *rows)?),
        (Some(path), None) => Some(CsvWriter::create(path)?),
        (None, _) => None,
    };
    let csv_link = csv.as_ref().map(CsvWriter::link_check);
    if let Some(v) = opts
        .vtk
        .as_ref()
        .filter(|v| !(v.every.is_finite() && v.every > 0.0))
    {
        anyhow::bail!("--vtk-every {}: must be a finite number > 0", v.every);
    }
    let vtk = match &opts.vtk {
        Some(v) => Some(VtkSeries::create(v, &info)?),
        None => None,
    };
    let viewer = if opts.has_rerun_sink() {
        Some(Viewer::open(&opts, &info)?)
    } else {
        None
    };
    let (tx, rx) = bounded(opts.channel_capacity.max(2));
    let shared = Arc::new(Shared::default());
    let (field_every, max_fields_in_flight) = (opts.field_every, opts.max_fields_in_flight);
    let vtk_every = opts.vtk.as_ref().map(|v| v.every);
    let thread = LoggerThread {
        rx,
        shared: shared.clone(),
        progress: Progress::new(opts.progress, info.t_end.unwrap_or(f64::NAN)),
        serve_url: opts.serve.as_ref().map(|s| s.url()),
        web_url: opts.serve.as_ref().and_then(|s| s.web_url()),
        opts,
        csv,
        csv_link,
        vtk,
        viewer,
        steps: 0,
        fields: 0,
        errors: Vec::new(),
        last_check: Instant::now(),
    };
    let thread = std::thread::Builder::new()
        .name("platefall-logger".into())
        .spawn(move || thread.run())
        .context("cannot start the logger thread")?;
    Ok(Logger {
        tx: Some(tx),
        thread: Some(thread),
        shared,
        fields: Cadence::new(field_every),
        vtk: vtk_every.map(Cadence::new),
        // A snapshot offered without asking `field_due` first is for the recording.
        due: FieldUse {
            viewer: true,
            vtk: false,
        },
        max_fields_in_flight,
    })
}

impl Logger {
    /// Convective time between field snapshots (`--field-every`).
    pub fn field_every(&self) -> f64 {
        self.fields.every()
    }

    /// The field cadences: true if a snapshot is due at simulated time `t`, for the recording
    /// (the first call always is; then at every multiple of `field_every`) or for `--vtk` (at
    /// every multiple of its interval). A true answer advances the cadences, so ask once per
    /// step and, when true, build a snapshot and [`offer_field`](Self::offer_field) it.
    pub fn field_due(&mut self, t: f64) -> bool {
        let viewer = self.fields.due(t);
        let vtk = self.vtk.as_mut().is_some_and(|c| c.due(t));
        self.due = FieldUse { viewer, vtk };
        viewer || vtk
    }

    /// A run resumed at time `t` after `steps` steps: the field cadence goes on from `t` as
    /// the saved run's would have (a new run, `steps` = 0, starts with a snapshot).
    pub fn resume_fields_at(&mut self, t: f64, steps: u64) {
        if steps > 0 {
            self.fields.skip_to(t);
            if let Some(v) = self.vtk.as_mut() {
                v.skip_to(t);
            }
        }
    }

    /// Sends one step (blocking when the channel is full: time series are never dropped).
    /// Fails if an output could not be written (stop the run then: nothing more can be kept) or
    /// if the logger thread has stopped.
    pub fn step(&self, sample: StepSample) -> anyhow::Result<()> {
        let tx = self.tx.as_ref().context("the logger has finished")?;
        tx.send(Message::Step(sample))
            .map_err(|_| anyhow::anyhow!("the logger thread stopped unexpectedly"))?;
        match self.output_failure() {
            Some(why) => anyhow::bail!("{why}"),
            None => Ok(()),
        }
    }

    /// Waits until the logger has handled every step sent so far and written the CSV's rows to
    /// its file (not synced: they survive the process, not the machine). Call it before writing
    /// a checkpoint: a run killed after the checkpoint then leaves a CSV (its `.NAME.partial-PID`
    /// file) that holds the rows up to it, so the run can be resumed with its CSV. Fails like
    /// [`step`](Self::step).
    pub fn flush_csv(&self) -> anyhow::Result<()> {
        let tx = self.tx.as_ref().context("the logger has finished")?;
        let (done_tx, done_rx) = bounded(1);
        let gone = || anyhow::anyhow!("the logger thread stopped unexpectedly");
        tx.send(Message::Flush(done_tx)).map_err(|_| gone())?;
        done_rx.recv().map_err(|_| gone())?;
        match self.output_failure() {
            Some(why) => anyhow::bail!("{why}"),
            None => Ok(()),
        }
    }

    /// Offers a field snapshot. A snapshot for the recording only is offered without blocking:
    /// false (and counted as skipped) when the logger is behind, the channel full or
    /// `max_fields_in_flight` snapshots queued. One due for `--vtk` is never skipped: this waits
    /// until fewer than `max_fields_in_flight` are queued (the files are what was asked for; the
    /// memory stays bounded), and returns false only if the logger has stopped or an output failed.
    pub fn offer_field(&self, snapshot: FieldSnapshot) -> bool {
        let Some(tx) = self.tx.as_ref() else {
            return false;
        };
        if self.due.vtk {
            return self.send_field_waiting(tx, snapshot);
        }
        let skip = || {
            self.shared.fields_skipped.fetch_add(1, Ordering::Relaxed);
            false
        };
        if self.shared.fields_in_flight.load(Ordering::Acquire) >= self.max_fields_in_flight {
            return skip();
        }
        self.shared.fields_in_flight.fetch_add(1, Ordering::AcqRel);
        match tx.try_send(Message::Field(Box::new(snapshot), self.due)) {
            Ok(()) => true,
            Err(TrySendError::Full(_)) | Err(TrySendError::Disconnected(_)) => {
                self.shared.fields_in_flight.fetch_sub(1, Ordering::AcqRel);
                skip()
            }
        }
    }

    /// Sends a snapshot once fewer than `max_fields_in_flight` are queued (see `offer_field`).
    fn send_field_waiting(&self, tx: &Sender<Message>, snapshot: FieldSnapshot) -> bool {
        let stopped = || {
            self.shared.failed.load(Ordering::SeqCst)
                || self.thread.as_ref().is_none_or(JoinHandle::is_finished)
        };
        while self.shared.fields_in_flight.load(Ordering::Acquire) >= self.max_fields_in_flight {
            if stopped() {
                self.shared.fields_skipped.fetch_add(1, Ordering::Relaxed);
                return false;
            }
            std::thread::sleep(Duration::from_millis(1));
        }
        self.shared.fields_in_flight.fetch_add(1, Ordering::AcqRel);
        let sent = tx
            .send(Message::Field(Box::new(snapshot), self.due))
            .is_ok();
        if !sent {
            self.shared.fields_in_flight.fetch_sub(1, Ordering::AcqRel);
            self.shared.fields_skipped.fetch_add(1, Ordering::Relaxed);
        }
        sent
    }

    /// The first output that could not be written, if any (one line).
    pub fn output_failure(&self) -> Option<String> {
        if !self.shared.failed.load(Ordering::SeqCst) {
            return None;
        }
        let g = self
            .shared
            .failure
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        g.clone()
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

/// The logger thread's state: its outputs and what it has counted.
struct LoggerThread {
    rx: Receiver<Message>,
    shared: Arc<Shared>,
    opts: RecordOptions,
    progress: Progress,
    csv: Option<CsvWriter>,
    csv_link: Option<LinkCheck>,
    vtk: Option<VtkSeries>,
    viewer: Option<Viewer>,
    serve_url: Option<String>,
    web_url: Option<String>,
    steps: u64,
    fields: u64,
    /// What went wrong with an output (the report says so; a write error also stops the run).
    errors: Vec<String>,
    last_check: Instant,
}

impl LoggerThread {
    fn run(mut self) -> anyhow::Result<LoggerReport> {
        let outcome = self.receive();
        self.finish(outcome)
    }

    /// Handles messages until the outcome arrives (or the solver goes away without one).
    fn receive(&mut self) -> RunOutcome {
        loop {
            match self.rx.recv_timeout(Duration::from_millis(200)) {
                Ok(msg) => {
                    let shared = self.shared.clone();
                    let _gate = shared.gate.lock().unwrap_or_else(|e| e.into_inner());
                    if let Some(outcome) = self.handle(msg) {
                        return outcome;
                    }
                    self.watch_outputs();
                }
                Err(RecvTimeoutError::Timeout) => {
                    self.idle();
                    self.watch_outputs();
                }
                Err(RecvTimeoutError::Disconnected) => return lost_solver_outcome(),
            }
        }
    }

    fn handle(&mut self, msg: Message) -> Option<RunOutcome> {
        match msg {
            Message::Step(s) => self.step(s),
            Message::Field(f, due) => self.field(&f, due),
            Message::Flush(done) => {
                self.flush_csv();
                let _ = done.send(());
            }
            Message::Finish(o) => return Some(o),
        }
        None
    }

    fn idle(&mut self) {
        self.progress.tick();
        let result = self.viewer.as_mut().map(Viewer::idle);
        self.note(result);
    }

    fn step(&mut self, s: StepSample) {
        self.steps += 1;
        self.progress.update(&s);
        if let Some(w) = &mut self.csv {
            if let Err(e) = w.write(&s) {
                self.csv = None; // dropped unfinished: its temporary file is removed
                self.fail(e);
            }
        }
        let result = self.viewer.as_mut().map(|v| v.step(s));
        self.note(result);
    }

    /// Writes the CSV's buffered rows to its (temporary) file.
    fn flush_csv(&mut self) {
        if let Some(w) = &mut self.csv {
            if let Err(e) = w.flush() {
                self.csv = None;
                self.fail(e);
            }
        }
    }

    /// An output failed: keep the reason, drop nothing else, and have the solver stop.
    fn fail(&mut self, e: OutputError) {
        let line = e.to_string();
        let mut g = self
            .shared
            .failure
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        g.get_or_insert_with(|| line.clone());
        self.shared.failed.store(true, Ordering::SeqCst);
        drop(g);
        if !self.errors.contains(&line) {
            self.errors.push(line);
        }
    }

    /// Notices a failed .rrd write at once, and every second a file removed from under us.
    fn watch_outputs(&mut self) {
        let mut found = self.viewer.as_ref().and_then(Viewer::output_error);
        if found.is_none() && self.last_check.elapsed() >= LINK_CHECK_EVERY {
            self.last_check = Instant::now();
            found = self.viewer.as_ref().and_then(Viewer::check_outputs);
            if let (Some(link), Some(w)) = (&self.csv_link, &self.csv) {
                if let Err(lost) = link.verify() {
                    found = Some(w.fail(lost.to_string()));
                }
            }
        }
        if let Some(e) = found {
            self.fail(e);
        }
    }

    fn field(&mut self, f: &FieldSnapshot, due: FieldUse) {
        self.shared.fields_in_flight.fetch_sub(1, Ordering::AcqRel);
        if due.vtk {
            if let Some(Err(e)) = self.vtk.as_mut().map(|v| v.write(f)) {
                self.vtk = None; // what was written stays listed in its collection
                self.fail(e);
            }
        }
        if !due.viewer {
            return;
        }
        let skipped = self.shared.fields_skipped.load(Ordering::Relaxed);
        match self.viewer.as_mut().map(|v| v.field(f, skipped)) {
            Some(Ok(false)) => {}
            Some(Err(e)) => self.errors.push(e.to_string()),
            Some(Ok(true)) | None => self.fields += 1,
        }
    }

    /// Keeps a recording error for the report.
    fn note(&mut self, result: Option<Result<(), RecordingError>>) {
        if let Some(Err(e)) = result {
            self.errors.push(e.to_string());
        }
    }

    /// Finalises every output, whatever happened before: each complete one is renamed into
    /// place; each that failed is removed and named in `errors`.
    fn finish(mut self, outcome: RunOutcome) -> anyhow::Result<LoggerReport> {
        let skipped = self.shared.fields_skipped.load(Ordering::Relaxed);
        self.progress.finish(outcome.status.name());
        let stats = self.stats_markdown(skipped);
        let viewer = self
            .viewer
            .take()
            .map(|v| v.finish(&outcome, &stats, &mut self.errors));
        let csv = match self.csv.take().map(|w| w.finish(&outcome.status)) {
            Some(Ok(r)) => Some(r),
            Some(Err(e)) => {
                self.errors.push(e.to_string());
                None
            }
            None => None,
        };
        let mut errors: Vec<String> = Vec::new();
        for e in self.errors.drain(..) {
            if !errors.contains(&e) {
                errors.push(e); // an output that failed mid-run fails its commit the same way
            }
        }
        let (rrd, connect, server, notes) = match viewer {
            Some(v) => (v.rrd, v.connect, v.server, v.notes),
            None => (None, None, None, Vec::new()),
        };
        Ok(LoggerReport {
            steps: self.steps,
            fields_logged: self.fields,
            fields_skipped: skipped,
            rrd,
            csv,
            vtk: self.vtk.as_ref().map(VtkSeries::report),
            serve_url: self.serve_url,
            web_url: self.web_url,
            connect,
            notes,
            errors,
            server,
        })
    }

    /// The recording's own account of what it holds, for `/run/summary`.
    fn stats_markdown(&self, skipped: u64) -> String {
        let mut stats = format!(
            "- steps recorded: {}\n- field snapshots recorded: {} (every {} c/U)\n\
             - field snapshots skipped because the logger fell behind: {skipped}\n",
            self.steps, self.fields, self.opts.field_every
        );
        if let Some(c) = self.viewer.as_ref().and_then(Viewer::connect_report) {
            stats.push_str(&format!(
                "- live stream to {}: {} messages dropped\n",
                c.url, c.dropped
            ));
        }
        stats
    }
}

/// The outcome when the solver's handle went away without reporting one.
fn lost_solver_outcome() -> RunOutcome {
    RunOutcome {
        status: RunStatus::Interrupted,
        summary_json: "{}".into(),
        report: "The solver stopped without reporting an outcome (an error or a panic); \
                 the recording ends at the last step received."
            .into(),
    }
}
