//! What a platefall recording holds for `platefall info` and `platefall reproduce`: how the run
//! was started, its summary and report, and its per-step series; read by
//! [`read_recording`](crate::viewer::read_recording) (feature `viewer`).
use std::path::PathBuf;

use crate::provenance::RecordedInvocation;
use platefall_core::sim::StepSample;

/// The recorded per-step series, in the order of [`RecordedStep::values`]: (name, unit).
pub const RECORDED_SERIES: [(&str, &str); 8] = [
    ("C_L", ""),
    ("C_D", ""),
    ("C_M", ""),
    ("V", "U"),
    ("dθ/dt", "rad per c/U"),
    ("γ", "rad"),
    ("α", "rad"),
    ("Δt", "c/U"),
];

/// One step of a recording.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RecordedStep {
    /// The step number.
    pub step: u64,
    /// Its time in c/U (as the recording's `time` timeline holds it: to the nanosecond).
    pub t: f64,
    /// The values of [`RECORDED_SERIES`], exactly as the run computed them.
    pub values: [f64; RECORDED_SERIES.len()],
}

impl RecordedStep {
    /// The step of `s`, as the recording holds it.
    pub fn of(s: &StepSample) -> RecordedStep {
        RecordedStep {
            step: s.step,
            t: s.t,
            values: [s.cl, s.cd, s.cm, s.speed, s.omega, s.gamma, s.alpha, s.dt],
        }
    }
}

/// A platefall recording, read.
#[derive(Clone, Debug)]
pub struct Recorded {
    /// How the run was started and what it was.
    pub invocation: RecordedInvocation,
    /// The summary JSON (None: the recording ends before the run did).
    pub summary_json: Option<String>,
    /// The end-of-run report (None as for the summary).
    pub report: Option<String>,
    /// Every step recorded, in order.
    pub steps: Vec<RecordedStep>,
}

/// A file that is not a complete platefall recording.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// The file cannot be opened.
    #[error("{}: cannot open it: {why}", .path.display())]
    Open {
        /// The file.
        path: PathBuf,
        /// The system's reason.
        why: String,
    },
    /// The file is not a Rerun recording.
    #[error("{}: not a readable Rerun recording ({why})", .path.display())]
    Undecodable {
        /// The file.
        path: PathBuf,
        /// The decoder's reason.
        why: String,
    },
    /// The recording has no footer: its writer did not finish it.
    #[error("{}: the recording is truncated (it has no footer): copy it again, or record the run again", .path.display())]
    Truncated {
        /// The file.
        path: PathBuf,
    },
    /// A Rerun recording without platefall's invocation document.
    #[error("{}: a Rerun recording, but not one platefall made (it has no /run/invocation)", .path.display())]
    NotPlatefall {
        /// The file.
        path: PathBuf,
    },
    /// The invocation document is not one this program reads.
    #[error("{}: its /run/invocation is not one this platefall reads ({why})", .path.display())]
    Invocation {
        /// The file.
        path: PathBuf,
        /// What is wrong with the document.
        why: String,
    },
    /// This build cannot read recordings.
    #[error("this platefall is built without the `viewer` feature: it cannot read recordings")]
    NoViewer,
}
