//! Running one case from the command line: validate everything (values, paths, resource
//! limits), start the solver and the logger threads, finalise every output, report, and exit
//! with a code that means one thing ([`Exit`]).
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use super::command::Command;
use super::config::{plate_notes, run_config};
use super::limits::check_limits;
use super::signals::{Interrupts, Phase};
use crate::exit::Exit;
use platefall_core::sim::{
    FieldSnapshot, Observer, RunRecord, RunStatus, Simulation, StepSample, ValidatedConfig,
};
use platefall_post::report::report;
use platefall_post::summary::{summarize, Summary};
use platefall_record::messages::{RunInfo, RunOutcome};
use platefall_record::output::write_atomically;
use platefall_record::{Logger, LoggerReport, RecordOptions};

/// A case, validated and ready to run.
struct Prepared {
    config: ValidatedConfig,
    opts: RecordOptions,
    summary_path: Option<PathBuf>,
    threads: usize,
}

/// Runs a case subcommand to its end; the exit code says how it ended. An `Err` means nothing
/// was run (bad input; or, for an [`OutputError`](platefall_record::output::OutputError), an
/// output that could not even be created).
pub fn run_case(cmd: &Command) -> anyhow::Result<Exit> {
    let p = prepare(cmd)?;
    let interrupts = Interrupts::install()?;
    let info = RunInfo::new(&p.config, command_line(), version());
    let mut sim = Simulation::new(p.config)?;
    let mut logger = platefall_record::spawn_logger(p.opts.clone(), info)?;
    let pool = crate::pool::pool(p.threads)?;

    let (mut rec, wall_seconds, lost) = solve(&mut sim, &mut logger, interrupts.stop(), &pool);
    if let Some(why) = lost {
        rec.status = RunStatus::OutputFailed(why);
    }
    interrupts.set_phase(Phase::Finalising);
    let summary = summarize(sim.config(), &rec, wall_seconds);
    let text = report(sim.config(), &summary);
    // (Cannot fail for a plain struct; never leave the logger unfinished over it.)
    let summary_json = serde_json::to_string_pretty(&summary)
        .unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"));
    let (log_report, mut failures) = finish_logger(logger, &rec.status, &summary_json, &text);
    if let Some(path) = &p.summary_path {
        if let Err(e) = write_atomically("--summary", path, summary_json.as_bytes()) {
            failures.push(e.to_string());
        }
    }
    print_report(&text, log_report.as_ref());
    let code = exit_code(&rec.status, &summary, &failures);
    if let Some(r) = log_report.filter(|_| rec.status != RunStatus::Interrupted) {
        // --serve keeps the server up for late viewers until Ctrl-C.
        interrupts.set_phase(Phase::Serving);
        r.serve_until_interrupted(interrupts.stop())?;
    }
    Ok(code)
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
    let others: Vec<(&'static str, &Path)> = summary_path
        .iter()
        .map(|p| ("--summary", p.as_path()))
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

/// The program and its version, for the recording.
fn version() -> String {
    format!("platefall {}", env!("CARGO_PKG_VERSION"))
}

/// Runs the solver inside the worker pool (this thread waits), timing it. The third value is the
/// output failure that stopped the run, if one did.
fn solve(
    sim: &mut Simulation,
    logger: &mut Logger,
    stop: &AtomicBool,
    pool: &rayon::ThreadPool,
) -> (RunRecord, f64, Option<String>) {
    pool.install(|| {
        let mut fwd = Forward {
            logger,
            stop,
            lost: None,
        };
        let start = Instant::now();
        let rec = sim.run(&mut fwd);
        (rec, start.elapsed().as_secs_f64(), fwd.lost)
    })
}

/// The exit code of a finished run, with its one-line messages on stderr.
fn exit_code(status: &RunStatus, summary: &Summary, failures: &[String]) -> Exit {
    if !failures.is_empty() {
        let stopped = match status {
            RunStatus::OutputFailed(_) => {
                format!("; the run stopped at t = {:.3}", summary.t_reached)
            }
            _ => String::new(),
        };
        eprintln!(
            "error: could not write {}{stopped}; nothing incomplete was left at a final name",
            failures.join("; ")
        );
    }
    match status {
        RunStatus::Interrupted => eprintln!(
            "interrupted: the outputs hold the run up to t = {:.3} and say so",
            summary.t_reached
        ),
        RunStatus::OutputFailed(msg) if failures.is_empty() => eprintln!("error: {msg}"),
        RunStatus::Diverged(e) if failures.is_empty() => {
            eprintln!("error: {e}; try a smaller --cfl or a finer --resolution")
        }
        _ => {}
    }
    match status {
        RunStatus::Interrupted | RunStatus::OutputFailed(_) => Exit::of_status(status),
        _ if !failures.is_empty() => Exit::OutputFailed,
        _ => Exit::of_status(status),
    }
}

/// Forwards the solver's output to the logger thread.
struct Forward<'a> {
    logger: &'a mut Logger,
    stop: &'a AtomicBool,
    lost: Option<String>,
}

impl Observer for Forward<'_> {
    fn step(&mut self, sample: &StepSample) {
        if let Err(e) = self.logger.step(*sample) {
            // An output failed, or the logger thread is gone: stop the run rather than compute
            // what cannot be kept.
            self.lost.get_or_insert(format!("{e:#}"));
            self.stop.store(true, Ordering::SeqCst);
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
}

/// The command line as typed, quoted where needed.
fn command_line() -> String {
    std::env::args()
        .map(|a| {
            if a.chars()
                .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+".contains(c))
            {
                a
            } else {
                format!("'{}'", a.replace('\'', "'\\''"))
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}
