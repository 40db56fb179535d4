//! The logger thread of a 3-D run (docs/three-d.md "Recording"): the solver thread sends every
//! step and, at the snapshot cadence, the flow's snapshot over a bounded channel; the logger
//! thread builds the meshes and logs them, so the solver never waits for the recording. A
//! snapshot that finds the channel full is skipped (and counted); steps are never dropped.
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;

use crossbeam_channel::{bounded, Sender};

use crate::messages::RunOutcome;
use crate::messages3::{Message3, RunInfo3, Step3};
use crate::options::RecordOptions;
use crate::viewer::{Viewer3, ViewerReport};
use platefall_core::flow3d::FieldSnapshot3;

/// Messages the channel holds before the solver waits for the logger.
const CHANNEL_DEPTH: usize = 256;
/// Snapshots sent and not yet logged, at most (each holds a few values per cell).
const SNAPSHOTS_IN_FLIGHT: usize = 2;

/// What the recording of a 3-D run produced.
pub struct Report3 {
    /// The viewer side's report (the .rrd file, live streams, notes).
    pub viewer: ViewerReport,
    /// What went wrong in the recording.
    pub errors: Vec<String>,
    /// Snapshots skipped because the logger was behind.
    pub skipped: u64,
}

/// The solver side of a 3-D recording.
pub struct Recorder3 {
    tx: Sender<Message3>,
    thread: JoinHandle<(ViewerReport, Vec<String>)>,
    in_flight: Arc<AtomicUsize>,
    skipped: u64,
}

impl Recorder3 {
    /// Opens the sinks of `opts` (an error here means nothing was started) and starts the
    /// logger thread.
    pub fn start(opts: &RecordOptions, info: &RunInfo3) -> anyhow::Result<Recorder3> {
        let viewer = Viewer3::open(opts, info)?;
        let (tx, rx) = bounded::<Message3>(CHANNEL_DEPTH);
        let in_flight = Arc::new(AtomicUsize::new(0));
        let logged_fields = Arc::clone(&in_flight);
        let thread = std::thread::Builder::new()
            .name("platefall-logger3".into())
            .spawn(move || {
                let mut viewer = viewer;
                let mut errors = Vec::new();
                for msg in rx {
                    let logged = match msg {
                        Message3::Step(s) => viewer.step(&s),
                        Message3::Field(f) => {
                            let logged = viewer.field(&f);
                            logged_fields.fetch_sub(1, Ordering::SeqCst);
                            logged
                        }
                        Message3::Finish(outcome) => {
                            return (viewer.finish(&outcome, &mut errors), errors);
                        }
                    };
                    if let Err(e) = logged {
                        errors.push(e.to_string());
                    }
                }
                let outcome = RunOutcome {
                    status: platefall_core::sim::RunStatus::Interrupted,
                    summary_json: String::new(),
                    report: String::new(),
                };
                (viewer.finish(&outcome, &mut errors), errors)
            })?;
        Ok(Recorder3 {
            tx,
            thread,
            in_flight,
            skipped: 0,
        })
    }

    /// Sends a step (waits while the channel is full).
    pub fn step(&self, s: Step3) {
        let _ = self.tx.send(Message3::Step(s));
    }

    /// Whether a snapshot now would be logged: false (and counted as skipped) while the
    /// logger still holds [`SNAPSHOTS_IN_FLIGHT`] of them, so the solver need not make it.
    pub fn wants_field(&mut self) -> bool {
        let free = self.in_flight.load(Ordering::SeqCst) < SNAPSHOTS_IN_FLIGHT;
        if !free {
            self.skipped += 1;
        }
        free
    }

    /// Sends a snapshot (ask [`Recorder3::wants_field`] first).
    pub fn field(&self, f: FieldSnapshot3) {
        self.in_flight.fetch_add(1, Ordering::SeqCst);
        let _ = self.tx.send(Message3::Field(Arc::new(f)));
    }

    /// Sends the outcome and waits for the recording to be committed.
    pub fn finish(self, outcome: RunOutcome) -> Report3 {
        let _ = self.tx.send(Message3::Finish(outcome));
        drop(self.tx);
        match self.thread.join() {
            Ok((viewer, errors)) => Report3 {
                viewer,
                errors,
                skipped: self.skipped,
            },
            Err(_) => Report3 {
                viewer: ViewerReport {
                    rrd: None,
                    connect: None,
                    server: None,
                    notes: Vec::new(),
                },
                errors: vec!["the recording's logger thread failed".into()],
                skipped: self.skipped,
            },
        }
    }
}
