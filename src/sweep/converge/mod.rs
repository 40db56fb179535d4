//! `platefall converge`: a refinement study of one case. It runs the case at three or more values
//! of one refined option (the resolution, a time-step control or the domain extent) as a sweep of
//! child processes in an output directory, then reports per quantity the observed order, the
//! Richardson extrapolation and the grid-convergence index, with the runs' own 95 % intervals
//! deciding which differences are resolved (`platefall_post::convergence`).
//!
//! A study is a sweep whose plan is written from the command line: `DIR/plan.toml` has the case,
//! its options as `[fixed]` and the refined option as the one `[grid]` axis, so everything a
//! sweep does holds here — each level is a child process with its own `cases/<id>/summary.json`,
//! a level whose summary is complete is not run again, Ctrl-C finalises the running levels, and
//! `results.csv` has one row per level (with the half-widths as columns). The study's own
//! outputs are `DIR/convergence.json` and `DIR/convergence.md` (written atomically), and the
//! table on stdout; `platefall converge collect DIR` recomputes them from the finished levels.
//!
//! With `--ensembles DIR1,DIR2,DIR3` the levels are ensembles already pooled by `platefall
//! ensemble` (one directory per value of the refined option): each level's value and 95 %
//! half-width are the ensemble's pooled mean and half-width, and nothing runs.
//!
//! Files: `study` (the request checked, and the plan it writes), `ensembles` (ensemble
//! directories as levels), `analysis` (the levels' summaries to the study), `table` (the
//! Markdown table).
mod analysis;
mod ensembles;
mod study;
mod table;

use std::path::{Path, PathBuf};

use super::commands::{local, open_prepared};
use super::failure::Failure;
use super::layout::Layout;
use super::plan::CaseSpec;
use super::{CaseCommands, ProgressMode};
use crate::exit::Exit;
use platefall_record::output::write_atomically;
use study::Refined;

/// What the command line asks of a refinement study.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ConvergeRequest {
    /// Run (or resume) a study and write it.
    Run {
        /// `OPTION=V1,V2,V3`: the refined option and its values.
        refine: String,
        /// The study's directory.
        output: PathBuf,
        /// Levels run at once.
        jobs: usize,
        /// Worker threads of each level (None: the cores divided among the jobs).
        threads: Option<usize>,
        /// The progress display.
        progress: ProgressMode,
        /// The case and its options, as on its own command line.
        case: Vec<String>,
    },
    /// A study of ensembles already pooled, one directory per level.
    Ensembles {
        /// `OPTION=V1,V2,V3`: the refined option and its values.
        refine: String,
        /// The ensembles' directories, in the order of the values.
        dirs: Vec<PathBuf>,
        /// Where the study is written.
        output: PathBuf,
    },
    /// Rewrite the study of a directory's finished levels.
    Collect {
        /// The study's directory.
        dir: PathBuf,
    },
}

/// Runs a study and returns the exit code: 0 every level completed and the study was written;
/// 2 bad input; 3 a level did not complete (the study of the others is written when three
/// remain); 4 an output could not be written; 130 interrupted.
pub(crate) fn main(request: &ConvergeRequest, commands: &dyn CaseCommands) -> Exit {
    match dispatch(request, commands) {
        Ok(code) => code,
        Err(f) => {
            eprintln!("error: {}", f.message);
            f.exit
        }
    }
}

fn dispatch(request: &ConvergeRequest, commands: &dyn CaseCommands) -> Result<Exit, Failure> {
    let (refine, output, jobs, threads, progress, case) = match request {
        ConvergeRequest::Collect { dir } => return collect(dir, commands),
        ConvergeRequest::Ensembles {
            refine,
            dirs,
            output,
        } => return of_ensembles(refine, dirs, output),
        ConvergeRequest::Run {
            refine,
            output,
            jobs,
            threads,
            progress,
            case,
        } => (refine, output, *jobs, *threads, *progress, case),
    };
    let study = study::study_of(refine, output, jobs, threads, case, commands)?;
    let layout = Layout::new(&study.output);
    let plan = super::plan::parse(&study.plan_text, "converge", commands)
        .map_err(|e| Failure::input(format!("converge: {e}")))?;
    let cases = plan
        .checked_cases(commands)
        .map_err(|e| Failure::input(format!("converge: {e}")))?;
    let code = local(Some(study.jobs), progress, &layout, &plan, &cases)?;
    if code == Exit::Interrupted {
        return Ok(code);
    }
    let written = write_levels(&layout, &cases, &study.refined)?;
    Ok(if code != Exit::Completed {
        code
    } else {
        written
    })
}

/// `collect DIR`: the study of a directory's finished levels.
fn collect(dir: &Path, commands: &dyn CaseCommands) -> Result<Exit, Failure> {
    let (layout, plan, manifest) = open_prepared(dir, commands)?;
    let refined = match plan.grid.as_slice() {
        [axis] if plan.zip.is_empty() => Refined::from_name(&axis.name)?,
        _ => {
            return Err(Failure::input(format!(
                "{} is a sweep, not a convergence study (one refined option in [grid]): use \
                 `platefall sweep collect`",
                layout.dir.display()
            )))
        }
    };
    write_levels(&layout, &manifest.cases, &refined)
}

/// `--ensembles`: the study of ensembles already pooled, one per level.
fn of_ensembles(refine: &str, dirs: &[PathBuf], output: &Path) -> Result<Exit, Failure> {
    let (refined, values) = study::refine_values(refine)?;
    let levels = ensembles::ensemble_levels(&refined, &values, dirs)?;
    let shown: Vec<String> = dirs
        .iter()
        .map(|d| d.to_string_lossy().into_owned())
        .collect();
    let case = vec![
        "converge".to_string(),
        format!("--refine={refine}"),
        format!("--ensembles={}", shown.join(",")),
    ];
    std::fs::create_dir_all(output)
        .map_err(|e| Failure::input(format!("cannot create {}: {e}", output.display())))?;
    let study = analysis::analyse_levels(levels, &refined, case);
    write_study(&Layout::new(output), study)
}

/// Analyses the levels, writes `convergence.json` and `convergence.md`, prints the table;
/// completed, or diverged (3) when fewer than three levels completed or some did not complete.
fn write_levels(layout: &Layout, cases: &[CaseSpec], refined: &Refined) -> Result<Exit, Failure> {
    write_study(layout, analysis::analyse(layout, cases, refined))
}

/// Writes `study` as `convergence.json` and `convergence.md` and prints the table; completed,
/// or diverged (3) when fewer than three levels completed or some did not complete.
fn write_study(layout: &Layout, study: analysis::Study) -> Result<Exit, Failure> {
    let json = serde_json::to_string_pretty(&study).map_err(|e| Failure::output(e.to_string()))?;
    let md = table::markdown(&study);
    let out = |name: &str, bytes: &[u8]| -> Result<(), Failure> {
        write_atomically("converge", &layout.output(name), bytes)?;
        Ok(())
    };
    out("convergence.json", (json + "\n").as_bytes())?;
    out("convergence.md", md.as_bytes())?;
    println!("{md}");
    println!(
        "study: {}/convergence.md, convergence.json",
        layout.dir.display()
    );
    let complete = study.levels.iter().all(|l| l.status == "completed");
    Ok(if complete && study.levels.len() >= 3 {
        Exit::Completed
    } else {
        Exit::Diverged
    })
}
