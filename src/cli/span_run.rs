//! `static`, `forced` and `free` with `--span` (docs/three-d.md "Cases", "On the command line"):
//! the case's options run the 3-D flow (`sim3::Run3`), writing the 3-D CSV, the summary (the 2-D
//! keys of the run's projection and the 3-D keys), the report and, when asked, checkpoints
//! (`span_steps.rs`; `platefall resume` of them: `span_resume.rs`) and the 3-D recording
//! (`span_recording.rs`). Options a 3-D run cannot honour yet are refused.
use std::path::{Path, PathBuf};
use std::time::Instant;

use super::args::SolverArgs;
use super::checkpointer::Checkpointer;
use super::command::Command;
use super::config::{plate_notes, run_config};
use super::limits::memory_limit;
use super::record_args::RecordArgs;
use super::shape_args::ShapeKind;
use super::signals::{Interrupts, Phase};
use super::span_cost::{cost_line, PhaseClock};
use super::span_outputs::{Outputs, Stop};
use super::span_plate::flight_plate;
use super::span_recording::{save_path, Recording};
use super::span_steps::{Control, Mover};
use crate::exit::Exit;
use crate::version::program_version as version;
use platefall_core::body::six::Plate6;
use platefall_core::flow3d::{Grid3, Span, BYTES_PER_CELL};
use platefall_core::sim::{RunConfig, RunRecord, RunStatus, SimError};
use platefall_core::sim3::Run3;
use platefall_post::summary3::{report3, summarize3};
use platefall_record::checkpoint::{ResumeInfo, SpanRun};
use platefall_record::files::check_writable;
use platefall_record::messages::RunOutcome;
use platefall_record::progress::Progress;
use platefall_record::provenance::Invocation;

/// The first option given that a 3-D run cannot honour yet.
fn unavailable(cmd: &Command) -> Option<&'static str> {
    let solver = cmd.case_args()?.0;
    let given = [
        (matches!(cmd, Command::Pinned(_)), "pinned --span"),
        (
            solver.section.body3().is_none(),
            "--shape rounded, nacaMPTT or polygon",
        ),
        (
            matches!(cmd, Command::Free(_)) && solver.section.shape != ShapeKind::Rect,
            "free --span with --shape other than rect",
        ),
        (solver.seed_grid, "--seed-grid"),
    ];
    given.iter().find(|g| g.0).map(|g| g.1)
}

/// A free fall in 3-D flies the card or a physical plate, not non-dimensional values.
fn non_dimensional_plate(cmd: &Command) -> Option<&'static str> {
    let Command::Free(a) = cmd else { return None };
    let b = &a.body;
    let given = [
        (b.preset.is_some(), "--preset"),
        (b.mass.is_some(), "--mass"),
        (b.inertia.is_some(), "--inertia"),
        (b.gravity.is_some(), "--gravity"),
        (b.displaced_mass.is_some(), "--displaced-mass"),
        (b.torque != 0.0, "--torque"),
    ];
    given.iter().find(|g| g.0).map(|g| g.1)
}

/// Runs a case with `--span` to its end; the exit code says how it ended.
pub fn run_span(cmd: &Command, span: Span) -> anyhow::Result<Exit> {
    let Some((solver, record)) = cmd.case_args() else {
        anyhow::bail!("not a case subcommand");
    };
    if let Some(flag) = unavailable(cmd) {
        anyhow::bail!("{flag} is not available for 3-D runs yet (with --span)");
    }
    if let Some(flag) = non_dimensional_plate(cmd) {
        anyhow::bail!(
            "{flag} is not available for 3-D runs yet: free --span flies the card or a physical \
             plate (--chord-mm, --thickness-mm, --plate-density)"
        );
    }
    let config = run_config(cmd)?;
    let (run, cells) = span_of(&config, solver, span)?;
    let plate = flight_plate(cmd, span)?;
    for (flag, path) in [("--csv", &record.csv), ("--summary", &solver.summary)] {
        if let Some(p) = path {
            check_writable(p, false).map_err(|r| anyhow::anyhow!("{flag} {}: {r}", p.display()))?;
        }
    }
    // A recording that may be continued by `resume` has an id of its own.
    let id = record.uses_rerun().then(super::continued::new_recording_id);
    let checkpoints = match solver.checkpoint.enabled() {
        true => Some(checkpointer(&config, solver, record, (&run, &id))?),
        false => None,
    };
    for line in plate_notes(cmd, &config).iter().chain(&plate.1) {
        eprintln!("{line}");
    }
    let mut out = Outputs::new(record.csv.as_deref(), cmd, cells)?;
    out.recording = Recording::start(cmd, &run, record, cells, id)?;
    out.progress = Some(Progress::new(record.progress_mode(), config.time.t_end));
    let interrupts = Interrupts::install()?;
    let start = SpanStart {
        plate: matches!(cmd, Command::Free(_)).then_some(plate.0),
        run,
        out,
        restored: None,
        checkpoints,
        summary: solver.summary.clone(),
        threads: solver.threads,
        stop_after: solver.checkpoint.stop_after_steps,
        invocation: super::provenance::invocation(cmd),
    };
    go(start, &interrupts)
}

/// The 3-D run of `config` with `span` and the solver options' grid, and its cells.
pub(super) fn span_of<'a>(
    config: &'a RunConfig,
    solver: &SolverArgs,
    span: Span,
) -> anyhow::Result<(Run3<'a>, usize)> {
    let (limit, _) = memory_limit(&solver.limits.max_memory)?;
    let mut run = Run3::new(config, span, solver.extent(), solver.growth(), limit);
    run.grid.shape = solver.section.body3().unwrap_or_default();
    if solver.section.shape == ShapeKind::Sphere && span != Span::Finite(1.0) {
        anyhow::bail!(
            "--shape sphere is one chord across: give --span 1, not {} (--shape ellipsoid for \
             other spans)",
            span_text(span)
        );
    }
    let cells = Grid3::new(&run.grid)?.cells();
    Ok((run, cells))
}

/// A span as the command line writes it.
fn span_text(span: Span) -> String {
    match span {
        Span::Finite(b) => format!("{b}"),
        Span::Periodic(b) => format!("periodic:{b}"),
    }
}

/// The checkpoints of a new 3-D run: the file (`--checkpoint`, else beside the CSV or the
/// summary, else `<case>.ckpt`) and what resuming needs (with the recording's path and id, when
/// the run records, for a continuation).
fn checkpointer(
    config: &RunConfig,
    solver: &SolverArgs,
    record: &RecordArgs,
    (run, id): (&Run3, &Option<String>),
) -> anyhow::Result<Checkpointer> {
    let every = solver.checkpoint.every()?;
    let no_recording = RecordArgs {
        no_save: true,
        ..record.clone()
    };
    let summary = solver.summary.as_deref();
    let kind = config.case.kind();
    let path =
        super::checkpointer::checkpoint_path(&solver.checkpoint, &no_recording, summary, kind);
    let abs = |o: Option<&Path>| o.map(std::path::absolute).transpose();
    let info = ResumeInfo {
        argv: std::env::args().collect(),
        config_json: serde_json::to_string_pretty(config)?,
        t_end: config.time.t_end,
        turns: config.time.turns,
        csv: abs(record.csv.as_deref())?,
        save: abs(id.as_ref().map(|_| save_path(record, run)).as_deref())?,
        summary: abs(summary)?,
        recording_id: id.clone(),
        every,
    };
    Ok(Checkpointer::new(path, every, 0.0, info, version()))
}

/// A 3-D run ready to step: new, or resumed from a checkpoint.
pub(super) struct SpanStart<'a> {
    /// The plate a free case flies (None: a static or forced case's flow).
    pub plate: Option<Plate6>,
    /// The run.
    pub run: Run3<'a>,
    /// The steps kept so far and the CSV.
    pub out: Outputs,
    /// The state to go on from (None: a new run).
    pub restored: Option<SpanRun>,
    /// The run's checkpoints, if asked for.
    pub checkpoints: Option<Checkpointer>,
    /// `--summary`.
    pub summary: Option<PathBuf>,
    /// `--threads`.
    pub threads: usize,
    /// The test hook `--stop-after-steps`.
    pub stop_after: Option<u64>,
    /// How the run was started, for the summary and the report.
    pub invocation: Invocation,
}

/// Steps a 3-D run to its end or a stop, writes the checkpoint at a stop (and, with a cadence,
/// at the end), then the outputs; the exit code says how it ended.
pub(super) fn go(mut s: SpanStart, interrupts: &Interrupts) -> anyhow::Result<Exit> {
    let cells = s.out.cells;
    eprintln!(
        "3-D grid: {cells} cells, about {:.2} GB",
        cells as f64 * BYTES_PER_CELL / 1e9
    );
    let pool = crate::pool::pool(s.threads)?;
    let clock = Instant::now();
    let mut ctl = Control {
        stop: interrupts.stop(),
        checkpoints: s.checkpoints.as_mut(),
        stop_after: s.stop_after,
    };
    let (run, out) = (&s.run, &mut s.out);
    let result = pool.install(|| {
        let mut mover = Mover::new(run, s.plate, s.restored.as_ref())?;
        let phases = PhaseClock::new();
        mover.set_phase_marker(phases.marker());
        let (steps_before, started) = (mover.steps(), Instant::now());
        let stopped = mover.run(run, out, &mut ctl)?;
        out.recirculation_length = mover.recirculation_length(run);
        let wall = started.elapsed().as_secs_f64();
        let steps = mover.steps() - steps_before;
        if let Some(line) = cost_line(phases.seconds(), wall, steps, cells) {
            eprintln!("{line}");
        }
        let periodic = ctl.checkpoints.as_ref().is_some_and(|c| c.periodic());
        let wanted = stopped || periodic;
        if wanted && ctl.checkpoints.is_some() {
            ctl.checkpoint(mover.save(), out)?;
        }
        Ok::<_, Stop>(stopped)
    });
    let wall = clock.elapsed().as_secs_f64();
    interrupts.set_phase(Phase::Finalising);
    let (status, saved) = match result {
        Ok(false) => (RunStatus::Completed, false),
        Ok(true) => (RunStatus::Interrupted, s.checkpoints.is_some()),
        Err(Stop::Flow(e)) => (RunStatus::Diverged(SimError::from(e)), false),
        Err(Stop::Output(e)) => (RunStatus::OutputFailed(e.to_string()), false),
        Err(Stop::Checkpoint(e)) => (RunStatus::OutputFailed(e), false),
    };
    if let Some(mut p) = s.out.progress.take() {
        p.finish(status.name());
    }
    let saved = saved.then(|| s.checkpoints.as_ref().map(|c| c.path().to_path_buf()));
    if let Some(c) = s.checkpoints.as_ref().filter(|c| c.written > 0) {
        eprintln!("{}", c.report_line());
    }
    let ended = Ended {
        status,
        wall_seconds: wall,
        checkpoint: saved.flatten(),
    };
    finish(&s.run, s.out, ended, s.summary.as_deref(), &s.invocation)
}

/// How a run ended: its status, the seconds it stepped, the checkpoint a stop wrote.
struct Ended {
    status: RunStatus,
    wall_seconds: f64,
    checkpoint: Option<PathBuf>,
}

/// The summary, the report, the CSV's trailer; the exit code.
fn finish(
    run: &Run3,
    out: Outputs,
    ended: Ended,
    summary_path: Option<&Path>,
    invocation: &Invocation,
) -> anyhow::Result<Exit> {
    let status = ended.status;
    let rec = RunRecord {
        status: status.clone(),
        samples: out.planar,
        t_release: run.config.case.release_time(),
        cells: out.cells,
        recirculation_length: out.recirculation_length,
    };
    let mut sum = summarize3(
        run.config,
        &rec,
        out.lateral,
        &out.attitude,
        ended.wall_seconds,
    );
    sum.three.span = Some(run.grid.span);
    sum.three.shape = Some(run.grid.shape);
    sum.three.cells_3d = out.cells;
    let text =
        super::provenance::with_version(&report3(run.config, &run.title(), &sum), invocation);
    let mut failures = Vec::new();
    let json = super::provenance::summary_json(invocation, &sum);
    if let Some(r) = out.recording {
        let outcome = RunOutcome {
            status: status.clone(),
            summary_json: json.clone(),
            report: text.clone(),
        };
        if !r.finish(outcome) {
            failures.push("the recording failed".to_string());
        }
    }
    if let Some(w) = out.csv {
        match w.finish(&status) {
            Ok((path, rows)) => eprintln!("csv: {} ({rows} rows)", path.display()),
            Err(e) => failures.push(e.to_string()),
        }
    }
    if let Some(line) = super::outcome::write_summary(summary_path, &json, &mut failures) {
        eprintln!("{line}");
    }
    print!("{text}");
    let saved = ended.checkpoint.as_deref();
    Ok(super::outcome::exit_code(
        &status,
        &sum.planar,
        &failures,
        saved,
    ))
}
