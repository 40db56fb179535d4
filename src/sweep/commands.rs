//! The entry points of `platefall sweep`: a local sweep, `--dry-run`, `--slurm`, `collect` and
//! `run-case`.
use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;
use std::time::Duration;

use super::child::{finish, interrupt, is_done, launch, this_exe};
use super::diagram::diagram_data;
use super::failure::Failure;
use super::layout::{difference, lock, prepare, read_manifest, Layout, Manifest};
use super::options::CaseCommands;
use super::plan::{self, CaseSpec, Plan};
use super::progress::{Progress, ProgressMode};
use super::request::SweepRequest;
use super::results::{gather, not_completed, outcome, tally, write_tables};
use super::runner::{interrupt_counter, run_pool};
use super::slurm::{quote, submit_script};
use crate::exit::Exit;
use platefall_post::phase::CaseState;

/// Runs `platefall sweep ...`; the exit code says how it ended (errors are printed here).
pub(crate) fn main(request: &SweepRequest, commands: &dyn CaseCommands) -> Exit {
    match dispatch(request, commands) {
        Ok(code) => code,
        Err(f) => {
            eprintln!("error: {}", f.message);
            f.exit
        }
    }
}

fn dispatch(request: &SweepRequest, commands: &dyn CaseCommands) -> Result<Exit, Failure> {
    match request {
        SweepRequest::Collect { dir } => collect(dir, commands),
        SweepRequest::RunCase { dir, index } => run_case(dir, *index, commands),
        SweepRequest::Run {
            plan: path,
            jobs,
            dry_run: dry,
            output,
            progress,
            slurm,
        } => {
            let plan = plan::load(path, commands)?;
            let cases = plan
                .checked_cases(commands)
                .map_err(|e| Failure::input(format!("plan {}: {e}", path.display())))?;
            let layout = Layout::new(&output_dir(output.as_deref(), &plan, path)?);
            if *dry {
                dry_run(&layout, &plan, &cases);
                Ok(Exit::Completed)
            } else if let Some(resources) = slurm {
                let after = collect_hint(&layout)?;
                submit_script(&layout, &plan, &cases, resources, &after)
            } else {
                local(*jobs, *progress, &layout, &plan, &cases)
            }
        }
    }
}

/// What a sweep submitted to Slurm runs afterwards: `sweep collect DIR`.
fn collect_hint(layout: &Layout) -> Result<String, Failure> {
    Ok(format!(
        "merge what has finished (any time) with: {} sweep collect {}",
        quote(&this_exe()?.to_string_lossy()),
        quote(&layout.dir.to_string_lossy())
    ))
}

/// `--output`, else the plan's `output`.
fn output_dir(output: Option<&Path>, plan: &Plan, path: &Path) -> Result<PathBuf, Failure> {
    output
        .map(Path::to_path_buf)
        .or_else(|| plan.output.clone())
        .ok_or_else(|| {
            Failure::input(format!(
                "plan {}: no output directory: set output = \"DIR\" in the plan or give --output DIR",
                path.display()
            ))
        })
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

/// Makes (or checks) the directory and takes its lock. A directory that cannot be made is bad
/// input, as for a run's outputs: nothing has run yet.
fn open_dir(
    layout: &Layout,
    plan: &Plan,
    cases: &[CaseSpec],
) -> Result<super::layout::DirLock, Failure> {
    std::fs::create_dir_all(&layout.dir)
        .map_err(|e| Failure::input(format!("cannot create {}: {e}", layout.dir.display())))?;
    let guard = lock(layout)?;
    prepare(layout, plan, cases)?;
    Ok(guard)
}

/// A local sweep: the cases not yet done, `--jobs` at once, then the merged results.
pub(crate) fn local(
    jobs: Option<usize>,
    progress_mode: ProgressMode,
    layout: &Layout,
    plan: &Plan,
    cases: &[CaseSpec],
) -> Result<Exit, Failure> {
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
    let interrupted = run_pool(
        &exe,
        layout,
        &todo,
        plan.outputs,
        jobs,
        &mut progress,
        &presses,
    );
    progress.finish();
    let code = merge(layout, plan, cases)?;
    Ok(if interrupted { Exit::Interrupted } else { code })
}

/// Writes the merged results and the phase diagram, prints the tally and what did not
/// complete; [`Exit::Completed`] if every case completed, else [`Exit::Diverged`].
fn merge(layout: &Layout, plan: &Plan, cases: &[CaseSpec]) -> Result<Exit, Failure> {
    let rows = gather(layout, cases);
    write_tables(layout, &rows)?;
    let data = diagram_data(plan, &rows);
    super::plot::write_figures(layout, &data)?;
    let rrd = platefall_record::viewer::write_phase_recording(&layout.output("phase.rrd"), &data)?;
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
        if rrd.is_some() { ", phase.rrd" } else { "" }
    );
    Ok(if missing.is_empty() {
        Exit::Completed
    } else {
        Exit::Diverged
    })
}

/// The command that made a directory without a plan of its own (`ensemble`), from its
/// `plan.toml`; None for a sweep's.
fn made_by(layout: &Layout) -> Option<String> {
    let text = std::fs::read_to_string(layout.plan()).unwrap_or_default();
    let rest = text.strip_prefix(plan::MADE_BY)?;
    Some(rest.split('`').next().unwrap_or_default().to_string())
}

/// The manifest of a prepared directory, which must exist.
fn manifest_of(layout: &Layout) -> Result<Manifest, Failure> {
    read_manifest(layout)?.ok_or_else(|| {
        Failure::input(format!(
            "{} is not a sweep directory (no sweep.json): give the directory a sweep wrote",
            layout.dir.display()
        ))
    })
}

/// The plan and cases of a prepared directory (its own `plan.toml`, checked against `sweep.json`).
pub(crate) fn open_prepared(
    dir: &Path,
    commands: &dyn CaseCommands,
) -> Result<(Layout, Plan, Manifest), Failure> {
    let layout = Layout::new(dir);
    if let Some(command) = made_by(&layout) {
        return Err(Failure::input(format!(
            "{} was made by `platefall {command}`, not from a plan: run that command again to go \
             on",
            layout.dir.display()
        )));
    }
    let manifest = manifest_of(&layout)?;
    let mut plan = plan::load(&layout.plan(), commands)?;
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
fn collect(dir: &Path, commands: &dyn CaseCommands) -> Result<Exit, Failure> {
    let (layout, plan, manifest) = open_prepared(dir, commands)?;
    merge(&layout, &plan, &manifest.cases)
}

/// `run-case DIR INDEX`: one case of a prepared directory (a sweep's, or an ensemble's
/// members), as a child process; exits with the case's exit code.
fn run_case(dir: &Path, index: usize, commands: &dyn CaseCommands) -> Result<Exit, Failure> {
    // A directory made by another command (an ensemble's members) has only its manifest.
    let (layout, manifest) = match made_by(&Layout::new(dir)) {
        Some(_) => {
            let layout = Layout::new(dir);
            let manifest = manifest_of(&layout)?;
            (layout, manifest)
        }
        None => {
            let (layout, _plan, manifest) = open_prepared(dir, commands)?;
            (layout, manifest)
        }
    };
    let case = manifest.cases.get(index).ok_or_else(|| {
        Failure::input(format!(
            "case index {index} is out of range: accepted 0..={}",
            manifest.cases.len().saturating_sub(1)
        ))
    })?;
    if is_done(&layout, &case.id) {
        println!("{}: already done", case.id);
        return Ok(Exit::Completed);
    }
    let presses = interrupt_counter()?;
    let exe = this_exe()?;
    let mut running = launch(&exe, &layout, case, manifest.outputs())
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
    let state = outcome(&layout, &case.id, Some(&status));
    println!("{}: {state} {}", case.id, status.message);
    let code = status
        .exit_code
        .and_then(Exit::from_code)
        .unwrap_or(case_exit(state));
    if code == Exit::Checkpointed {
        requeue_slurm_task();
    }
    Ok(code)
}

/// Inside a Slurm array task stopped with its checkpoint (the script's `--signal=B:USR1@120`
/// before the time limit): puts the task back in the queue, where it resumes (best effort).
fn requeue_slurm_task() {
    let (Ok(job), Ok(task)) = (
        std::env::var("SLURM_ARRAY_JOB_ID"),
        std::env::var("SLURM_ARRAY_TASK_ID"),
    ) else {
        return;
    };
    let id = format!("{job}_{task}");
    match std::process::Command::new("scontrol")
        .args(["requeue", &id])
        .status()
    {
        Ok(s) if s.success() => {
            println!("requeued Slurm task {id}: it resumes from its checkpoint")
        }
        Ok(s) => eprintln!("warning: scontrol requeue {id} failed ({s})"),
        Err(e) => eprintln!("warning: cannot run scontrol requeue {id}: {e}"),
    }
}

/// The exit of `run-case` for a case whose process gave no exit code of platefall's (killed by
/// a signal): by how the case stands.
fn case_exit(state: CaseState) -> Exit {
    match state {
        CaseState::Completed => Exit::Completed,
        CaseState::Diverged => Exit::Diverged,
        CaseState::Interrupted => Exit::Interrupted,
        CaseState::Failed | CaseState::Unfinished | CaseState::Missing => Exit::OutputFailed,
    }
}
