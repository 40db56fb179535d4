//! Writing a run's checkpoints: at the `--checkpoint-every` cadence, at a stop (SIGTERM, SIGUSR1,
//! the first Ctrl-C) and, with a cadence, at the end. The state comes from the core
//! ([`Simulation::save`], or a 3-D run's, `span_checkpoint.rs`); the file from the record crate
//! ([`write_checkpoint`]).
use std::path::{Path, PathBuf};

use super::args::CheckpointArgs;
use super::record_args::RecordArgs;
use platefall_core::sim::CaseKind;
use std::time::Instant;

use platefall_core::sim::{History, Simulation};
use platefall_record::checkpoint::{write_checkpoint, Checkpoint, ResumeInfo, RunState};
use platefall_record::{Cadence, Logger};

/// The checkpoints of one run.
pub struct Checkpointer {
    path: PathBuf,
    /// The `--checkpoint-every` cadence (none: only at a stop and on demand).
    cadence: Option<Cadence>,
    info: ResumeInfo,
    program: String,
    /// Checkpoints written, their last size, and the time spent writing them.
    pub written: u64,
    /// The last one's size in bytes.
    pub bytes: u64,
    /// Seconds spent taking and writing them.
    pub seconds: f64,
}

impl Checkpointer {
    /// Checkpoints to `path` every `every` convective times (None: only at a stop and on
    /// demand), for a run at time `t` now.
    pub fn new(
        path: PathBuf,
        every: Option<f64>,
        t: f64,
        info: ResumeInfo,
        program: String,
    ) -> Self {
        let cadence = every.map(|e| {
            let mut c = Cadence::new(e);
            c.skip_to(t);
            c
        });
        Checkpointer {
            path,
            cadence,
            info,
            program,
            written: 0,
            bytes: 0,
            seconds: 0.0,
        }
    }

    /// The file.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Whether a cadence was asked for (then the run's end writes one too).
    pub fn periodic(&self) -> bool {
        self.cadence.is_some()
    }

    /// Whether a checkpoint is due at the run's time `t` (then it counts as taken).
    pub fn due(&mut self, t: f64) -> bool {
        self.cadence.as_mut().is_some_and(|c| c.due(t))
    }

    /// After a step: writes a checkpoint if one is due at the run's time.
    pub fn after_step(
        &mut self,
        sim: &Simulation,
        history: &History,
        logger: &Logger,
    ) -> anyhow::Result<()> {
        if !self.due(sim.flow().t()) {
            return Ok(());
        }
        self.write(sim, history, logger)
    }

    /// Writes a checkpoint of the run as it is now, once the `logger` has written the CSV's
    /// rows up to it: a run killed after this leaves a CSV that can resume from it.
    pub fn write(
        &mut self,
        sim: &Simulation,
        history: &History,
        logger: &Logger,
    ) -> anyhow::Result<()> {
        logger.flush_csv()?;
        self.write_state(RunState::Planar(Box::new(sim.save(history))))
    }

    /// Writes a checkpoint of `state` (its outputs' rows up to it already written).
    pub fn write_state(&mut self, state: RunState) -> anyhow::Result<()> {
        let start = Instant::now();
        let ckpt = Checkpoint {
            program: self.program.clone(),
            resume: self.info.clone(),
            sim: state,
        };
        self.bytes = write_checkpoint(&self.path, &ckpt)?;
        self.written += 1;
        self.seconds += start.elapsed().as_secs_f64();
        Ok(())
    }

    /// One line for the end of the run: where, how many, how big, how long.
    pub fn report_line(&self) -> String {
        format!(
            "checkpoint: {} ({:.1} MB; {} written in {:.2} s)",
            self.path.display(),
            self.bytes as f64 / 1e6,
            self.written,
            self.seconds
        )
    }
}

/// The checkpoint file: `--checkpoint`, else beside the CSV, the recording or the summary, else
/// `<case>.ckpt`.
pub fn checkpoint_path(
    args: &CheckpointArgs,
    record: &RecordArgs,
    summary: Option<&Path>,
    case: CaseKind,
) -> PathBuf {
    if let Some(p) = &args.checkpoint {
        return p.clone();
    }
    let save = (!record.no_save).then(|| {
        record
            .save
            .clone()
            .unwrap_or_else(|| RecordArgs::default_save_path(case))
    });
    record
        .csv
        .clone()
        .or(save)
        .or(summary.map(Path::to_path_buf))
        .map(|p| p.with_extension("ckpt"))
        .unwrap_or_else(|| PathBuf::from(format!("{case}.ckpt")))
}
