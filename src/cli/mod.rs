//! The command line: one subcommand per case (SPEC §1) plus `bench`. The only layer that knows
//! clap; it turns flags into the library's typed descriptions and its typed errors into one-line
//! messages that name the flag.
pub mod args;
pub mod bench;
pub mod flags;
pub mod limits;
pub mod plate_args;
pub mod record_args;
pub mod run;
pub mod shape_args;
pub mod signals;
pub mod threads;

use clap::{Parser, Subcommand};

pub use args::{
    plate_notes, run_config, BodyArgs, FarFieldArg, ForcedArgs, FreeArgs, PinnedArgs, SolverArgs,
    StaticArgs,
};
pub use bench::BenchArgs;
pub use flags::ArgError;
pub use record_args::RecordArgs;

/// The exit codes, shown by `--help` (each means one thing; see the README "Exit codes").
pub const EXIT_CODES: &str = "Exit codes:
  0    completed (every output complete at its final name)
  2    bad input: one line names the value and what is accepted; nothing was run or written
  3    the solution diverged; the outputs hold the run up to then and say so
  4    an output could not be written (disk full, permissions, directory removed, sink error):
       nothing incomplete is left at its final name
  130  interrupted (Ctrl-C, SIGTERM); the outputs hold the run up to then and say so.
       A second Ctrl-C quits at once, leaving unfinished outputs as .NAME.partial-PID files";

/// A thin plate falling through a viscous fluid: 2-D Navier–Stokes in a body-fixed grid coupled to
/// the plate's flight mechanics, streamed live to the Rerun viewer.
///
/// All quantities are non-dimensional: lengths on the chord c, speeds on the reference speed U,
/// time on c/U (one "convective time").
#[derive(Parser, Debug)]
#[command(
    name = "platefall",
    version,
    about,
    long_about,
    propagate_version = true,
    after_help = EXIT_CODES
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Case A: a plate impulsively started at a fixed angle of attack (vortex shedding, C_L, C_D, Strouhal).
    #[command(after_help = EXIT_CODES)]
    Static(StaticArgs),
    /// Case B: a translating plate spun up at constant angular acceleration to a rate, then held.
    #[command(after_help = EXIT_CODES)]
    Forced(ForcedArgs),
    /// Case C: a translating plate free to rotate about its centre (pinned autorotation).
    #[command(after_help = EXIT_CODES)]
    Pinned(PinnedArgs),
    /// Case D: a plate released into free fall under gravity (the tumbling card).
    #[command(after_help = EXIT_CODES)]
    Free(FreeArgs),
    /// Time the flow step alone on several grid sizes (ns per cell per step, momentum vs pressure).
    Bench(BenchArgs),
    /// Run a parameter sweep from a plan file, locally or as a Slurm job array, and merge it into
    /// a results table and a phase diagram.
    Sweep(crate::sweep::SweepArgs),
}

impl Command {
    /// The options every case subcommand shares: the solver's and the recording's (None for bench).
    pub fn case_args(&self) -> Option<(&SolverArgs, &RecordArgs)> {
        match self {
            Command::Static(a) => Some((&a.solver, &a.record)),
            Command::Forced(a) => Some((&a.solver, &a.record)),
            Command::Pinned(a) => Some((&a.solver, &a.record)),
            Command::Free(a) => Some((&a.solver, &a.record)),
            Command::Bench(_) | Command::Sweep(_) => None,
        }
    }
}
