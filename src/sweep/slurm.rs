//! `--slurm`: a job-array script with one task per case not yet done; each task runs
//! `platefall sweep run-case DIR INDEX` with this executable's absolute path, so the cluster fills
//! the same directory a local sweep would.
use super::child::{is_done, this_exe};
use super::failure::{write_output, Failure};
use super::layout::{prepare, Layout};
use super::plan::{check_slurm, CaseSpec, Plan, SlurmPlan};
use super::slurm_time::{time_limit_seconds, DEFAULT_TIME};
use crate::exit::Exit;

/// Resources of each array task given on the command line (they override the plan's).
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct SlurmOverrides {
    /// Partition to submit to.
    pub(crate) partition: Option<String>,
    /// Wall-time limit per case, as sbatch takes it.
    pub(crate) time: Option<String>,
    /// Memory per case, as sbatch takes it.
    pub(crate) mem: Option<String>,
    /// CPUs per case.
    pub(crate) cpus: Option<u32>,
    /// At most this many array tasks at once.
    pub(crate) max_parallel: Option<u32>,
    /// Seconds before the time limit at which Slurm warns each case.
    pub(crate) signal_lead: Option<u32>,
}

impl SlurmOverrides {
    /// The `[slurm]` keys these flags give.
    fn keys(&self) -> Vec<&'static str> {
        let given = [
            ("time", self.time.is_some()),
            ("memory", self.mem.is_some()),
            ("partition", self.partition.is_some()),
            ("cpus", self.cpus.is_some()),
            ("max-parallel", self.max_parallel.is_some()),
            ("signal-lead", self.signal_lead.is_some()),
        ];
        given.iter().filter(|(_, g)| *g).map(|(k, _)| *k).collect()
    }
}

/// Resources when neither the plan nor a flag gives them (the time: [`DEFAULT_TIME`]).
const DEFAULT_MEMORY: &str = "2G";
/// The signal lead when the plan gives none and the time limit is long: two minutes to stop
/// after the current step and write the checkpoint and the outputs.
const DEFAULT_SIGNAL_LEAD: u64 = 120;
/// Slurm's default MaxArraySize is 1001 (indices 0..=1000).
const DEFAULT_MAX_ARRAY_INDEX: usize = 1000;

/// The plan's resources overridden by the flags.
fn resources(plan: &SlurmPlan, flags: &SlurmOverrides) -> SlurmPlan {
    SlurmPlan {
        time: flags.time.clone().or_else(|| plan.time.clone()),
        memory: flags.mem.clone().or_else(|| plan.memory.clone()),
        cpus: flags.cpus.or(plan.cpus),
        partition: flags.partition.clone().or_else(|| plan.partition.clone()),
        max_parallel: flags.max_parallel.or(plan.max_parallel),
        signal_lead: flags.signal_lead.or(plan.signal_lead),
        sbatch: plan.sbatch.clone(),
        setup: plan.setup.clone(),
    }
}

/// Indices as Slurm's `--array` takes them: runs of consecutive indices as `a-b`.
pub(crate) fn array_spec(indices: &[usize]) -> String {
    let mut parts = Vec::new();
    let mut i = 0;
    while i < indices.len() {
        let start = indices[i];
        let mut end = start;
        while i + 1 < indices.len() && indices[i + 1] == end + 1 {
            i += 1;
            end += 1;
        }
        parts.push(if end == start {
            start.to_string()
        } else {
            format!("{start}-{end}")
        });
        i += 1;
    }
    parts.join(",")
}

/// Seconds before the time limit at which Slurm warns the task with SIGUSR1: the plan's
/// `signal-lead`, else two minutes, or a quarter of a shorter time limit's (at least 1 s). Slurm
/// may send it up to a minute earlier than asked (it checks time limits every 30 s or so).
pub(crate) fn signal_lead_of(res: &SlurmPlan) -> u64 {
    if let Some(lead) = res.signal_lead {
        return u64::from(lead);
    }
    let limit = time_limit_seconds(res.time.as_deref().unwrap_or(DEFAULT_TIME)).flatten();
    limit.map_or(DEFAULT_SIGNAL_LEAD, |l| {
        (l / 4).clamp(1, DEFAULT_SIGNAL_LEAD)
    })
}

/// A word for the shell, single-quoted when it needs to be.
pub(crate) fn quote(s: &str) -> String {
    if !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+%@".contains(c))
    {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

/// A job name Slurm and the shell accept.
fn job_name(name: &str) -> String {
    let clean: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("platefall-{clean}")
}

/// The text of `sweep.sbatch`; `after` says what to run once its tasks have finished.
pub(crate) fn script(
    layout: &Layout,
    plan: &Plan,
    todo: &[usize],
    res: &SlurmPlan,
    exe: &str,
    after: &str,
) -> String {
    let dir = layout.dir.to_string_lossy();
    let logs = layout.slurm_logs();
    let mut array = array_spec(todo);
    if let Some(n) = res.max_parallel {
        array.push_str(&format!("%{n}"));
    }
    let mut s = String::from("#!/bin/bash\n");
    s.push_str(&format!(
        "# platefall sweep `{}`: {} case(s) of `{}` as a Slurm job array (one task per case).\n",
        plan.name,
        todo.len(),
        plan.case
    ));
    s.push_str(&format!(
        "# Submit: sbatch {}\n",
        quote(&layout.output("sweep.sbatch").to_string_lossy())
    ));
    s.push_str(&format!("# Then {after}\n"));
    let mut opt = |line: String| s.push_str(&format!("#SBATCH {line}\n"));
    opt(format!("--job-name={}", job_name(&plan.name)));
    opt(format!("--array={array}"));
    opt(format!("--output={}/%A_%a.out", logs.to_string_lossy()));
    opt(format!(
        "--time={}",
        res.time.as_deref().unwrap_or(DEFAULT_TIME)
    ));
    opt(format!(
        "--mem={}",
        res.memory.as_deref().unwrap_or(DEFAULT_MEMORY)
    ));
    opt(format!("--cpus-per-task={}", res.cpus.unwrap_or(1)));
    opt("--ntasks=1".into());
    // Before the time limit the case writes its checkpoint and the task requeues itself; the
    // next attempt resumes it and appends to the same log.
    opt(format!("--signal=B:USR1@{}", signal_lead_of(res)));
    opt("--requeue".into());
    opt("--open-mode=append".into());
    if let Some(p) = &res.partition {
        opt(format!("--partition={p}"));
    }
    for line in &res.sbatch {
        opt(line.trim().trim_start_matches("#SBATCH").trim().to_string());
    }
    s.push_str("set -eu\n");
    for line in &res.setup {
        s.push_str(line);
        s.push('\n');
    }
    s.push_str(&format!(
        "exec {} sweep run-case {} \"$SLURM_ARRAY_TASK_ID\"\n",
        quote(exe),
        quote(&dir)
    ));
    s
}

/// `--slurm`: prepares the directory, writes `DIR/sweep.sbatch` for the cases not yet done and
/// prints how to submit it and, from `after`, what to run once its tasks have finished.
pub(crate) fn submit_script(
    layout: &Layout,
    plan: &Plan,
    cases: &[CaseSpec],
    flags: &SlurmOverrides,
    after: &str,
) -> Result<Exit, Failure> {
    let res = resources(&plan.slurm, flags);
    check_slurm(&res, &flags.keys())?;
    let exe = this_exe()?;
    std::fs::create_dir_all(layout.slurm_logs()).map_err(|e| {
        Failure::input(format!(
            "cannot create {}: {e}",
            layout.slurm_logs().display()
        ))
    })?;
    prepare(layout, plan, cases)?;
    let todo: Vec<usize> = cases
        .iter()
        .filter(|c| !is_done(layout, &c.id))
        .map(|c| c.index)
        .collect();
    let path = layout.output("sweep.sbatch");
    if todo.is_empty() {
        println!(
            "every case of {} is done: nothing to submit; {after}",
            layout.dir.display()
        );
        return Ok(Exit::Completed);
    }
    let text = script(layout, plan, &todo, &res, &exe.to_string_lossy(), after);
    write_output(&path, text.as_bytes())?;
    if todo.last().is_some_and(|&i| i > DEFAULT_MAX_ARRAY_INDEX) {
        eprintln!(
            "warning: array indices go up to {}; Slurm's default MaxArraySize allows 0..={DEFAULT_MAX_ARRAY_INDEX} (ask your admins, or split the plan)",
            todo.last().copied().unwrap_or(0)
        );
    }
    println!(
        "wrote {} ({} of {} cases; {} already done)",
        path.display(),
        todo.len(),
        cases.len(),
        cases.len() - todo.len()
    );
    println!("submit with:\n  sbatch {}", quote(&path.to_string_lossy()));
    println!("then {after}");
    Ok(Exit::Completed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn array_spec_merges_consecutive_indices() {
        assert_eq!(array_spec(&[0, 1, 2, 3]), "0-3");
        assert_eq!(array_spec(&[1, 3, 4, 5, 9]), "1,3-5,9");
        assert_eq!(array_spec(&[7]), "7");
    }

    #[test]
    fn time_limits_read_as_slurm_reads_them() {
        let t = time_limit_seconds;
        assert_eq!(t("90"), Some(Some(5400)));
        assert_eq!(t("1:30"), Some(Some(120)), "rounded up to whole minutes");
        assert_eq!(t("01:00:00"), Some(Some(3600)));
        assert_eq!(t("2-12"), Some(Some(216_000)));
        assert_eq!(t("1-0:30"), Some(Some(88_200)));
        assert_eq!(t("1-00:00:01"), Some(Some(86_460)));
        for unlimited in ["UNLIMITED", "infinite", "0", "-1"] {
            assert_eq!(t(unlimited), Some(None), "{unlimited}");
        }
        for bad in ["1h", "", "1:2:3:4", "a-1", "1-", "-5", "1:-2"] {
            assert_eq!(t(bad), None, "{bad}");
        }
    }

    #[test]
    fn the_signal_lead_is_the_plans_or_fits_the_time_limit() {
        let lead = |time: Option<&str>, signal_lead| {
            signal_lead_of(&SlurmPlan {
                time: time.map(String::from),
                signal_lead,
                ..Default::default()
            })
        };
        assert_eq!(lead(None, None), 120, "the default hour");
        assert_eq!(lead(Some("00:02:00"), None), 30);
        assert_eq!(lead(Some("10"), None), 120);
        assert_eq!(lead(Some("UNLIMITED"), None), 120);
        assert_eq!(lead(Some("00:02:00"), Some(45)), 45);
    }

    #[test]
    fn quote_leaves_plain_words_and_quotes_the_rest() {
        assert_eq!(quote("/a/b-c.d"), "/a/b-c.d");
        assert_eq!(quote("a b"), "'a b'");
        assert_eq!(quote("it's"), "'it'\\''s'");
    }
}
