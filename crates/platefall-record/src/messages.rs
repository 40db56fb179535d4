//! The messages from the solver thread to the logger thread: the solver's own outputs
//! ([`StepSample`], [`FieldSnapshot`]) plus what the recording needs around them; and what the
//! viewer side reports back about a live stream ([`ConnectReport`], the same with or without the
//! `viewer` feature).
use std::sync::Arc;

use platefall_core::grid::GridGeometry;
use platefall_core::shape::Outline;
use platefall_core::sim::{CaseKind, FieldSnapshot, RunStatus, StepSample, ValidatedConfig};
use platefall_post::ViewDefaults;

use crate::provenance::Invocation;

/// Everything about a run that does not change while it runs; given when the logger starts.
#[derive(Clone, Debug)]
pub struct RunInfo {
    /// Which case the run is.
    pub case: CaseKind,
    /// One-line human description, e.g. "free fall, card preset, Re 4770, N=32".
    pub title: String,
    /// The full resolved configuration as pretty JSON (enough to reproduce the run).
    pub config_json: String,
    /// The command line as typed (argv joined with shell quoting).
    pub command_line: String,
    /// The program, its version and the commit it is built from.
    pub version: String,
    /// How the run was started (arguments, directory, input files), for the recording.
    pub invocation: Invocation,
    /// The plate's section in body coordinates (chord = 1), as the flow sees it.
    pub section: Arc<Outline>,
    /// The section in words, e.g. "rectangle t/c = 0.015625".
    pub section_label: String,
    /// Body-fixed grid geometry shared by every field snapshot.
    pub grid: Arc<GridGeometry>,
    /// The viewer's defaults for the run (wake window, plot ranges).
    pub view: ViewDefaults,
    /// The time the run ends at, when it is known beforehand (None when it stops after a number
    /// of turns): the progress display's end and the length of the recording's curve segments.
    pub t_end: Option<f64>,
}

impl RunInfo {
    /// The information of a run of `config`, started by `command_line` of `version`.
    pub fn new(config: &ValidatedConfig, command_line: String, version: String) -> RunInfo {
        let grid = config.grid();
        RunInfo {
            case: config.case.kind(),
            title: config.title(),
            // (Cannot fail for plain data.)
            config_json: serde_json::to_string_pretty(config).unwrap_or_default(),
            command_line,
            invocation: Invocation {
                version: version.clone(),
                ..Invocation::default()
            },
            version,
            section: Arc::new(config.grid.shape.outline()),
            section_label: config.grid.shape.describe(),
            grid: Arc::new(grid.geometry()),
            view: ViewDefaults::of(config),
            // A run that stops after a number of turns has no known end time: show no ETA rather
            // than a wrong one.
            t_end: config.time.turns.is_none().then_some(config.time.t_end),
        }
    }

    /// The same, started as `invocation` says (its version replaces [`RunInfo::version`]).
    pub fn with_invocation(self, invocation: Invocation) -> RunInfo {
        RunInfo {
            version: invocation.version.clone(),
            invocation,
            ..self
        }
    }
}

/// How the run ended, with its summary; sent once, last.
#[derive(Clone, Debug)]
pub struct RunOutcome {
    /// How the run ended (completed, diverged, interrupted …), with the details.
    pub status: RunStatus,
    /// The summary JSON (pretty) as written by `--summary`.
    pub summary_json: String,
    /// The human-readable end-of-run report (markdown-ish plain text).
    pub report: String,
}

/// One message on the solver → logger channel.
#[derive(Clone, Debug)]
pub enum Message {
    /// Every step, never dropped.
    Step(StepSample),
    /// A field snapshot, at the field cadences, and what it is for; may be thinned.
    Field(Box<FieldSnapshot>, FieldUse),
    /// Write out the CSV's buffered rows (the steps sent so far), then answer: sent before a
    /// checkpoint, so that a run killed after it leaves a CSV holding the rows up to it.
    Flush(crossbeam_channel::Sender<()>),
    /// The run is over: record its outcome, finalise every output and stop the logger.
    Finish(RunOutcome),
}

/// What a field snapshot is for: the recording's pictures, the VTK series, or both.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FieldUse {
    /// Due at the recording's field cadence (`--field-every`).
    pub viewer: bool,
    /// Due at the VTK cadence (`--vtk-every`).
    pub vtk: bool,
}

/// The Rerun recording stream failed: the scene stops recording (its outputs are reported), the
/// run goes on.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("recording: {0}")]
pub struct RecordingError(pub String);

/// A viewer option Rerun does not accept (a memory limit, a proxy URL): Rerun's own reason.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct ViewerRefusal(pub String);

/// What a --connect / --spawn stream did.
#[derive(Clone, Debug, PartialEq)]
pub struct ConnectReport {
    /// The viewer's URL the stream was sent to.
    pub url: String,
    /// Messages handed to the gRPC client.
    pub sent: u64,
    /// Messages dropped because the viewer did not keep up (or was not there).
    pub dropped: u64,
    /// True if a viewer was connected at some point.
    pub ever_connected: bool,
}
