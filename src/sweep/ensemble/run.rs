//! Running an ensemble: its members as a sweep of child processes in the output directory (the
//! sweep's local pool, so a member whose summary is complete is not run again and Ctrl-C
//! finalises the running ones) or as the tasks of a Slurm job array (`--slurm`, the sweep's
//! script: each task a `platefall sweep run-case` of the directory), then the pooled
//! statistics of the completed members.
use std::path::Path;

use serde::Serialize;
use serde_json::Value as Json;

use super::histograms::write_histograms;
use super::members::{branch_of, case_of, members, Branch, EnsembleSpec, Member};
use super::parting::{parting, Parting};
use super::pooled::{pool_keys, table, Quantity};
use super::traces::trace;
use crate::exit::Exit;
use crate::sweep::child::is_done;
use crate::sweep::commands::local;
use crate::sweep::failure::{write_output, Failure};
use crate::sweep::layout::Layout;
use crate::sweep::plan::{Axis, CaseSpec, Plan, MADE_BY};
use crate::sweep::progress::ProgressMode;
use crate::sweep::slurm::{submit_script, SlurmOverrides};
use crate::sweep::values::{Scale, Value};
use platefall_core::sim::CaseKind;
use platefall_record::viewer::write_ensemble_recording;

/// What `DIR/ensemble.json` holds.
#[derive(Serialize)]
struct Pooled<'a> {
    /// Where the members branched.
    branch: &'a Branch,
    /// Every member, with its perturbation.
    members: &'a [Member],
    /// The members whose summaries say completed (the ones pooled).
    completed: Vec<&'a str>,
    /// When the members parted (their θ̇), and whether their windows start after it.
    parting: Option<Parting>,
    /// Per summary key with an interval: the pooled mean and interval, the members' means.
    quantities: std::collections::BTreeMap<String, Quantity>,
}

/// Runs `platefall ensemble` and returns its exit code: 0 every member completed and the
/// pooled statistics were written; 2 bad input (before anything runs); 3 a member did not
/// complete (the others are pooled); 4 an output could not be written; 130 interrupted.
pub(crate) fn main(
    spec: &EnsembleSpec,
    output: &Path,
    jobs: Option<usize>,
    progress: ProgressMode,
    slurm: Option<&SlurmOverrides>,
) -> Exit {
    match run(spec, output, jobs, progress, slurm) {
        Ok(code) => code,
        Err(f) => {
            eprintln!("error: {}", f.message);
            f.exit
        }
    }
}

fn run(
    spec: &EnsembleSpec,
    output: &Path,
    jobs: Option<usize>,
    progress: ProgressMode,
    slurm: Option<&SlurmOverrides>,
) -> Result<Exit, Failure> {
    let (ckpt, branch) = branch_of(spec)?;
    let case = ckpt
        .resume
        .argv
        .get(1)
        .and_then(|n| CaseKind::from_name(n))
        .ok_or_else(|| Failure::input("--from: the checkpoint's command line names no case"))?;
    let members = members(spec);
    let cases: Vec<CaseSpec> = members
        .iter()
        .enumerate()
        .map(|(k, m)| case_of(spec, &branch, k, m))
        .collect();
    let axis = Axis {
        name: "perturb-omega".into(),
        values: members
            .iter()
            .map(|m| Value::Float(m.perturbation))
            .collect(),
        scale: Scale::Linear,
    };
    let text = format!(
        "{MADE_BY}ensemble`: {} members branched from {} (not a plan for `platefall sweep`; \
         run the same `platefall ensemble` again to go on)\n",
        members.len(),
        branch.checkpoint.display()
    );
    let plan = Plan::along("ensemble", case, axis, text);
    let layout = Layout::new(output);
    let code = match slurm {
        Some(flags) if !cases.iter().all(|c| is_done(&layout, &c.id)) => {
            return submit_script(&layout, &plan, &cases, flags, SLURM_AFTER);
        }
        // With --slurm and every member done: pool them.
        Some(_) => Exit::Completed,
        None => local(jobs, progress, &layout, &plan, &cases)?,
    };
    if code == Exit::Interrupted {
        return Ok(code);
    }
    let written = write_pooled(&layout, &cases, &branch, &members)?;
    Ok(if code != Exit::Completed {
        code
    } else {
        written
    })
}

/// What to run once an ensemble's Slurm array has finished.
const SLURM_AFTER: &str = "once the array has finished, run this `platefall ensemble` command \
     again: it pools the members (and writes a script for any member not done)";

/// A completed member's summary.
fn completed_summary(layout: &Layout, id: &str) -> Option<Json> {
    let text = std::fs::read_to_string(layout.summary(id)).ok()?;
    let v: Json = serde_json::from_str(&text).ok()?;
    (v.get("status")?.as_str()? == "completed").then_some(v)
}

/// Pools the completed members into `ensemble.json` and `ensemble.md` and prints the table;
/// completed, or diverged (3) when fewer than two members completed.
fn write_pooled(
    layout: &Layout,
    cases: &[CaseSpec],
    branch: &Branch,
    members: &[Member],
) -> Result<Exit, Failure> {
    let done: Vec<(&CaseSpec, Json)> = cases
        .iter()
        .filter_map(|c| completed_summary(layout, &c.id).map(|s| (c, s)))
        .collect();
    let summaries: Vec<Json> = done.iter().map(|(_, s)| s.clone()).collect();
    let csvs: Vec<std::path::PathBuf> = done.iter().map(|(c, _)| layout.csv(&c.id)).collect();
    let csv_refs: Vec<&Path> = csvs.iter().map(|p| p.as_path()).collect();
    let window_start = summaries
        .iter()
        .filter_map(|s| s.get("developed_from").and_then(Json::as_f64))
        .reduce(f64::min);
    let pooled = Pooled {
        branch,
        members,
        completed: done.iter().map(|(c, _)| c.id.as_str()).collect(),
        parting: parting(&csv_refs, branch.t, window_start),
        quantities: pool_keys(&summaries),
    };
    let json = serde_json::to_string_pretty(&pooled).map_err(|e| Failure::output(e.to_string()))?;
    let md = markdown(&pooled);
    write_output(&layout.output("ensemble.json"), (json + "\n").as_bytes())?;
    write_output(&layout.output("ensemble.md"), md.as_bytes())?;
    let histograms = write_histograms(layout, pooled.completed.len(), &pooled.quantities)?;
    let traces: Vec<_> = done
        .iter()
        .filter_map(|(c, _)| trace(&c.id, &layout.csv(&c.id), branch.t))
        .collect();
    let title = format!("ensemble of {} members", traces.len());
    let rrd = write_ensemble_recording(&layout.output("ensemble.rrd"), &title, &traces, &md)
        .map_err(|e| Failure::output(e.to_string()))?;
    println!("{md}");
    println!(
        "ensemble: {}/ensemble.md, ensemble.json{}{}",
        layout.dir.display(),
        if histograms { ", histograms.png" } else { "" },
        if rrd.is_some() { ", ensemble.rrd" } else { "" }
    );
    Ok(
        if pooled.completed.len() == members.len() && members.len() >= 2 {
            Exit::Completed
        } else {
            Exit::Diverged
        },
    )
}

/// The ensemble's Markdown: what was pooled, when the members parted, the table.
fn markdown(p: &Pooled) -> String {
    let parted = match &p.parting {
        Some(Parting {
            time: Some(t),
            after_branch: Some(a),
            independent,
            ..
        }) => format!(
            "The members' θ̇ decorrelated at t = {t:.2} ({a:.2} after the branch); their windows \
             of averaging start {}.",
            if *independent {
                "after it"
            } else {
                "before it: lengthen the discarded part (--average-from-turn)"
            }
        ),
        _ => "The members' θ̇ did not decorrelate within their common span: they are not yet \
              independent (lengthen the run or the perturbation)."
            .to_string(),
    };
    format!(
        "# Ensemble of {} members ({} completed), branched at t = {:.4} ({:.2} turns after release)\n\n{parted}\n\n{}",
        p.members.len(),
        p.completed.len(),
        p.branch.t,
        p.branch.turns,
        table(&p.quantities)
    )
}
