//! The `platefall converge` command line, turned into the study's own [`ConvergeRequest`].
use std::path::PathBuf;

use clap::{Args, Subcommand};

use super::sweep_args::ProgressMode;
use crate::exit::Exit;
use crate::sweep::converge::ConvergeRequest;

const AFTER_HELP: &str = "\
Example (the card's free fall, its plate 1/64 chord thick at every N, averaged over turns 11-30):
  platefall converge --refine resolution=32,64,128 --output conv/card -- \\
      free --turns 30 --average-from-turn 10

The levels run as a sweep in DIR (DIR/plan.toml, DIR/cases/<id>/summary.json, results.csv): a level \
whose summary is complete is not run again, so the same command resumes a stopped study. The study \
is DIR/convergence.md and DIR/convergence.json; `platefall converge collect DIR` rewrites them from \
the finished levels.

With --ensembles the levels are ensembles already pooled (`platefall ensemble`, one directory per \
value), so that the members' spread, not one run's, decides which differences are resolved:
  platefall converge --refine resolution=64,128,256 --ensembles ens/64,ens/128,ens/256 \
      --output conv/card-ens";

/// Run one case at three or more values of a refined option (resolution, cc, cfl, dt-max or
/// extent) and report, per quantity of its summary, the observed order of convergence, the
/// Richardson extrapolation and the grid-convergence index, with the runs' 95 % intervals deciding
/// which differences are resolved.
#[derive(Args, Debug)]
#[command(
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    after_help = Exit::help(true),
    after_long_help = Exit::sweep_long_help(AFTER_HELP)
)]
pub struct ConvergeArgs {
    #[command(subcommand)]
    pub action: Option<ConvergeAction>,
    /// The refined option and its values, e.g. `resolution=32,64,128` (at least three; also cc,
    /// cfl, dt-max or extent).
    #[arg(long, value_name = "OPTION=V1,V2,V3", required = true)]
    pub refine: Option<String>,
    /// The study's directory (the levels' runs and the study itself).
    #[arg(long, value_name = "DIR", required = true)]
    pub output: Option<PathBuf>,
    /// Levels run at once.
    #[arg(long, short = 'j', value_name = "N", default_value_t = 1)]
    pub jobs: usize,
    /// Worker threads of each level's run [default: the cores divided among the --jobs]; a
    /// `--threads` among the case's options takes precedence.
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// Progress display on stderr.
    #[arg(long, value_enum, value_name = "MODE", default_value_t = ProgressMode::Auto)]
    pub progress: ProgressMode,
    /// Levels that are ensembles pooled by `platefall ensemble`, one directory per value of
    /// --refine in the same order: each level's value and 95 % half-width are the pooled ones,
    /// and nothing runs.
    #[arg(
        long,
        value_name = "DIR1,DIR2,DIR3",
        value_delimiter = ',',
        conflicts_with_all = ["case", "jobs", "threads"]
    )]
    pub ensembles: Option<Vec<PathBuf>>,
    /// The case and its options, as on its own command line (`free --turns 30 ...`).
    #[arg(
        value_name = "CASE [OPTIONS]",
        trailing_var_arg = true,
        allow_hyphen_values = true,
        required_unless_present = "ensembles"
    )]
    pub case: Vec<String>,
}

/// What `converge` does besides running a study.
#[derive(Subcommand, Debug)]
pub enum ConvergeAction {
    /// Rewrite DIR/convergence.md and .json from the levels that have finished.
    Collect {
        /// The study's directory.
        #[arg(value_name = "DIR")]
        dir: PathBuf,
    },
}

impl ConvergeArgs {
    /// The study's request (clap has checked that `--refine` and `--output` are given).
    pub(super) fn request(&self) -> ConvergeRequest {
        match &self.action {
            Some(ConvergeAction::Collect { dir }) => ConvergeRequest::Collect { dir: dir.clone() },
            None if self.ensembles.is_some() => ConvergeRequest::Ensembles {
                refine: self.refine.clone().unwrap_or_default(),
                dirs: self.ensembles.clone().unwrap_or_default(),
                output: self.output.clone().unwrap_or_default(),
            },
            None => ConvergeRequest::Run {
                refine: self.refine.clone().unwrap_or_default(),
                output: self.output.clone().unwrap_or_default(),
                jobs: self.jobs,
                threads: self.threads,
                progress: self.progress.into(),
                case: self.case.clone(),
            },
        }
    }
}
