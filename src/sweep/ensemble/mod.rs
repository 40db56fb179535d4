//! `platefall ensemble`: M members branched from one spun-up run's checkpoint, each a `platefall
//! resume --perturb-omega` of it with its own seeded perturbation of θ̇, run as a sweep of child
//! processes in an output directory (or, with `--slurm`, as the tasks of a Slurm job array that
//! fill the same directory), and pooled (docs/statistics.md, "Ensembles of independent
//! members"): per summary quantity the ensemble mean with its 95 % interval from the members'
//! means, combined with their own intervals where the F test allows, Σ n_eff and the
//! independence verdict; and when the members' θ̇ parted, measured from their separation.
//!
//! The directory is a sweep's (`cases/<id>/summary.json`, `run.csv`, `results.csv`, the
//! members' regimes along their perturbation in `phase.png`) plus `ensemble.json`,
//! `ensemble.md`, `histograms.png` (the members' means, under the pooled mean and interval) and
//! `ensemble.rrd` (every member overlaid, for the viewer). Members whose summaries are complete
//! are not run again: the same command goes on with only the missing ones.
//!
//! Files, each using only those after it: `run` (the command), `histograms` (the figure of
//! the pooled quantities), `pooled` (the members'
//! summaries pooled, and the table), `parting` (their decorrelation from their CSVs), `traces`
//! (the CSVs' columns read back), `members` (the request checked against the checkpoint, and
//! each member's command line).
mod histograms;
mod members;
mod parting;
mod pooled;
mod run;
mod traces;

pub(crate) use members::EnsembleSpec;
pub(crate) use run::main;
