//! `platefall resume`'s options, below the command that takes them (`command.rs`) and the resume
//! itself (`resume.rs`), which parses a checkpoint's command line with that command.
use std::path::PathBuf;

use clap::Args;

use super::args::CheckpointArgs;
use super::record_args::{ProgressArg, RecordArgs};
use platefall_core::config::EndTime;

/// `platefall resume`'s options (the checkpoint options are a case run's, with resume's defaults).
#[derive(Args, Debug, Clone)]
#[command(
    mut_arg("checkpoint_every", |a| a.help("Checkpoint cadence [default: the run's]")),
    mut_arg("checkpoint", |a| a.help("The checkpoint file to write [default: the one resumed from]"))
)]
pub struct ResumeArgs {
    /// The checkpoint file (written by --checkpoint-every or at a stop)
    pub file: PathBuf,
    /// A new end time (later than the checkpoint's time), in c/U (60) or, for a plate with
    /// physical units, in seconds (10.5s) [default: the run's]
    #[arg(long, value_name = "T", allow_negative_numbers = true)]
    pub t_end: Option<EndTime>,
    /// A new number of net turns after release [default: the run's]
    #[arg(long, value_name = "N")]
    pub turns: Option<f64>,
    /// Worker threads (0: one per core) [default: the run's]; the results do not depend on it
    #[arg(long)]
    pub threads: Option<usize>,
    /// The CSV [default: the run's; it is rewritten with the earlier rows first]
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Take the earlier rows from this CSV: the `.NAME.partial-PID` file of a run that was
    /// killed outright (it holds the rows up to its last checkpoint) [default: the run's CSV]
    #[arg(long, value_name = "FILE")]
    pub csv_from: Option<PathBuf>,
    /// The continuation recording [default: the run's with -from-STEP before .rrd]
    #[arg(long, value_name = "FILE.rrd", conflicts_with = "no_save")]
    pub save: Option<PathBuf>,
    /// No continuation recording
    #[arg(long)]
    pub no_save: bool,
    /// The summary JSON [default: the run's]
    #[arg(long, value_name = "FILE")]
    pub summary: Option<PathBuf>,
    /// No progress output
    #[arg(long, short = 'q')]
    pub quiet: bool,
    /// Progress display on stderr [default: the run's]
    #[arg(long, value_enum, value_name = "MODE")]
    pub progress: Option<ProgressArg>,
    /// Branch an ensemble member: add D to the plate's angular velocity θ̇ (rad per c/U) before
    /// going on (pinned and free runs)
    #[arg(long, value_name = "D", allow_negative_numbers = true)]
    pub perturb_omega: Option<f64>,
    /// Average the summary's means from this complete turn after release on [default: the
    /// run's]
    #[arg(long, value_name = "K")]
    pub average_from_turn: Option<usize>,
    // --checkpoint-every, --checkpoint: a case run's options, with resume's defaults (above).
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
}

impl ResumeArgs {
    /// The checkpoint file to write: `--checkpoint`, else the one resumed from.
    pub(super) fn checkpoint_out(&self) -> PathBuf {
        let given = self.checkpoint.checkpoint.as_ref();
        given.unwrap_or(&self.file).clone()
    }

    /// The run's recording options `r` with resume's progress choices: `--progress MODE`
    /// replaces the run's (and its `-q`), `-q` turns progress off (2-D and 3-D resumes alike).
    pub(super) fn apply_progress(&self, r: &mut RecordArgs) {
        if let Some(p) = self.progress {
            (r.progress, r.quiet) = (p, false);
        }
        r.quiet |= self.quiet;
    }
}
