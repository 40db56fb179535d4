//! The entry points of `platefall sweep`: a local sweep, `--dry-run`, `--slurm`, `collect` and
//! `run-case`.
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::Ordering;
use std::time::Duration;

use super::args::{SweepAction, SweepArgs};
use super::child::{finish, interrupt, is_done, launch};
use super::layout::{difference, lock, prepare, read_manifest, Layout, Manifest};
use super::plan::{self, CaseSpec, Plan};
use super::progress::Progress;
use super::results::{gather, not_completed, tally, write_tables};
use super::runner::{interrupt_counter, run_pool};
use super::{Failure, EXIT_INCOMPLETE, EXIT_INTERRUPTED};

/// Runs `platefall sweep ...` and returns the process exit code.
pub fn main(args: &SweepArgs) -> ExitCode {
    match dispatch(args) {
        Ok(code) => ExitCode::from(code),
        Err(f) => {
            eprintln!("error: {}", f.message);
            ExitCode::from(f.code)
        }
    }
}

fn dispatch(args: &SweepArgs) -> Result<u8, Failure> {
    match &args.action {
        Some(SweepAction::Collect { dir }) => collect(dir),
        Some(SweepAction::RunCase { dir, index }) => run_case(dir, *index),
        None => {
            let path = args
                .plan
                .as_deref()
                .ok_or_else(|| Failure::input("give a plan file: platefall sweep PLAN.toml"))?;
            let plan = plan::load(path).map_err(Failure::input)?;
            let cases = plan
                .checked_cases()
                .map_err(|e| Failure::input(format!("plan {}: {e}", path.display())))?;
            let layout = Layout::new(&output_dir(args, &plan, path)?);
            if args.dry_run {
                dry_run(&layout, &plan, &cases);
                Ok(0)
            } else if args.slurm {
                super::slurm::submit_script(&layout, &plan, &cases, &args.resources)
            } else {
                local(args, &layout, &plan, &cases)
            }
        }
    }
}

/// `--output`, else the plan's `output`.
fn output_dir(args: &SweepArgs, plan: &Plan, path: &Path) -> Result<PathBuf, Failure> {
    args.output
        .clone()
        .or_else(|| plan.output.clone())
        .ok_or_else(|| {
            Failure::input(format!(
                "plan {}: no output directory: set output = \"DIR\" in the plan or give --output DIR",
                path.display()
            ))
        })
}

/// This executable, for the cases' child processes and the Slurm script.
pub fn this_exe() -> Result<PathBuf, Failure> {
    std::env::current_exe()
        .map_err(|e| Failure::output(format!("cannot find this executable's path: {e}")))
}

/// `--dry-run`: the cases, which are done, and the command each would run.
fn dry_run(layout: &Layout, plan: &Plan, cases: &[CaseSpec]) {
    let done = cases.iter().filter(|c| is_done(layout, &c.id)).count();
    println!(
        "sweep {}: {} cases of `{}` in {} ({done} done, {} to run)",
        plan.name,
        cases.len(),
        plan.case,
        layout.dir.display(),
        cases.len() - done
    );
    for c in cases {
        let mark = if is_done(layout, &c.id) {
            "done"
        } else {
            "todo"
        };
        println!("{mark}  {}  platefall {}", c.id, c.args.join(" "));
    }
}

/// Makes (or checks) the directory and takes its lock.
fn open_dir(
    layout: &Layout,
    plan: &Plan,
    cases: &[CaseSpec],
) -> Result<super::layout::DirLock, Failure> {
    std::fs::create_dir_all(&layout.dir)
        .map_err(|e| Failure::output(format!("cannot create {}: {e}", layout.dir.display())))?;
    let guard = lock(layout)?;
    prepare(layout, plan, cases)?;
    Ok(guard)
}

/// A local sweep: the cases not yet done, `--jobs` at once, then the merged results.
fn local(
    args: &SweepArgs,
    layout: &Layout,
    plan: &Plan,
    cases: &[CaseSpec],
) -> Result<u8, Failure> {
    run_local(layout, plan, cases, args.jobs, args.progress)
}

/// Runs the cases of `plan` not yet done in `layout`, `jobs` at once (default: one per core), and
/// merges the results; the sweep's exit code. `platefall converge` runs its levels this way.
pub fn run_local(
    layout: &Layout,
    plan: &Plan,
    cases: &[CaseSpec],
    jobs: Option<usize>,
    progress_mode: super::args::ProgressMode,
) -> Result<u8, Failure> {
    let jobs = match jobs {
        Some(0) => {
            return Err(Failure::input(
                "--jobs 0 is out of range: accepted 1 or more",
            ))
        }
        Some(n) => n,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let exe = this_exe()?;
    let _lock = open_dir(layout, plan, cases)?;
    let todo: Vec<CaseSpec> = cases
        .iter()
        .filter(|c| !is_done(layout, &c.id))
        .cloned()
        .collect();
    let done = cases.len() - todo.len();
    eprintln!(
        "sweep {}: {} cases of `{}` in {} ({done} already done); running {} with {} at once",
        plan.name,
        cases.len(),
        plan.case,
        layout.dir.display(),
        todo.len(),
        jobs.min(todo.len().max(1))
    );
    let presses = interrupt_counter()?;
    let mut progress = Progress::new(progress_mode, cases.len(), done);
    let recording = plan.outputs.recording;
    let interrupted = run_pool(
        &exe,
        layout,
        &todo,
        recording,
        jobs,
        &mut progress,
        &presses,
    );
    progress.finish();
    let code = merge(layout, plan, cases)?;
    Ok(if interrupted { EXIT_INTERRUPTED } else { code })
}

/// Writes the merged results and the phase diagram, prints the tally and what did not
/// complete; 0 if every case completed, else 3.
pub fn merge(layout: &Layout, plan: &Plan, cases: &[CaseSpec]) -> Result<u8, Failure> {
    let rows = gather(layout, cases);
    write_tables(layout, &rows)?;
    let data = super::diagram::DiagramData::new(plan, &rows);
    super::plot::write_figures(layout, &data)?;
    #[cfg(feature = "viewer")]
    super::recording::write_recording(layout, &data)?;
    println!("{}", tally(&rows));
    let missing = not_completed(&rows);
    if !missing.is_empty() {
        println!("not completed:");
        for line in &missing {
            println!("{line}");
        }
    }
    println!(
        "results: {}/results.csv, results.json, phase.png, phase.svg{}",
        layout.dir.display(),
        if cfg!(feature = "viewer") {
            ", phase.rrd"
        } else {
            ""
        }
    );
    Ok(if missing.is_empty() {
        0
    } else {
        EXIT_INCOMPLETE
    })
}

/// The plan and cases of a prepared directory (its own `plan.toml`, checked against `sweep.json`).
pub fn open_prepared(dir: &Path) -> Result<(Layout, Plan, Manifest), Failure> {
    let layout = Layout::new(dir);
    let manifest = read_manifest(&layout)?.ok_or_else(|| {
        Failure::input(format!(
            "{} is not a sweep directory (no sweep.json): give the directory a sweep wrote",
            layout.dir.display()
        ))
    })?;
    let mut plan = plan::load(&layout.plan()).map_err(Failure::input)?;
    if let Some(why) = difference(&manifest, &Manifest::of(&plan, &plan.cases())) {
        return Err(Failure::input(format!(
            "{}: plan.toml does not match sweep.json ({why}); restore it or rerun the sweep",
            layout.dir.display()
        )));
    }
    if !manifest.name.is_empty() {
        plan.name = manifest.name.clone();
    }
    Ok((layout, plan, manifest))
}

/// `collect DIR`: merge whatever has finished.
fn collect(dir: &Path) -> Result<u8, Failure> {
    let (layout, plan, manifest) = open_prepared(dir)?;
    merge(&layout, &plan, &manifest.cases)
}

/// `run-case DIR INDEX`: one case of a prepared directory, as a child process; exits with the
/// case's exit code.
fn run_case(dir: &Path, index: usize) -> Result<u8, Failure> {
    let (layout, _plan, manifest) = open_prepared(dir)?;
    let case = manifest.cases.get(index).ok_or_else(|| {
        Failure::input(format!(
            "case index {index} is out of range: accepted 0..={}",
            manifest.cases.len().saturating_sub(1)
        ))
    })?;
    if is_done(&layout, &case.id) {
        println!("{}: already done", case.id);
        return Ok(0);
    }
    let presses = interrupt_counter()?;
    let exe = this_exe()?;
    let mut running = launch(&exe, &layout, case, manifest.recording)
        .map_err(|e| Failure::output(format!("{}: could not start: {e}", case.id)))?;
    let mut forwarded = 0;
    let exit = loop {
        match running.child.try_wait() {
            Ok(Some(exit)) => break exit,
            Ok(None) => {}
            Err(e) => {
                return Err(Failure::output(format!(
                    "{}: lost the process: {e}",
                    case.id
                )))
            }
        }
        let p = presses.load(Ordering::SeqCst);
        if p > forwarded {
            interrupt(&mut running, p > 1);
            forwarded = p;
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let status = finish(&layout, running, exit);
    let state = super::results::outcome(&layout, &case.id, Some(&status));
    println!("{}: {state} {}", case.id, status.message);
    Ok(status.exit_code.map_or(1, |c| c.clamp(0, 255) as u8))
}
