//! The command line's grammar: the subcommands and their options (clap), and the one function
//! that parses an argument vector.
use std::ffi::OsString;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

use super::args::{ForcedArgs, FreeArgs, PinnedArgs, SolverArgs, StaticArgs};
use super::bench_args::BenchArgs;
use super::converge_args::ConvergeArgs;
use super::ensemble_args::EnsembleArgs;
use super::info::InfoArgs;
use super::record_args::RecordArgs;
use super::reproduce_args::ReproduceArgs;
use super::resume_args::ResumeArgs;
use super::sweep_args::SweepArgs;
use crate::exit::Exit;

/// A thin plate falling through a viscous fluid: 2-D Navier–Stokes in a body-fixed grid coupled to
/// the plate's flight mechanics, streamed live to the Rerun viewer.
///
/// All quantities are non-dimensional: lengths on the chord c, speeds on the reference speed U,
/// time on c/U (one "convective time").
#[derive(Parser, Debug)]
#[command(
    name = "platefall",
    version = crate::version::VERSION,
    about,
    long_about,
    propagate_version = true,
    after_help = Exit::help(false)
)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Case A: a plate impulsively started at a fixed angle of attack (vortex shedding, C_L, C_D, Strouhal).
    #[command(after_help = Exit::help(false))]
    Static(StaticArgs),
    /// Case B: a translating plate spun up at constant angular acceleration to a rate, then held.
    #[command(after_help = Exit::help(false))]
    Forced(ForcedArgs),
    /// Case C: a translating plate free to rotate about its centre (pinned autorotation).
    #[command(after_help = Exit::help(false))]
    Pinned(PinnedArgs),
    /// Case D: a plate released into free fall under gravity (the tumbling card).
    #[command(after_help = Exit::help(false))]
    Free(FreeArgs),
    /// Time the flow step alone on several grid sizes (ns per cell per step, momentum vs pressure).
    Bench(BenchArgs),
    /// Run a parameter sweep from a plan file, locally or as a Slurm job array, and merge it into
    /// a results table and a phase diagram.
    Sweep(SweepArgs),
    /// Run a case at three or more resolutions (or time steps, domain sizes) and report the
    /// observed order, the Richardson extrapolation and the grid-convergence index per quantity,
    /// with the runs' 95 % intervals deciding which differences are resolved.
    Converge(ConvergeArgs),
    /// Run M members branched from a spun-up run's checkpoint, each with its own small
    /// perturbation of θ̇, and pool their means into ensemble means with 95 % intervals.
    Ensemble(EnsembleArgs),
    /// Continue a run from its checkpoint (--checkpoint-every, or a stop by SIGTERM, SIGUSR1 or
    /// Ctrl-C), exactly as if it had not stopped; or extend a completed one (--t-end, --turns).
    #[command(after_help = Exit::help(false))]
    Resume(ResumeArgs),
    /// What a recording is: the run's title, the program and commit that made it, its command
    /// line, input files, steps, report and configuration (with --json also its summary JSON).
    Info(InfoArgs),
    /// Run a recording's run again from the recording alone (its arguments and input files) and
    /// compare every recorded step with it bit for bit: "identical", or the first step, time and
    /// quantity where they part, with both values.
    Reproduce(ReproduceArgs),
}

impl Command {
    /// The options every case subcommand shares: the solver's and the recording's (None for bench
    /// sweep and converge).
    pub fn case_args(&self) -> Option<(&SolverArgs, &RecordArgs)> {
        match self {
            Command::Static(a) => Some((&a.solver, &a.record)),
            Command::Forced(a) => Some((&a.solver, &a.record)),
            Command::Pinned(a) => Some((&a.solver, &a.record)),
            Command::Free(a) => Some((&a.solver, &a.record)),
            Command::Bench(_)
            | Command::Sweep(_)
            | Command::Converge(_)
            | Command::Ensemble(_)
            | Command::Resume(_)
            | Command::Info(_)
            | Command::Reproduce(_) => None,
        }
    }
}

/// Parses an argument vector (the program's name first): the process's own, or the one a sweep
/// case's child process will be started with.
pub fn parse<I, T>(argv: I) -> Result<Cli, clap::Error>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let matches = super::whole::negatives_named(Cli::command()).try_get_matches_from(argv)?;
    Cli::from_arg_matches(&matches)
}
