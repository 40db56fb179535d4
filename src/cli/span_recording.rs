//! The recording of a 3-D run (docs/three-d.md "Recording"): opened from the run's recording
//! options, fed every step and a snapshot of the flow at the `--field-every` cadence, committed
//! with the run's outcome.
use std::path::PathBuf;

use platefall_core::flow3d::{FlowSolver3, Span};
use platefall_core::sim3::Run3;
use platefall_record::messages::{FieldUse, RunOutcome};
use platefall_record::messages3::{RunInfo3, Step3};
use platefall_record::recorder3::Recorder3;
use platefall_record::viewer::ViewerReport;

use super::command::Command;
use super::record_args::RecordArgs;

/// Snapshot cadence of a 3-D recording without `--field-every` (c/U).
const FIELD_EVERY_3D: f64 = 0.5;
/// The Q level of the recording's vortex iso-surface ((U/c)²).
const Q_LEVEL: f64 = 2.0;
/// The vorticity at which the recording's slices saturate (U/c).
const VORTICITY_SCALE: f64 = 5.0;

/// The recording of a 3-D run: its logger and the snapshot cadences (the recording's, the VTK
/// series'), each with the time its next snapshot is due (infinite without it).
pub(super) struct Recording {
    recorder: Recorder3,
    every: [f64; 2],
    next: [f64; 2],
}

impl Recording {
    /// Opens the recording and the VTK series the options ask for ([`save_path`] by default),
    /// or none without either; `id` the recording id (a continuation's is its run's).
    pub(super) fn start(
        cmd: &Command,
        run: &Run3,
        record: &RecordArgs,
        cells: usize,
        id: Option<String>,
    ) -> anyhow::Result<Option<Recording>> {
        let rerun = record.uses_rerun();
        if !rerun && record.vtk.is_none() {
            return Ok(None);
        }
        let case = run.config.case.kind();
        let mut args = record.clone();
        args.save = Some(save_path(record, run));
        args.field_every = Some(record.field_every.unwrap_or(FIELD_EVERY_3D));
        let mut opts = args.resolve(case, &[])?;
        opts.recording_id = id;
        let span = run.grid.span;
        let half_span = 0.5 * span.length();
        let title = run.title();
        let invocation = super::provenance::invocation(cmd);
        let config_markdown = format!(
            "# {title}\n\n```text\n{}\n```\n\n{cells} cells; {}\n",
            invocation.args.join(" "),
            invocation.version
        );
        let info = RunInfo3 {
            title,
            config_markdown,
            half_size: [0.5, 0.5 * run.grid.thickness, half_span],
            periodic: matches!(span, Span::Periodic(_)),
            t_end: Some(run.config.time.t_end),
            q_level: Q_LEVEL,
            vorticity_scale: VORTICITY_SCALE,
        };
        let inf = f64::INFINITY;
        let every = [
            if rerun { opts.field_every } else { inf },
            opts.vtk.as_ref().map_or(inf, |v| v.every),
        ];
        Ok(Some(Recording {
            recorder: Recorder3::start(&opts, &info, rerun)?,
            next: every.map(|e| if e.is_finite() { 0.0 } else { inf }),
            every,
        }))
    }

    /// Sends a step and, when one is due, the flow's snapshot (for the recording only if the
    /// logger keeps up).
    pub(super) fn step(&mut self, s: Step3, flow: &FlowSolver3) {
        self.recorder.step(s);
        let due = self.next.map(|t| s.t + 1e-9 >= t);
        for ((next, every), due) in self.next.iter_mut().zip(self.every).zip(due) {
            if due {
                *next = s.t + every;
            }
        }
        let admitted = self.recorder.admit(FieldUse {
            viewer: due[0],
            vtk: due[1],
        });
        if admitted.viewer || admitted.vtk {
            self.recorder.field(flow.snapshot(), admitted);
        }
    }

    /// Commits the recording and says what it holds; false if it failed.
    pub(super) fn finish(self, outcome: RunOutcome) -> bool {
        let report = self.recorder.finish(outcome);
        if let Some(v) = &report.vtk {
            eprintln!(
                "VTK: {} ({} snapshots, {:.1} MB)",
                v.pvd.display(),
                v.snapshots,
                v.bytes as f64 / 1e6
            );
        }
        if let Some(viewer) = report.viewer {
            viewer_lines(viewer, report.skipped);
        }
        for e in &report.errors {
            eprintln!("error: {e}");
        }
        report.errors.is_empty()
    }
}

/// Where a 3-D run's recording goes: `--save`, else `recordings/<case>-3d.rrd`.
pub(super) fn save_path(record: &RecordArgs, run: &Run3) -> PathBuf {
    let case = run.config.case.kind();
    record.save.clone().unwrap_or_else(|| {
        RecordArgs::default_save_path(case).with_file_name(format!("{case}-3d.rrd"))
    })
}

/// What the viewer side of a recording says at the end; a --serve server is shut down.
fn viewer_lines(viewer: ViewerReport, skipped: u64) {
    if let Some((path, bytes)) = &viewer.rrd {
        let skipped = match skipped {
            0 => String::new(),
            k => format!(", {k} snapshots skipped"),
        };
        eprintln!(
            "recording: {} ({:.1} MB{skipped})",
            path.display(),
            *bytes as f64 / 1e6
        );
    }
    for n in &viewer.notes {
        eprintln!("platefall: warning: {n}");
    }
    if let Some(server) = viewer.server {
        server.shut_down();
    }
}
