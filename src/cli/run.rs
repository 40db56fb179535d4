//! Running one case from the command line: validate everything (values, paths, resource
//! limits), start the solver and the logger threads, finalise every output, report, and exit
//! with a code that means one thing ([`Exit`]).
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use super::checkpointer::Checkpointer;
use super::command::Command;
use super::config::{plate_notes, run_config};
use super::limits::check_limits;
use super::signals::{Interrupts, Phase};
use crate::exit::Exit;
use crate::version::program_version as version;
use platefall_core::sim::{
    FieldSnapshot, History, Observer, RunRecord, RunStatus, Simulation, StepSample, ValidatedConfig,
};
use platefall_post::report::report;
use platefall_post::summary::summarize;
use platefall_record::checkpoint::ResumeInfo;
use platefall_record::messages::{RunInfo, RunOutcome};
use platefall_record::{Logger, LoggerReport, RecordOptions};

/// A case, validated and ready to run.
struct Prepared {
    config: ValidatedConfig,
    opts: RecordOptions,
    summary_path: Option<PathBuf>,
    threads: usize,
    checkpoint: Option<PathBuf>,
}

/// A run ready to go: the simulation (new, or restored from a checkpoint) and its outputs.
pub(super) struct Started {
    /// The run.
    pub sim: Simulation,
    /// The steps' history so far (empty for a new run).
    pub history: History,
    /// The recording and CSV.
    pub opts: RecordOptions,
    /// `--summary`.
    pub summary_path: Option<PathBuf>,
    /// `--threads`.
    pub threads: usize,
    /// The run's checkpoints, if asked for.
    pub checkpoints: Option<Checkpointer>,
    /// The test hook `--stop-after-steps`.
    pub stop_after: Option<u64>,
}

/// Runs a case subcommand to its end; the exit code says how it ended. An `Err` means nothing
/// was run (bad input; or, for an [`OutputError`](platefall_record::output::OutputError), an
/// output that could not even be created).
pub fn run_case(cmd: &Command) -> anyhow::Result<Exit> {
    if let Some(span) = cmd.case_args().and_then(|(solver, _)| solver.span) {
        return super::span_run::run_span(cmd, span);
    }
    if let Some((solver, _)) = cmd.case_args().filter(|(s, _)| s.section.needs_span()) {
        anyhow::bail!(
            "--shape {} is a body in three dimensions: give --span (e.g. --span 1)",
            solver.section.shape.name()
        );
    }
    let mut p = prepare(cmd)?;
    let Some((solver, _)) = cmd.case_args() else {
        anyhow::bail!("not a case subcommand");
    };
    let interrupts = Interrupts::install()?;
    let checkpoints = match p.checkpoint.take() {
        Some(path) => {
            let id = super::continued::new_recording_id();
            p.opts.recording_id = Some(id.clone());
            let info = resume_info(&p, solver.checkpoint.every()?, id)?;
            Some(Checkpointer::new(path, info.every, 0.0, info, version()))
        }
        None => None,
    };
    let info = RunInfo::new(&p.config, command_line(), version())
        .with_invocation(super::provenance::invocation(cmd));
    let started = Started {
        sim: Simulation::new(p.config)?,
        history: History::default(),
        opts: p.opts,
        summary_path: p.summary_path,
        threads: p.threads,
        checkpoints,
        stop_after: solver.checkpoint.stop_after_steps,
    };
    execute(started, info, &interrupts)
}

/// Runs a started run to its end: the solver, the logger, the checkpoints at a stop or the
/// end, the summary, the report; the exit code says how it ended.
pub(super) fn execute(
    mut r: Started,
    info: RunInfo,
    interrupts: &Interrupts,
) -> anyhow::Result<Exit> {
    let invocation = info.invocation.clone();
    let mut logger = platefall_record::spawn_logger(r.opts.clone(), info)?;
    logger.resume_fields_at(r.sim.flow().t(), r.history.total_steps());
    let pool = crate::pool::pool(r.threads)?;
    let ctx = Solve {
        stop: interrupts.stop(),
        checkpoints: r.checkpoints.as_mut(),
        stop_after: r.stop_after,
    };
    let (mut rec, wall_seconds, lost) = solve(&mut r.sim, r.history, &mut logger, ctx, &pool);
    if let Some(why) = lost {
        rec.status = RunStatus::OutputFailed(why);
    }
    interrupts.set_phase(Phase::Finalising);
    let (saved, ckpt_failure) = last_checkpoint(&r.sim, &rec, r.checkpoints.as_mut(), &logger);
    let saved = saved
        .then(|| r.checkpoints.as_ref().map(|c| c.path().to_path_buf()))
        .flatten();
    let summary = summarize(r.sim.config(), &rec, wall_seconds);
    let text = super::provenance::with_version(&report(r.sim.config(), &summary), &invocation);
    let summary_json = super::provenance::summary_json(&invocation, &summary);
    let (log_report, mut failures) = finish_logger(logger, &rec.status, &summary_json, &text);
    failures.extend(ckpt_failure);
    let summary_line =
        super::outcome::write_summary(r.summary_path.as_deref(), &summary_json, &mut failures);
    print_report(&text, log_report.as_ref());
    if let Some(line) = summary_line {
        eprintln!("{line}");
    }
    if let Some(c) = r.checkpoints.as_ref().filter(|c| c.written > 0) {
        eprintln!("{}", c.report_line());
    }
    let code = super::outcome::exit_code(&rec.status, &summary, &failures, saved.as_deref());
    if let Some(r) = log_report.filter(|_| rec.status != RunStatus::Interrupted) {
        // --serve keeps the server up for late viewers until Ctrl-C.
        interrupts.set_phase(Phase::Serving);
        r.serve_until_interrupted(interrupts.stop())?;
    }
    Ok(code)
}

/// The checkpoint at a stop (or, with a cadence, at the end): whether one was written at a
/// stop, and the failure to write it.
fn last_checkpoint(
    sim: &Simulation,
    rec: &RunRecord,
    checkpoints: Option<&mut Checkpointer>,
    logger: &Logger,
) -> (bool, Option<String>) {
    let Some(c) = checkpoints else {
        return (false, None);
    };
    let wanted = match rec.status {
        RunStatus::Interrupted => true,
        RunStatus::Completed => c.periodic(),
        _ => false,
    };
    if !wanted {
        return (false, None);
    }
    match c.write(sim, &rec.samples, logger) {
        Ok(()) => (rec.status == RunStatus::Interrupted, None),
        Err(e) => (false, Some(format!("{e:#}"))),
    }
}

/// What the checkpoint of a new run records to resume it.
fn resume_info(p: &Prepared, every: Option<f64>, id: String) -> anyhow::Result<ResumeInfo> {
    let abs = |o: &Option<PathBuf>| -> std::io::Result<Option<PathBuf>> {
        o.as_deref().map(std::path::absolute).transpose()
    };
    Ok(ResumeInfo {
        argv: std::env::args().collect(),
        config_json: serde_json::to_string_pretty(&p.config)?,
        t_end: p.config.time.t_end,
        turns: p.config.time.turns,
        csv: abs(&p.opts.csv)?,
        save: abs(&p.opts.save)?,
        summary: abs(&p.summary_path)?,
        recording_id: Some(id),
        every,
    })
}

/// Validates everything before anything runs or is written: values, resource limits, paths.
fn prepare(cmd: &Command) -> anyhow::Result<Prepared> {
    let config = run_config(cmd)?;
    let Some((solver_args, record_args)) = cmd.case_args() else {
        anyhow::bail!("not a case subcommand");
    };
    let queued = record_args
        .uses_rerun()
        .then_some(RecordOptions::default().max_fields_in_flight);
    if let Some(warning) = check_limits(&config, &solver_args.limits, queued)? {
        eprintln!("warning: {warning}");
    }
    let summary_path = solver_args.summary.clone();
    solver_args.checkpoint.every()?;
    let checkpoint = solver_args.checkpoint.enabled().then(|| {
        let summary = summary_path.as_deref();
        super::checkpointer::checkpoint_path(
            &solver_args.checkpoint,
            record_args,
            summary,
            config.case.kind(),
        )
    });
    let others: Vec<(&'static str, &Path)> = summary_path
        .iter()
        .map(|p| ("--summary", p.as_path()))
        .chain(checkpoint.iter().map(|p| ("--checkpoint", p.as_path())))
        .collect();
    let opts = record_args.resolve(config.case.kind(), &others)?;
    for line in plate_notes(cmd, &config) {
        eprintln!("{line}");
    }
    Ok(Prepared {
        config,
        opts,
        summary_path,
        threads: solver_args.threads,
        checkpoint,
    })
}

/// Sends the outcome and waits for the logger to finalise its outputs; the report (None if the
/// logger thread failed) and the outputs that could not be written.
fn finish_logger(
    logger: Logger,
    status: &RunStatus,
    summary_json: &str,
    text: &str,
) -> (Option<LoggerReport>, Vec<String>) {
    let outcome = RunOutcome {
        status: status.clone(),
        summary_json: summary_json.to_string(),
        report: text.to_string(),
    };
    match logger.finish(outcome) {
        Ok(r) => {
            let failures = r.errors.clone();
            (Some(r), failures)
        }
        Err(e) => (None, vec![format!("the recording and CSV: {e:#}")]),
    }
}

/// The report on stdout, the outputs written on stderr.
fn print_report(text: &str, log_report: Option<&LoggerReport>) {
    eprintln!();
    print!("{text}");
    for line in log_report.map(LoggerReport::lines).unwrap_or_default() {
        eprintln!("{line}");
    }
    std::io::stdout().flush().ok();
}

/// What the solver loop polls besides the logger: the stop flag, the checkpoints, the test hook.
struct Solve<'a> {
    stop: &'a AtomicBool,
    checkpoints: Option<&'a mut Checkpointer>,
    stop_after: Option<u64>,
}

/// Runs the solver inside the worker pool (this thread waits), timing it, going on with the
/// steps' `history`. The third value is the output failure that stopped the run, if one did.
fn solve(
    sim: &mut Simulation,
    history: History,
    logger: &mut Logger,
    ctx: Solve,
    pool: &rayon::ThreadPool,
) -> (RunRecord, f64, Option<String>) {
    pool.install(|| {
        let mut fwd = Forward {
            logger,
            stop: ctx.stop,
            lost: None,
            checkpoints: ctx.checkpoints,
            stop_after: ctx.stop_after,
        };
        let start = Instant::now();
        let rec = sim.run_from(&mut fwd, history);
        (rec, start.elapsed().as_secs_f64(), fwd.lost)
    })
}

/// Forwards the solver's output to the logger thread, and writes the checkpoints.
struct Forward<'a> {
    logger: &'a mut Logger,
    stop: &'a AtomicBool,
    lost: Option<String>,
    checkpoints: Option<&'a mut Checkpointer>,
    stop_after: Option<u64>,
}

impl Forward<'_> {
    /// An output failed: stop the run rather than compute what cannot be kept.
    fn lose(&mut self, why: String) {
        self.lost.get_or_insert(why);
        self.stop.store(true, Ordering::SeqCst);
    }
}

impl Observer for Forward<'_> {
    fn step(&mut self, sample: &StepSample) {
        if let Err(e) = self.logger.step(*sample) {
            // An output failed, or the logger thread is gone.
            self.lose(format!("{e:#}"));
        }
    }
    fn wants_field(&mut self, t: f64) -> bool {
        self.logger.field_due(t)
    }
    fn field(&mut self, snapshot: FieldSnapshot) {
        self.logger.offer_field(snapshot);
    }
    fn should_stop(&self) -> bool {
        self.stop.load(Ordering::SeqCst)
    }
    fn after_step(&mut self, sim: &Simulation, history: &History) {
        if let Some(c) = self.checkpoints.as_deref_mut() {
            if let Err(e) = c.after_step(sim, history, self.logger) {
                self.lose(format!("{e:#}"));
            }
        }
        if self.stop_after.is_some_and(|n| sim.flow().steps() >= n) {
            self.stop.store(true, Ordering::SeqCst);
        }
    }
}

/// The command line as typed, quoted where needed.
pub(super) fn command_line() -> String {
    super::shell::shell_line(std::env::args())
}
