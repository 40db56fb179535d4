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
//! Files: `args` (the command line and the plan it writes), `analysis` (the levels' summaries to
//! the study), `table` (the Markdown table).
pub mod analysis;
pub mod args;
pub mod table;

use std::path::Path;
use std::process::ExitCode;

pub use args::ConvergeArgs;

use crate::sweep::commands::{open_prepared, run_local};
use crate::sweep::layout::Layout;
use crate::sweep::{Failure, EXIT_INCOMPLETE};
use args::{ConvergeAction, Refined};
use platefall_record::output::write_atomically;

/// Runs `platefall converge ...` and returns the exit code: 0 every level completed and the study
/// was written; 2 bad input; 3 a level did not complete (the study of the others is written when
/// three remain); 4 an output could not be written; 130 interrupted.
pub fn main(args: &ConvergeArgs) -> ExitCode {
    match dispatch(args) {
        Ok(code) => ExitCode::from(code),
        Err(f) => {
            eprintln!("error: {}", f.message);
            ExitCode::from(f.code)
        }
    }
}

fn dispatch(args: &ConvergeArgs) -> Result<u8, Failure> {
    if let Some(ConvergeAction::Collect { dir }) = &args.action {
        return collect(dir);
    }
    let study = args::study_of(args)?;
    let layout = Layout::new(&study.output);
    let plan = crate::sweep::plan::parse(&study.plan_text, "converge")
        .map_err(|e| Failure::input(format!("converge: {e}")))?;
    let cases = plan
        .checked_cases()
        .map_err(|e| Failure::input(format!("converge: {e}")))?;
    if let Some(note) = &study.warning {
        eprintln!("warning: {note}");
    }
    let code = run_local(&layout, &plan, &cases, Some(study.jobs), args.progress)?;
    if code == crate::sweep::EXIT_INTERRUPTED {
        return Ok(code);
    }
    let written = write_study(&layout, &study.refined)?;
    Ok(if code != 0 { code } else { written })
}

/// `collect DIR`: the study of a directory's finished levels.
fn collect(dir: &Path) -> Result<u8, Failure> {
    let (layout, plan, _) = open_prepared(dir)?;
    let refined = match plan.grid.as_slice() {
        [axis] if plan.zip.is_empty() => Refined::from_name(&axis.name).map_err(Failure::input)?,
        _ => {
            return Err(Failure::input(format!(
                "{} is a sweep, not a convergence study (one refined option in [grid]): use \
                 `platefall sweep collect`",
                layout.dir.display()
            )))
        }
    };
    write_study(&layout, &refined)
}

/// Analyses the levels, writes `convergence.json` and `convergence.md`, prints the table; 0, or 3
/// when fewer than three levels completed or some did not complete.
fn write_study(layout: &Layout, refined: &Refined) -> Result<u8, Failure> {
    let (_, _, manifest) = open_prepared(&layout.dir)?;
    let study = analysis::analyse(layout, &manifest.cases, refined);
    let json = serde_json::to_string_pretty(&study).map_err(|e| Failure::output(e.to_string()))?;
    let md = table::markdown(&study);
    let out = |name: &str, bytes: &[u8]| {
        write_atomically("converge", &layout.output(name), bytes)
            .map(|_| ())
            .map_err(|e| Failure::output(e.to_string()))
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
        0
    } else {
        EXIT_INCOMPLETE
    })
}
