//! The `platefall sweep` command line, turned into the sweep's own [`SweepRequest`].
use std::path::PathBuf;

use clap::{Args, Subcommand, ValueEnum};

use crate::exit::Exit;
use crate::sweep::{self, SlurmOverrides, SweepRequest};

/// Shown after `platefall sweep --help` (before the exit codes).
const AFTER_HELP: &str = "\
A plan names a case, its fixed options ([fixed]), the swept ones ([grid]: every combination; [zip]: \
advanced together; lists [a, b] or ranges { from = A, to = B, count = N, scale = \"log\" }), the \
output directory, [outputs] recording and vtk, the [diagram] axes and value, and [slurm] resources. See \
examples/sweep-static.toml and docs/user-guide.md, \"Parameter sweeps\".

A case is done when DIR/cases/<id>/summary.json says completed or diverged; rerunning the plan runs \
only the others. Ctrl-C stops launching, lets the running cases finalise and merges the results.";

/// Run a parameter sweep of one case from a plan file (TOML): locally with --jobs cases at once,
/// or as a Slurm job array with --slurm; `collect` merges a directory's finished cases.
#[derive(Args, Debug)]
#[command(
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    after_help = Exit::help(true),
    after_long_help = Exit::sweep_long_help(AFTER_HELP)
)]
pub struct SweepArgs {
    #[command(subcommand)]
    pub action: Option<SweepAction>,
    /// The plan file (see docs/user-guide.md, "Parameter sweeps").
    #[arg(value_name = "PLAN.toml", required = true)]
    pub plan: Option<PathBuf>,
    /// Cases run at once [default: the number of cores].
    #[arg(long, short = 'j', value_name = "N")]
    pub jobs: Option<usize>,
    /// Check the plan and list the cases (and which are done) without running anything.
    #[arg(long)]
    pub dry_run: bool,
    /// The output directory [default: the plan's `output`].
    #[arg(long, value_name = "DIR")]
    pub output: Option<PathBuf>,
    /// Progress display on stderr.
    #[arg(long, value_enum, value_name = "MODE", default_value_t = ProgressMode::Auto)]
    pub progress: ProgressMode,
    /// Write DIR/sweep.sbatch (a Slurm job array, one task per case not yet done) and print how to
    /// submit it, instead of running the cases here.
    #[arg(long)]
    pub slurm: bool,
    #[command(flatten)]
    pub resources: SlurmFlags,
}

/// Resources of each Slurm array task (override the plan's `[slurm]`).
#[derive(Args, Debug, Clone, Default)]
#[command(next_help_heading = "Slurm (with --slurm)")]
pub struct SlurmFlags {
    /// Partition to submit to.
    #[arg(long, value_name = "NAME", requires = "slurm")]
    pub partition: Option<String>,
    /// Wall-time limit per case, as sbatch takes it (e.g. 01:00:00).
    #[arg(long, value_name = "TIME", requires = "slurm")]
    pub time: Option<String>,
    /// Memory per case, as sbatch takes it (e.g. 2G).
    #[arg(long, value_name = "MEM", requires = "slurm")]
    pub mem: Option<String>,
    /// CPUs per case.
    #[arg(long, value_name = "N", requires = "slurm")]
    pub cpus: Option<u32>,
    /// At most this many array tasks at once.
    #[arg(long, value_name = "N", requires = "slurm")]
    pub max_parallel: Option<u32>,
    /// Seconds before the time limit at which Slurm sends each case SIGUSR1, to checkpoint and
    /// stop [default: 120, or a quarter of a shorter time limit].
    #[arg(long, value_name = "S", requires = "slurm")]
    pub signal_lead: Option<u32>,
}

impl SlurmFlags {
    /// The resources these flags give.
    pub(super) fn overrides(&self) -> SlurmOverrides {
        SlurmOverrides {
            partition: self.partition.clone(),
            time: self.time.clone(),
            mem: self.mem.clone(),
            cpus: self.cpus,
            max_parallel: self.max_parallel,
            signal_lead: self.signal_lead,
        }
    }
}

/// The sweep's own subcommands.
#[derive(Subcommand, Debug)]
pub enum SweepAction {
    /// Merge whatever has finished in a sweep directory into results.csv, results.json and the
    /// phase diagram, and list the cases that are missing and why.
    Collect {
        /// The sweep directory.
        #[arg(value_name = "DIR")]
        dir: PathBuf,
    },
    /// Run one case of a prepared sweep directory (what each Slurm array task runs).
    RunCase {
        /// The sweep directory.
        #[arg(value_name = "DIR")]
        dir: PathBuf,
        /// The case's index (0-based; Slurm's $SLURM_ARRAY_TASK_ID).
        #[arg(value_name = "INDEX")]
        index: usize,
    },
}

/// How progress is shown on stderr.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ProgressMode {
    /// A bar on a terminal, one line per finished case otherwise.
    Auto,
    /// Always the bar.
    Bar,
    /// One line per finished case.
    Lines,
    /// Nothing.
    Off,
}

impl From<ProgressMode> for sweep::ProgressMode {
    fn from(mode: ProgressMode) -> Self {
        match mode {
            ProgressMode::Auto => sweep::ProgressMode::Auto,
            ProgressMode::Bar => sweep::ProgressMode::Bar,
            ProgressMode::Lines => sweep::ProgressMode::Lines,
            ProgressMode::Off => sweep::ProgressMode::Off,
        }
    }
}

/// A `platefall sweep` command line that asks for nothing the sweep can do.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SweepArgsError {
    /// Neither a plan file nor a subcommand (`collect`, `run-case`).
    #[error("give a plan file: platefall sweep PLAN.toml")]
    NoPlan,
}

impl SweepArgs {
    /// The sweep's request.
    ///
    /// # Errors
    /// [`SweepArgsError::NoPlan`] without a plan file or a subcommand.
    pub(super) fn request(&self) -> Result<SweepRequest, SweepArgsError> {
        Ok(match &self.action {
            Some(SweepAction::Collect { dir }) => SweepRequest::Collect { dir: dir.clone() },
            Some(SweepAction::RunCase { dir, index }) => SweepRequest::RunCase {
                dir: dir.clone(),
                index: *index,
            },
            None => SweepRequest::Run {
                plan: self.plan.clone().ok_or(SweepArgsError::NoPlan)?,
                jobs: self.jobs,
                dry_run: self.dry_run,
                output: self.output.clone(),
                progress: self.progress.into(),
                slurm: self.slurm.then(|| self.resources.overrides()),
            },
        })
    }
}
