//! The logger thread of a 3-D run (docs/three-d.md "Recording"): the solver thread sends every
//! step and, at the snapshot cadences, the flow's snapshot over a bounded channel; the logger
//! thread builds the meshes and logs them (the Rerun recording) and writes the VTK series, so
//! the solver never waits for either. Steps are never dropped; a snapshot for the recording
//! alone is skipped (and counted) while the logger still holds [`SNAPSHOTS_IN_FLIGHT`] of them;
//! one the VTK series needs is always sent.
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;

use crossbeam_channel::{bounded, Sender};

use crate::messages::{FieldUse, RunOutcome};
use crate::messages3::{Message3, RunInfo3, Step3};
use crate::options::RecordOptions;
use crate::viewer::{Viewer3, ViewerReport};
use crate::vtk::three::VtkSeries3;
use crate::vtk::VtkReport;
use platefall_core::flow3d::FieldSnapshot3;

/// Messages the channel holds before the solver waits for the logger.
const CHANNEL_DEPTH: usize = 256;
/// Snapshots sent and not yet logged, at most, for the recording alone.
const SNAPSHOTS_IN_FLIGHT: usize = 2;

/// What the recording of a 3-D run produced.
pub struct Report3 {
    /// The viewer side's report (the .rrd file, live streams, notes), if it recorded.
    pub viewer: Option<ViewerReport>,
    /// The VTK series, if it wrote one.
    pub vtk: Option<VtkReport>,
    /// What went wrong in the recording or the VTK series.
    pub errors: Vec<String>,
    /// Snapshots skipped because the logger was behind.
    pub skipped: u64,
}

/// The solver side of a 3-D recording.
pub struct Recorder3 {
    tx: Sender<Message3>,
    thread: JoinHandle<Report3>,
    in_flight: Arc<AtomicUsize>,
    skipped: u64,
}

/// What the logger thread writes to.
struct Logger3 {
    viewer: Option<Viewer3>,
    vtk: Option<VtkSeries3>,
    last: Option<Step3>,
    errors: Vec<String>,
}

impl Logger3 {
    fn step(&mut self, s: &Step3) {
        self.last = Some(*s);
        if let Some(Err(e)) = self.viewer.as_mut().map(|v| v.step(s)) {
            self.errors.push(e.to_string());
        }
    }

    fn field(&mut self, f: &FieldSnapshot3, due: FieldUse) {
        if due.viewer {
            if let Some(Err(e)) = self.viewer.as_mut().map(|v| v.field(f)) {
                self.errors.push(e.to_string());
            }
        }
        let (Some(series), Some(at), true) = (self.vtk.as_mut(), self.last.as_ref(), due.vtk)
        else {
            return;
        };
        if let Err(e) = series.write(f, at) {
            self.errors.push(e.to_string());
            self.vtk = None;
        }
    }

    fn finish(mut self, outcome: &RunOutcome) -> Report3 {
        let viewer = self
            .viewer
            .take()
            .map(|v| v.finish(outcome, &mut self.errors));
        Report3 {
            viewer,
            vtk: self.vtk.as_ref().map(VtkSeries3::report),
            errors: self.errors,
            skipped: 0,
        }
    }
}

impl Recorder3 {
    /// Opens what `opts` asks for: the Rerun sinks when `rerun`, the VTK series when
    /// `opts.vtk` (an error here means nothing was started); starts the logger thread.
    pub fn start(opts: &RecordOptions, info: &RunInfo3, rerun: bool) -> anyhow::Result<Recorder3> {
        let vtk = opts.vtk.as_ref().map(VtkSeries3::create).transpose()?;
        let viewer = rerun.then(|| Viewer3::open(opts, info)).transpose()?;
        let mut logger = Logger3 {
            viewer,
            vtk,
            last: None,
            errors: Vec::new(),
        };
        let (tx, rx) = bounded::<Message3>(CHANNEL_DEPTH);
        let in_flight = Arc::new(AtomicUsize::new(0));
        let logged_fields = Arc::clone(&in_flight);
        let thread = std::thread::Builder::new()
            .name("platefall-logger3".into())
            .spawn(move || {
                for msg in rx {
                    match msg {
                        Message3::Step(s) => logger.step(&s),
                        Message3::Field(f, due) => {
                            logger.field(&f, due);
                            logged_fields.fetch_sub(1, Ordering::SeqCst);
                        }
                        Message3::Finish(outcome) => return logger.finish(&outcome),
                    }
                }
                logger.finish(&RunOutcome {
                    status: platefall_core::sim::RunStatus::Interrupted,
                    summary_json: String::new(),
                    report: String::new(),
                })
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

    /// What a snapshot due for `due` would still be taken for: the VTK series always, the
    /// recording unless the logger holds [`SNAPSHOTS_IN_FLIGHT`] (then it is counted skipped).
    pub fn admit(&mut self, due: FieldUse) -> FieldUse {
        let free = self.in_flight.load(Ordering::SeqCst) < SNAPSHOTS_IN_FLIGHT;
        if due.viewer && !free {
            self.skipped += 1;
        }
        FieldUse {
            viewer: due.viewer && free,
            vtk: due.vtk,
        }
    }

    /// Sends a snapshot for `due` (see [`Recorder3::admit`]).
    pub fn field(&self, f: FieldSnapshot3, due: FieldUse) {
        self.in_flight.fetch_add(1, Ordering::SeqCst);
        let _ = self.tx.send(Message3::Field(Arc::new(f), due));
    }

    /// Sends the outcome and waits for the recording to be committed.
    pub fn finish(self, outcome: RunOutcome) -> Report3 {
        let _ = self.tx.send(Message3::Finish(outcome));
        drop(self.tx);
        let mut report = self.thread.join().unwrap_or_else(|_| Report3 {
            viewer: None,
            vtk: None,
            errors: vec!["the recording's logger thread failed".into()],
            skipped: 0,
        });
        report.skipped = self.skipped;
        report
    }
}
