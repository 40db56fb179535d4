//! Running one case from the command line: validate everything, start the solver and the logger
//! threads, report, and exit with a code that means one thing.
//!
//! Exit codes: 0 completed; 2 bad input (nothing is run or written); 3 the solution diverged
//! (the recording and summary up to that point are still finalised); 130 interrupted (Ctrl-C).
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;

use anyhow::Context;

use super::args::run_config;
use super::Command;
use crate::post::report::report;
use crate::post::summary::{summarize, Summary};
use crate::record::files::check_writable;
use crate::record::messages::{RunInfo, RunOutcome};
use crate::record::{self, Logger, RecordOptions};
use crate::sim::{
    FieldSnapshot, Observer, RunConfig, RunRecord, RunStatus, Simulation, StepSample,
};

/// A case, validated and ready to run.
struct Prepared {
    config: RunConfig,
    opts: RecordOptions,
    summary_path: Option<PathBuf>,
}

/// Runs a case subcommand to its end; the exit code says how it ended.
pub fn run_case(cmd: &Command) -> anyhow::Result<ExitCode> {
    let p = prepare(cmd)?;
    let mut sim = Simulation::new(p.config.clone())?;
    let stop = Arc::new(AtomicBool::new(false));
    install_ctrlc(stop.clone())?;
    let mut logger = record::spawn_logger(p.opts.clone(), run_info(&p.config, &sim))?;

    let (rec, wall_seconds, lost) = solve(&mut sim, &mut logger, &stop);

    let summary = summarize(&p.config, &rec, wall_seconds);
    let text = report(&p.config, &summary);
    let summary_json = serde_json::to_string_pretty(&summary)?;
    if let Some(path) = &p.summary_path {
        write_atomically(path, summary_json.as_bytes())
            .with_context(|| format!("writing --summary {}", path.display()))?;
    }
    let outcome = RunOutcome {
        status: rec.status.clone(),
        summary_json,
        report: text.clone(),
    };
    let log_report = logger.finish(outcome)?;
    eprintln!();
    print!("{text}");
    for line in log_report.lines() {
        eprintln!("{line}");
    }
    std::io::stdout().flush().ok();
    if let Some(e) = lost {
        eprintln!("error: the logger thread stopped early: {e:#}");
    }
    let code = exit_code(&rec.status, &summary);
    if rec.status != RunStatus::Interrupted {
        // --serve keeps the server up for late viewers until Ctrl-C.
        log_report.serve_until_interrupted(&stop)?;
    }
    Ok(code)
}

/// Validates everything before anything runs or is written.
fn prepare(cmd: &Command) -> anyhow::Result<Prepared> {
    let config = run_config(cmd)?;
    let Some((solver_args, record_args)) = cmd.case_args() else {
        anyhow::bail!("not a case subcommand");
    };
    let summary_path = solver_args.summary.clone();
    if let Some(path) = &summary_path {
        check_writable(path, false)
            .map_err(|reason| anyhow::anyhow!("--summary {}: {reason}", path.display()))?;
    }
    // A run that stops after a number of turns has no known end time: show no ETA rather than a
    // wrong one.
    let progress_end = if config.time.turns.is_some() {
        f64::NAN
    } else {
        config.time.t_end
    };
    let mut opts = record_args.resolve(config.case.name(), progress_end)?;
    opts.view.plot_ranges = Some(crate::post::PlotRanges::for_config(&config));
    if let Some(b) = &config.body {
        if let Some(advice) = crate::body::coupling_advice(&b.props) {
            eprintln!("warning: {advice}");
        }
    }
    Ok(Prepared {
        config,
        opts,
        summary_path,
    })
}

/// The first Ctrl-C asks the run to stop (it finalises what it has); a second one, while the
/// run is still going, quits at once.
fn install_ctrlc(stop: Arc<AtomicBool>) -> anyhow::Result<()> {
    let presses = AtomicBool::new(false);
    ctrlc::set_handler(move || {
        if presses.swap(true, Ordering::SeqCst) && !stop.load(Ordering::SeqCst) {
            std::process::exit(130);
        }
        stop.store(true, Ordering::SeqCst);
    })
    .context("installing the Ctrl-C handler")
}

/// What the recording needs to know about the run before it starts.
fn run_info(config: &RunConfig, sim: &Simulation) -> RunInfo {
    RunInfo {
        case: config.case.name().to_string(),
        title: config.title(),
        config_json: serde_json::to_string_pretty(config).unwrap_or_default(),
        command_line: command_line(),
        version: format!("platefall {}", env!("CARGO_PKG_VERSION")),
        thickness: sim.flow.grid.thickness,
        grid: Arc::new(sim.flow.grid.geometry()),
    }
}

/// Runs the solver on its own thread (this one waits), timing it.
fn solve(
    sim: &mut Simulation,
    logger: &mut Logger,
    stop: &AtomicBool,
) -> (RunRecord, f64, Option<anyhow::Error>) {
    std::thread::scope(|scope| {
        let handle = scope.spawn(|| {
            let mut fwd = Forward {
                logger,
                stop,
                lost: None,
            };
            let start = Instant::now();
            let rec = sim.run(&mut fwd);
            (rec, start.elapsed().as_secs_f64(), fwd.lost)
        });
        handle.join().expect("solver thread panicked")
    })
}

/// The exit code of a finished run, with its one-line message on stderr.
fn exit_code(status: &RunStatus, summary: &Summary) -> ExitCode {
    match status {
        RunStatus::Completed => ExitCode::SUCCESS,
        RunStatus::Diverged(msg) => {
            eprintln!("error: {msg}; try a smaller --cfl or a finer --resolution");
            ExitCode::from(3)
        }
        RunStatus::Interrupted => {
            eprintln!(
                "interrupted: the recording and summary hold the run up to t = {:.3}",
                summary.t_end
            );
            ExitCode::from(130)
        }
    }
}

/// Forwards the solver's output to the logger thread.
struct Forward<'a> {
    logger: &'a mut Logger,
    stop: &'a AtomicBool,
    lost: Option<anyhow::Error>,
}

impl Observer for Forward<'_> {
    fn step(&mut self, sample: &StepSample) {
        if let Err(e) = self.logger.step(*sample) {
            // The logger thread is gone: stop the run rather than compute what cannot be kept.
            self.lost.get_or_insert(e);
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

/// Writes via a temporary file and a rename, so a reader never sees half a file.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = path.with_extension("tmp-platefall");
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(&tmp, path)
}
