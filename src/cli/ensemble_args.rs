//! The `platefall ensemble` command line, turned into the ensemble's own request.
use std::path::PathBuf;

use clap::Args;
use platefall_core::config::EndTime;

use super::sweep_args::{ProgressMode, SlurmFlags};
use crate::exit::Exit;
use crate::sweep::ensemble::{self, EnsembleSpec};

const AFTER_HELP: &str = "\
Example (the card at N = 64: spun up to turn 11, then 8 members of 20 more turns, 4 at once):
  platefall free --resolution 64 --turns 11 --checkpoint spin.ckpt --csv spin.csv --no-save
  platefall ensemble --from spin.ckpt --members 8 --perturbation 1e-6 --turns 31 \\
      --average-from-turn 13 --jobs 4 --output ens/card

The members run as a sweep in DIR (DIR/cases/<id>/summary.json, run.csv, results.csv): a member \
whose summary is complete is not run again, so the same command resumes a stopped ensemble. The \
pooled statistics are DIR/ensemble.md and DIR/ensemble.json.

On a Slurm cluster, add --slurm (and the resources of each task): it writes DIR/sweep.sbatch, one \
array task per member not yet done, each `platefall sweep run-case DIR INDEX`; submit it with \
sbatch, and once the array has finished run the same command again: it pools the members (and \
writes a script for any that did not finish).";

/// Run M members branched from a spun-up run's checkpoint, each with its own seeded
/// perturbation of θ̇, and pool their means into ensemble means with 95 % intervals, the
/// members' independence and when they parted.
#[derive(Args, Debug)]
#[command(after_help = Exit::help(true), after_long_help = Exit::sweep_long_help(AFTER_HELP))]
pub struct EnsembleArgs {
    /// The spun-up run's checkpoint (a pinned or free run after its release).
    #[arg(long, value_name = "FILE")]
    pub from: PathBuf,
    /// Members M (2 or more).
    #[arg(long, short = 'm', value_name = "M")]
    pub members: usize,
    /// Size ε of the perturbations of θ̇ (rad per c/U): member k gets ε z_k, z_k the seeded
    /// standard normal numbers (0 < |ε| ≤ 0.01).
    #[arg(long, value_name = "EPS", allow_negative_numbers = true)]
    pub perturbation: f64,
    /// Seed of the perturbations (the same seed gives the same members; more members of one
    /// seed hold the fewer).
    #[arg(long, value_name = "S", default_value_t = 1)]
    pub seed: u64,
    /// Each member's end in net turns after release [default: the spun-up run's].
    #[arg(long, value_name = "N")]
    pub turns: Option<f64>,
    /// Each member's end time, in c/U (60) or, for a plate with physical units, in seconds
    /// (10.5s) [default: the spun-up run's].
    #[arg(long, value_name = "T", allow_negative_numbers = true)]
    pub t_end: Option<EndTime>,
    /// Average each member from this complete turn after release [default: two turns after
    /// the branch].
    #[arg(long, value_name = "K")]
    pub average_from_turn: Option<usize>,
    /// The members' checkpoint cadence [default: the spun-up run's].
    #[arg(long, value_name = "T", allow_negative_numbers = true)]
    pub checkpoint_every: Option<f64>,
    /// Worker threads of each member; the results do not depend on it.
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub threads: usize,
    /// Members run at once [default: one per core].
    #[arg(long, short = 'j', value_name = "N", conflicts_with = "slurm")]
    pub jobs: Option<usize>,
    /// The ensemble's directory.
    #[arg(long, value_name = "DIR")]
    pub output: PathBuf,
    /// Progress display on stderr.
    #[arg(long, value_enum, value_name = "MODE", default_value_t = ProgressMode::Auto)]
    pub progress: ProgressMode,
    /// Write DIR/sweep.sbatch (a Slurm job array, one task per member not yet done) and print
    /// how to submit it, instead of running the members here; once every member is done, the
    /// same command pools them.
    #[arg(long)]
    pub slurm: bool,
    #[command(flatten)]
    pub resources: SlurmFlags,
}

/// Runs `platefall ensemble ...`.
pub fn run_ensemble(args: &EnsembleArgs) -> Exit {
    let spec = EnsembleSpec {
        from: args.from.clone(),
        members: args.members,
        perturbation: args.perturbation,
        seed: args.seed,
        turns: args.turns,
        t_end: args.t_end,
        average_from_turn: args.average_from_turn,
        checkpoint_every: args.checkpoint_every,
        threads: args.threads,
    };
    let slurm = args.slurm.then(|| args.resources.overrides());
    ensemble::main(
        &spec,
        &args.output,
        args.jobs,
        args.progress.into(),
        slurm.as_ref(),
    )
}
