//! `platefall resume CHECKPOINT`: goes on with a run from its checkpoint. The run description is
//! rebuilt from the checkpoint's command line and must be the one the checkpoint holds; only its
//! end may change (`--t-end`, `--turns`). The CSV is rewritten as the earlier rows plus the new
//! ones (byte for byte the uninterrupted run's), the summary is the whole run's, and the
//! recording is a continuation `.rrd` with the same recording id (the viewer opens both as one).
use std::path::{Path, PathBuf};

use anyhow::Context as _;

use super::branch;
use super::checkpointer::Checkpointer;
use super::command::parse;
use super::record_args::RecordArgs;
use super::resume_args::ResumeArgs;
use super::resume_checks::{already_over, resumed_config, ResumeRefusal};
use super::run::{command_line, execute, Started};
use super::signals::Interrupts;
use crate::exit::Exit;
use crate::version::program_and_commit;
use crate::version::program_version as version;
use platefall_core::sim::{CaseKind, Simulation};
use platefall_record::checkpoint::{read_checkpoint, Checkpoint, ResumeInfo, RunState};
use platefall_record::messages::RunInfo;
use platefall_record::provenance::Invocation;
use platefall_record::RecordOptions;

/// Runs `platefall resume`.
pub fn run_resume(args: &ResumeArgs) -> anyhow::Result<Exit> {
    let given_every = args.checkpoint.given_every()?;
    let mut ckpt = read_checkpoint(&args.file, &version())?;
    let cmd = parse(&ckpt.resume.argv).map_err(|e| ResumeRefusal::CommandLine {
        file: args.file.clone(),
        why: e.kind().to_string(),
    })?;
    if let RunState::Span(state) = ckpt.sim {
        let (resume, state) = (ckpt.resume, *state);
        return super::span_resume::resume_span(args, &cmd.command, resume, state);
    }
    if let (Some(d), Some(sim)) = (args.perturb_omega, ckpt.sim.planar_mut()) {
        branch::own_checkpoint(&args.file, &args.checkpoint_out())?;
        branch::perturb_omega(sim, d)?;
    }
    let Some((solver, record)) = cmd.command.case_args() else {
        anyhow::bail!(ResumeRefusal::CommandLine {
            file: args.file.clone(),
            why: "not a case subcommand".into()
        });
    };
    let config = resumed_config(&cmd.command, &ckpt.resume, args)?;
    let mut info = ckpt.resume.clone();
    (info.t_end, info.turns) = (config.time.t_end, config.time.turns);
    if let Some(turn) = args.average_from_turn {
        branch::set_average_from_turn(&mut info, turn)?;
    }
    let opts = resumed_outputs(record, &mut info, &ckpt, args, config.case.kind())?;
    let every = given_every.or(info.every);
    info.every = every;
    let interrupts = Interrupts::install()?;
    // (The continuation's own invocation: `platefall resume FILE`.)
    let invocation = Invocation::of_this_process(program_and_commit(), Vec::new());
    let run_info = RunInfo::new(&config, command_line(), version()).with_invocation(invocation);
    let t = ckpt.sim.t();
    let RunState::Planar(saved) = ckpt.sim else {
        anyhow::bail!("checkpoint {}: not a 2-D run's", args.file.display());
    };
    let (sim, history) = Simulation::restore(config, *saved)?;
    if sim.finished() {
        anyhow::bail!(already_over(args, t));
    }
    let path = args.checkpoint_out();
    let started = Started {
        sim,
        history,
        summary_path: info.summary.clone(),
        opts,
        threads: args.threads.unwrap_or(solver.threads),
        checkpoints: Some(Checkpointer::new(path, every, t, info, version())),
        stop_after: args.checkpoint.stop_after_steps,
    };
    execute(started, run_info, &interrupts)
}

/// The resumed run's outputs: the run's own (the CSV rewritten with its earlier rows, a
/// continuation recording), or those given (a branch: only those given); `info` takes them
/// for the next checkpoint.
fn resumed_outputs(
    record: &RecordArgs,
    info: &mut ResumeInfo,
    ckpt: &Checkpoint,
    args: &ResumeArgs,
    kind: CaseKind,
) -> anyhow::Result<RecordOptions> {
    let steps = ckpt.sim.steps();
    let mut r = record.clone();
    // A branch (an ensemble member) writes only the outputs it names (branch.rs).
    let branch = args.perturb_omega.is_some();
    let run_own = |p: &Option<PathBuf>| p.clone().filter(|_| !branch);
    r.csv = args.csv.clone().or(run_own(&info.csv));
    r.save = match (&args.save, run_own(&info.save)) {
        (Some(p), _) => Some(p.clone()),
        (None, Some(p)) => Some(super::continued::continuation(&p, steps)),
        (None, None) => None,
    };
    r.no_save = args.no_save || r.save.is_none();
    args.apply_progress(&mut r);
    let summary = args.summary.clone().or(run_own(&info.summary));
    let ckpt_path = args.checkpoint_out();
    let others: Vec<(&'static str, &Path)> = summary
        .iter()
        .map(|p| ("--summary", p.as_path()))
        .chain([("--checkpoint", ckpt_path.as_path())])
        .collect();
    let mut opts = r.resolve(kind, &others)?;
    let earlier = args.csv_from.as_ref().or(info.csv.as_ref());
    opts.csv_prefix = match (&opts.csv, earlier, &args.csv_from) {
        (Some(_), Some(earlier), from) => {
            platefall_record::check_csv_prefix(earlier, steps).map_err(|why| {
                let hint = from
                    .is_none()
                    .then(|| partial_with_rows(earlier, steps))
                    .flatten();
                ResumeRefusal::Csv(match hint {
                    Some(p) => format!("{why}; add --csv-from {} (it holds them)", p.display()),
                    None => why.to_string(),
                })
            })?;
            Some((earlier.clone(), steps))
        }
        (None, _, Some(from)) => return Err(ResumeRefusal::CsvFromWithoutCsv(from.clone()).into()),
        _ => None,
    };
    opts.recording_id = info.recording_id.clone();
    let abs = |p: &Option<PathBuf>| p.as_deref().map(std::path::absolute).transpose();
    if branch {
        info.save = abs(&args.save).context("the recording's path")?;
    }
    info.csv = abs(&opts.csv).context("the CSV's path")?;
    info.summary = abs(&summary).context("the summary's path")?;
    Ok(opts)
}

/// A `.NAME.partial-PID` file beside `csv` (left by a run of this CSV killed outright) that
/// holds the first `rows` rows, to name in the refusal.
fn partial_with_rows(csv: &Path, rows: u64) -> Option<PathBuf> {
    let mut found: Vec<PathBuf> = platefall_record::output::partials_of(csv)
        .into_iter()
        .map(|(p, _)| p)
        .filter(|p| platefall_record::check_csv_prefix(p, rows).is_ok())
        .collect();
    found.sort();
    found.pop()
}
