//! platefall: parse the command line, build the configuration, run the solver on its own thread
//! with a logger thread beside it, report, and exit with a meaningful code.
//!
//! Exit codes: 0 completed; 2 bad input (nothing is run or written); 3 the solution diverged
//! (the recording and summary up to that point are still finalised); 130 interrupted (Ctrl-C).
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use anyhow::Context;
use clap::Parser;

use platefall::cli::{run_config, BenchArgs, Cli, Command, SolverArgs};
use platefall::config::RunConfig;
use platefall::record::messages::{FieldSnapshot, RunInfo, RunOutcome, RunStatus, StepSample};
use platefall::record::{self, options::RecordArgs, Logger};
use platefall::sim::{Observer, Simulation};
use platefall::summary::{report, summarize};

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Bench(args) => bench(args).map(|_| ExitCode::SUCCESS),
        Command::Sweep(args) => return platefall::sweep::main(args),
        cmd => run_case(cmd),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

/// The options every case subcommand shares: the solver's and the recording's.
fn case_args(cmd: &Command) -> (&SolverArgs, &RecordArgs) {
    match cmd {
        Command::Static(a) => (&a.solver, &a.record),
        Command::Forced(a) => (&a.solver, &a.record),
        Command::Pinned(a) => (&a.solver, &a.record),
        Command::Free(a) => (&a.solver, &a.record),
        Command::Bench(_) | Command::Sweep(_) => unreachable!("not a case"),
    }
}

/// Checks that a file can be created at `path` without leaving anything behind.
fn check_writable(flag: &str, path: &Path) -> anyhow::Result<()> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if !dir.is_dir() {
        anyhow::bail!(
            "{flag} {}: directory {} does not exist",
            path.display(),
            dir.display()
        );
    }
    let probe = dir.join(format!(".platefall-probe-{}", std::process::id()));
    std::fs::File::create(&probe).map_err(|e| {
        anyhow::anyhow!(
            "{flag} {}: cannot write in {} ({e})",
            path.display(),
            dir.display()
        )
    })?;
    let _ = std::fs::remove_file(probe);
    Ok(())
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

fn run_case(cmd: &Command) -> anyhow::Result<ExitCode> {
    // Everything is validated before anything runs or is written.
    let config: RunConfig = run_config(cmd)?;
    let case = config.case.name();
    let (solver_args, record_args) = case_args(cmd);
    let summary_path = solver_args.summary.as_deref();
    if let Some(p) = summary_path {
        check_writable("--summary", p)?;
    }
    // A run that stops after a number of turns has no known end time: show no ETA rather than a
    // wrong one.
    let progress_end = if config.turns.is_some() {
        f64::NAN
    } else {
        config.t_end
    };
    let opts = record_args.resolve(case, progress_end)?;
    if let Some(b) = &config.body {
        if let Some(advice) = platefall::body::coupling_advice(&b.props) {
            eprintln!("warning: {advice}");
        }
    }
    let mut sim = Simulation::new(config.clone()).map_err(|e| anyhow::anyhow!(e))?;

    let stop = Arc::new(AtomicBool::new(false));
    {
        let stop = stop.clone();
        let presses = AtomicBool::new(false);
        ctrlc::set_handler(move || {
            if presses.swap(true, Ordering::SeqCst) && !stop.load(Ordering::SeqCst) {
                std::process::exit(130);
            }
            stop.store(true, Ordering::SeqCst);
        })
        .context("installing the Ctrl-C handler")?;
    }

    let info = RunInfo {
        case: case.to_string(),
        title: config.title(),
        config_json: serde_json::to_string_pretty(&config)?,
        command_line: command_line(),
        version: format!("platefall {}", env!("CARGO_PKG_VERSION")),
        thickness: sim.flow.grid.thickness,
        grid: std::sync::Arc::new(sim.flow.grid.geometry()),
    };
    let mut logger = record::spawn_logger(opts, info)?;

    // The solver runs on its own thread; this thread waits for it.
    let (rec, lost) = std::thread::scope(|scope| {
        let handle = scope.spawn(|| {
            let mut fwd = Forward {
                logger: &mut logger,
                stop: &stop,
                lost: None,
            };
            let rec = sim.run(&mut fwd);
            (rec, fwd.lost)
        });
        handle.join().expect("solver thread panicked")
    });

    let summary = summarize(&config, &rec);
    let text = report(&config, &summary);
    let summary_json = serde_json::to_string_pretty(&summary)?;
    if let Some(p) = summary_path {
        write_atomically(p, summary_json.as_bytes())
            .with_context(|| format!("writing --summary {}", p.display()))?;
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
    let code = match &rec.status {
        RunStatus::Completed => ExitCode::SUCCESS,
        RunStatus::Diverged(msg) => {
            eprintln!("error: {msg}");
            ExitCode::from(3)
        }
        RunStatus::Interrupted => {
            eprintln!(
                "interrupted: the recording and summary hold the run up to t = {:.3}",
                summary.t_end
            );
            ExitCode::from(130)
        }
    };
    if rec.status != RunStatus::Interrupted {
        // --serve keeps the server up for late viewers until Ctrl-C.
        log_report.serve_until_interrupted(&stop)?;
    }
    Ok(code)
}

/// Writes via a temporary file and a rename, so a reader never sees half a file.
fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = path.with_extension("tmp-platefall");
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(&tmp, path)
}

fn bench(args: &BenchArgs) -> anyhow::Result<()> {
    if args.steps == 0 {
        anyhow::bail!("--steps 0 is out of range: accepted 1..");
    }
    if let Some(p) = &args.json {
        check_writable("--json", p)?;
    }
    let mut rows = Vec::new();
    eprintln!("timing {} steps per grid, single-threaded, prescribed motion (α = 0.4 translation + θ̇ = 1)", args.steps);
    for &n in &args.resolutions {
        let row = platefall::bench::bench_one(n, args.steps).map_err(|e| anyhow::anyhow!(e))?;
        rows.push(row);
        eprint!(
            "{}",
            platefall::bench::table(&rows)
                .lines()
                .last()
                .map(|l| format!("{l}\n"))
                .unwrap_or_default()
        );
    }
    print!("{}", platefall::bench::table(&rows));
    if let Some(p) = &args.json {
        write_atomically(p, serde_json::to_string_pretty(&rows)?.as_bytes())?;
    }
    Ok(())
}
