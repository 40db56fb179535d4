//! `platefall resume CHECKPOINT` of a 3-D run (docs/three-d.md "On the command line"): the run
//! is rebuilt from the checkpoint's command line (it must build the run the checkpoint holds;
//! only its end may change: `--t-end`, `--turns`), put back into the saved flow or flight, and
//! goes on. The CSV is rewritten as its rows up to the checkpoint (read back from the run's CSV,
//! or `--csv-from`) plus the new ones, byte for byte the uninterrupted run's; the summary is the
//! whole run's (the checkpoint holds every step's samples).
use std::path::PathBuf;

use super::checkpointer::Checkpointer;
use super::command::Command;
use super::resume_args::ResumeArgs;
use super::resume_checks::{already_over, resumed_config, ResumeRefusal};
use super::signals::Interrupts;
use super::span_outputs::{csv_header, Outputs};
use super::span_plate::flight_plate;
use super::span_recording::Recording;
use super::span_run::{go, span_of, SpanStart};
use crate::exit::Exit;
use crate::version::{program_and_commit, program_version as version};
use platefall_core::sim::turns_done;
use platefall_core::sim3::Run3;
use platefall_record::checkpoint::{ResumeInfo, SpanRun, SpanState};
use platefall_record::csv3::check_prefix3;
use platefall_record::options::ProgressMode;
use platefall_record::progress::Progress;
use platefall_record::provenance::Invocation;

/// Goes on with the 3-D run of `cmd` (the checkpoint's command line) from `state`.
pub(super) fn resume_span(
    args: &ResumeArgs,
    cmd: &Command,
    mut info: ResumeInfo,
    state: SpanState,
) -> anyhow::Result<Exit> {
    let Some((solver, span)) = cmd
        .case_args()
        .and_then(|(solver, _)| Some((solver, solver.span?)))
    else {
        anyhow::bail!(ResumeRefusal::CommandLine {
            file: args.file.clone(),
            why: "not a case subcommand with --span".into()
        });
    };
    for (given, flag) in [
        (args.perturb_omega.is_some(), "--perturb-omega"),
        (args.average_from_turn.is_some(), "--average-from-turn"),
    ] {
        if given {
            anyhow::bail!("{flag} is not available for 3-D runs yet (a --span checkpoint)");
        }
    }
    let given_every = args.checkpoint.given_every()?;
    let config = resumed_config(cmd, &info, args)?;
    let t = state.t();
    if over(&config.time, &state) {
        anyhow::bail!(already_over(args, t));
    }
    (info.t_end, info.turns) = (config.time.t_end, config.time.turns);
    let (run, cells) = span_of(&config, solver, span)?;
    let (plate, _) = flight_plate(cmd, span)?;
    let csv = args.csv.clone().or(info.csv.clone());
    let summary = args.summary.clone().or(info.summary.clone());
    let earlier = args.csv_from.clone().or(info.csv.clone());
    let csv_pair = match (&csv, &earlier, &args.csv_from) {
        (Some(c), Some(e), _) => Some((c.as_path(), e.as_path())),
        (None, _, Some(from)) => anyhow::bail!(ResumeRefusal::CsvFromWithoutCsv(from.clone())),
        _ => None,
    };
    if let Some((_, earlier)) = csv_pair {
        check_prefix3(earlier, csv_header(cmd), state.steps())
            .map_err(|why| ResumeRefusal::Csv(why.to_string()))?;
    }
    let mut out = Outputs::resume(csv_pair, cmd, cells, &state)?;
    out.recording = continuation(args, cmd, &info, (&run, cells), state.steps())?;
    let mode = cmd.case_args().map_or(ProgressMode::Off, |(_, record)| {
        let mut r = record.clone();
        args.apply_progress(&mut r);
        r.progress_mode()
    });
    out.progress = Some(Progress::new(mode, config.time.t_end));
    let abs = |p: &Option<PathBuf>| p.as_deref().map(std::path::absolute).transpose();
    (info.csv, info.summary) = (abs(&csv)?, abs(&summary)?);
    info.every = given_every.or(info.every);
    let every = info.every;
    let interrupts = Interrupts::install()?;
    let path = args.checkpoint_out();
    let start = SpanStart {
        plate: matches!(cmd, Command::Free(_)).then_some(plate),
        run,
        out,
        restored: Some(state.run),
        checkpoints: Some(Checkpointer::new(path, every, t, info, version())),
        summary,
        threads: args.threads.unwrap_or(solver.threads),
        stop_after: args.checkpoint.stop_after_steps,
        // (The continuation's own invocation: `platefall resume FILE`.)
        invocation: Invocation::of_this_process(program_and_commit(), Vec::new()),
    };
    go(start, &interrupts)
}

/// The continuation recording of a run that recorded: `--save`, else the run's recording with
/// `-from-STEP` before `.rrd`, with the run's recording id (the viewer opens both as one run);
/// none with `--no-save` or for a run that did not record.
fn continuation(
    args: &ResumeArgs,
    cmd: &Command,
    info: &ResumeInfo,
    (run, cells): (&Run3, usize),
    steps: u64,
) -> anyhow::Result<Option<Recording>> {
    let save = match (&args.save, &info.save) {
        _ if args.no_save => None,
        (Some(p), _) => Some(p.clone()),
        (None, Some(p)) => Some(super::continued::continuation(p, steps)),
        (None, None) => None,
    };
    let Some((save, (_, record))) = save.zip(cmd.case_args()) else {
        return Ok(None);
    };
    let mut record = record.clone();
    (record.save, record.no_save, record.vtk) = (Some(save), false, None);
    (record.serve, record.web, record.spawn, record.connect) = (false, false, false, None);
    Recording::start(cmd, run, &record, cells, info.recording_id.clone())
}

/// Whether the run in `state` is already over under `time`'s end and turn limit.
fn over(time: &platefall_core::sim::TimeControl, state: &SpanState) -> bool {
    let turned = match &state.run {
        SpanRun::Flight {
            pitch,
            theta_release,
            ..
        } => turns_done(time.turns, *pitch, *theta_release),
        SpanRun::Prescribed(_) => false,
    };
    state.t() >= time.t_end - 1e-9 || turned
}
