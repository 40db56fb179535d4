//! What a 3-D run keeps of its steps (docs/three-d.md "On the command line"): the CSV, the
//! planar, lateral and attitude samples the summary is made of (new, or from a checkpoint), and
//! why a run stopped before its end.
use std::path::Path;

use super::command::Command;
use super::span_recording::Recording;
use platefall_core::flow3d::FlowSolver3;
use platefall_core::sim::{History, StepSample};
use platefall_core::sim3::Flight3Error;
use platefall_post::summary3::{lateral_sample, Attitude};
use platefall_record::checkpoint::SpanState;
use platefall_record::csv3::{Csv3Writer, CSV3_HEADER, CSV6_HEADER};
use platefall_record::messages3::Step3;
use platefall_record::output::OutputError;
use platefall_record::progress::Progress;

/// What a 3-D run keeps of its steps.
pub(super) struct Outputs {
    pub(super) csv: Option<Csv3Writer>,
    pub(super) planar: History,
    pub(super) lateral: History,
    pub(super) attitude: Vec<Attitude>,
    pub(super) cells: usize,
    /// The recirculation length behind a static body at the end (flow3d `wake.rs`).
    pub(super) recirculation_length: Option<f64>,
    /// The 3-D recording, if the run has one.
    pub(super) recording: Option<Recording>,
    /// Progress on stderr (simulated time, steps per second, the time left).
    pub(super) progress: Option<Progress>,
}

/// The header of the CSV of `cmd`'s 3-D run.
pub(super) fn csv_header(cmd: &Command) -> &'static str {
    match cmd {
        Command::Free(_) => CSV6_HEADER,
        _ => CSV3_HEADER,
    }
}

impl Outputs {
    pub(super) fn new(csv: Option<&Path>, cmd: &Command, cells: usize) -> anyhow::Result<Outputs> {
        let header = csv_header(cmd);
        Ok(Outputs {
            csv: csv.map(|p| Csv3Writer::create(p, header)).transpose()?,
            planar: History::default(),
            lateral: History::default(),
            attitude: Vec::new(),
            cells,
            recirculation_length: None,
            recording: None,
            progress: None,
        })
    }

    /// The outputs of a run resumed from `state`: the CSV (if any) starts with the first rows
    /// of `earlier`, up to the checkpoint.
    pub(super) fn resume(
        csv: Option<(&Path, &Path)>,
        cmd: &Command,
        cells: usize,
        state: &SpanState,
    ) -> anyhow::Result<Outputs> {
        let header = csv_header(cmd);
        let rows = state.steps();
        let resume = |(path, earlier)| Csv3Writer::resume(path, header, earlier, rows);
        Ok(Outputs {
            csv: csv.map(resume).transpose()?,
            planar: state.planar.clone(),
            lateral: state.lateral.clone(),
            attitude: state.attitude.clone(),
            cells,
            recirculation_length: None,
            recording: None,
            progress: None,
        })
    }

    /// Sends a step (and, when due, the flow's snapshot) to the recording.
    pub(super) fn record(&mut self, s: Step3, flow: &FlowSolver3) {
        if let Some(r) = &mut self.recording {
            r.step(s, flow);
        }
    }

    /// Keeps a step's planar and lateral samples (and shows the progress).
    pub(super) fn keep(&mut self, planar: StepSample, c: [f64; 3]) {
        if let Some(p) = &mut self.progress {
            p.update(&planar);
        }
        self.planar.push(planar);
        self.lateral.push(lateral_sample(&planar, c[0], c[1], c[2]));
    }
}

/// Why a 3-D run stopped before its end.
pub(super) enum Stop {
    /// The flow or the flight failed.
    Flow(Flight3Error),
    /// The CSV could not be written.
    Output(OutputError),
    /// A checkpoint could not be written (or does not fit the run).
    Checkpoint(String),
}

impl<E: Into<Flight3Error>> From<E> for Stop {
    fn from(e: E) -> Stop {
        Stop::Flow(e.into())
    }
}
