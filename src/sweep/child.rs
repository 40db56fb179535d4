//! One case as a child process: its argument vector with the sweep's outputs, its log, its
//! `status.json` (attempt, host, start, end, exit code, the last error line) and whether it is done.
use std::fs::OpenOptions;
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Instant, SystemTime};

use serde::{Deserialize, Serialize};

use super::clock::{hostname, unix_seconds, utc};
use super::failure::Failure;
use super::layout::Layout;
use super::plan::{CaseSpec, Outputs};
use platefall_core::sim::StatusKind;
use platefall_record::checkpoint::read_checkpoint;
use platefall_record::output::{partial_path_of, write_atomically, OutputError};

/// This executable, for the cases' child processes and the Slurm script.
pub(crate) fn this_exe() -> Result<PathBuf, Failure> {
    std::env::current_exe()
        .map_err(|e| Failure::output(format!("cannot find this executable's path: {e}")))
}

/// Writes a case's `status.json` atomically.
fn write_status(layout: &Layout, id: &str, status: &CaseStatus) -> Result<(), OutputError> {
    let path = layout.status(id);
    let bytes = serde_json::to_vec_pretty(status)
        .map_err(|e| OutputError::new("status.json", &path, e.to_string()))?;
    write_atomically("status.json", &path, &bytes).map(|_| ())
}

/// What `status.json` says about a case's last attempt.
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
pub(crate) struct CaseStatus {
    /// "running" while the attempt runs, "exited" after it.
    pub(crate) state: String,
    pub(crate) attempt: u32,
    pub(crate) host: String,
    pub(crate) pid: u32,
    pub(crate) started: String,
    pub(crate) started_unix: f64,
    #[serde(default)]
    pub(crate) finished: Option<String>,
    /// Wall time of the child process, seconds.
    #[serde(default)]
    pub(crate) elapsed_seconds: Option<f64>,
    #[serde(default)]
    pub(crate) exit_code: Option<i32>,
    /// The signal that ended the process, if one did.
    #[serde(default)]
    pub(crate) signal: Option<i32>,
    /// The last error line of the attempt's log (or what ended it).
    #[serde(default)]
    pub(crate) message: String,
}

/// Reads a case's `status.json`, if there is a readable one.
pub(crate) fn read_status(layout: &Layout, id: &str) -> Option<CaseStatus> {
    let text = std::fs::read_to_string(layout.status(id)).ok()?;
    serde_json::from_str(&text).ok()
}

/// The `status` of a case's summary, if the summary exists at its final name.
pub(crate) fn summary_status(layout: &Layout, id: &str) -> Option<StatusKind> {
    let text = std::fs::read_to_string(layout.summary(id)).ok()?;
    let v: serde_json::Value = serde_json::from_str(&text).ok()?;
    serde_json::from_value(v.get("status")?.clone()).ok()
}

/// A case is done when its summary says completed or diverged (a finished failure); an
/// interrupted or missing summary means it runs again.
pub(crate) fn is_done(layout: &Layout, id: &str) -> bool {
    matches!(
        summary_status(layout, id),
        Some(StatusKind::Completed | StatusKind::Diverged)
    )
}

/// How a case's attempt starts.
#[derive(Clone, Debug, PartialEq)]
enum Start {
    /// From the beginning.
    Fresh,
    /// From its checkpoint after `steps` steps, with the earlier rows of the CSV from
    /// `csv_from` (None: the case's own CSV).
    Resume {
        steps: u64,
        csv_from: Option<PathBuf>,
    },
}

/// How a case goes on. It resumes from its checkpoint when this program reads it and the case's
/// CSV holds the rows up to it; or when, killed outright (SIGKILL, the OOM killer, a lost node),
/// it left its CSV under the temporary name of its process (`last`'s pid), which holds the rows
/// up to its last checkpoint. Otherwise it starts again.
fn start_of(layout: &Layout, id: &str, last: Option<&CaseStatus>) -> Start {
    let Ok(ckpt) = read_checkpoint(&layout.checkpoint(id), &crate::version::program_version())
    else {
        return Start::Fresh;
    };
    let (csv, steps) = (layout.csv(id), ckpt.sim.steps());
    let holds_rows = |p: &Path| platefall_record::check_csv_prefix(p, steps).is_ok();
    if holds_rows(&csv) {
        return Start::Resume {
            steps,
            csv_from: None,
        };
    }
    match last.map(|s| partial_path_of(&csv, s.pid)) {
        Some(left) if holds_rows(&left) => Start::Resume {
            steps,
            csv_from: Some(left),
        },
        _ => Start::Fresh,
    }
}

/// The full argument vector of a case: its options plus the outputs the sweep manages, with
/// checkpoints at the default cadence; or, resumed, `resume` of its checkpoint with the same
/// outputs (the recording goes on in a continuation `run-from-STEP.rrd`; a VTK series is
/// written by the first attempt only).
fn full_args(layout: &Layout, case: &CaseSpec, outputs: Outputs, start: &Start) -> Vec<String> {
    let path = |p: &Path| p.to_string_lossy().into_owned();
    let ckpt = layout.checkpoint(&case.id);
    let resumed = *start != Start::Fresh;
    let mut args = match start {
        Start::Resume { csv_from, .. } => {
            let mut a = vec!["resume".into(), path(&ckpt), "--quiet".into()];
            a.extend(csv_from.iter().map(|f| format!("--csv-from={}", path(f))));
            a
        }
        Start::Fresh => {
            let mut a = case.args.clone();
            a.push(format!("--checkpoint={}", path(&ckpt)));
            a.push("--progress=off".into());
            a
        }
    };
    args.push(format!("--summary={}", path(&layout.summary(&case.id))));
    args.push(format!("--csv={}", path(&layout.csv(&case.id))));
    match (outputs.recording, resumed) {
        (true, false) => args.push(format!("--save={}", path(&layout.recording(&case.id)))),
        (true, true) => {}
        (false, _) => args.push("--no-save".into()),
    }
    if outputs.vtk && !resumed {
        args.push(format!("--vtk={}", path(&layout.vtk(&case.id))));
    }
    args
}

/// A running case.
pub(crate) struct Running {
    pub(crate) case: CaseSpec,
    pub(crate) child: Child,
    pub(crate) status: CaseStatus,
    started: Instant,
    /// Where the child's own lines start in the log.
    log_start: u64,
    /// The CSV a killed attempt left, which this attempt resumes from, and the rows it is
    /// taken for (removed once the case's own CSV holds them).
    csv_from: Option<(PathBuf, u64)>,
}

/// Starts a case: removes a stale summary, appends an attempt header to its log, records
/// `status.json` as running, and spawns `exe` with the case's arguments.
pub(crate) fn launch(
    exe: &Path,
    layout: &Layout,
    case: &CaseSpec,
    outputs: Outputs,
) -> std::io::Result<Running> {
    let id = &case.id;
    std::fs::create_dir_all(layout.case_dir(id))?;
    match std::fs::remove_file(layout.summary(id)) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => return Err(e),
        _ => {}
    }
    let last = read_status(layout, id);
    let attempt = last.as_ref().map_or(1, |s| s.attempt + 1);
    let start = start_of(layout, id, last.as_ref());
    let args = full_args(layout, case, outputs, &start);
    let mut log = OpenOptions::new()
        .create(true)
        .append(true)
        .open(layout.log(id))?;
    let now = SystemTime::now();
    writeln!(
        log,
        "==== platefall sweep: case {id}, attempt {attempt}, {} on {}\n$ {} {}",
        utc(now),
        hostname(),
        exe.display(),
        args.join(" ")
    )?;
    let log_start = log.seek(SeekFrom::End(0))?;
    let mut cmd = Command::new(exe);
    cmd.args(&args)
        .stdin(Stdio::null())
        .stdout(log.try_clone()?)
        .stderr(log);
    stop_with_parent(&mut cmd);
    let child = cmd.spawn()?;
    let status = CaseStatus {
        state: "running".into(),
        attempt,
        host: hostname(),
        pid: child.id(),
        started: utc(now),
        started_unix: unix_seconds(now),
        ..Default::default()
    };
    write_status(layout, id, &status).map_err(std::io::Error::other)?;
    Ok(Running {
        case: case.clone(),
        child,
        status,
        started: Instant::now(),
        log_start,
        csv_from: match start {
            Start::Resume { steps, csv_from } => csv_from.map(|f| (f, steps)),
            Start::Fresh => None,
        },
    })
}

/// Records in `status.json` that a case could not be started (best effort), and returns that status.
pub(crate) fn launch_failed(layout: &Layout, case: &CaseSpec, err: &std::io::Error) -> CaseStatus {
    let now = SystemTime::now();
    let status = CaseStatus {
        state: "exited".into(),
        attempt: read_status(layout, &case.id).map_or(1, |s| s.attempt + 1),
        host: hostname(),
        started: utc(now),
        started_unix: unix_seconds(now),
        finished: Some(utc(now)),
        message: format!("could not start: {err}"),
        ..Default::default()
    };
    let _ = write_status(layout, &case.id, &status);
    status
}

/// On Linux, a case gets SIGINT when the sweep that started it dies (even by SIGKILL), so it
/// finalises its outputs instead of running on unsupervised.
fn stop_with_parent(cmd: &mut Command) {
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::process::CommandExt;
        // SAFETY: prctl is async-signal-safe and touches no memory of the parent.
        unsafe {
            cmd.pre_exec(|| {
                if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGINT) != 0 {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            });
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = cmd;
}

/// Sends SIGINT (Ctrl-C) to a running case, or kills it where there are no signals.
pub(crate) fn interrupt(r: &mut Running, hard: bool) {
    #[cfg(unix)]
    {
        let sig = if hard { libc::SIGKILL } else { libc::SIGINT };
        // SAFETY: kill(2) on our own child's pid; it has not been reaped yet.
        unsafe {
            libc::kill(r.child.id() as libc::pid_t, sig);
        }
    }
    #[cfg(not(unix))]
    {
        let _ = hard;
        let _ = r.child.kill();
    }
}

/// Records how a case ended in its `status.json`, and returns that status.
pub(crate) fn finish(layout: &Layout, mut r: Running, exit: ExitStatus) -> CaseStatus {
    let id = r.case.id.clone();
    let now = SystemTime::now();
    r.status.state = "exited".into();
    r.status.finished = Some(utc(now));
    r.status.elapsed_seconds = Some(r.started.elapsed().as_secs_f64());
    r.status.exit_code = exit.code();
    r.status.signal = exit_signal(&exit);
    r.status.message = match r.status.signal {
        Some(sig) => format!("killed by signal {sig}"),
        None if exit.success() => String::new(),
        None => last_error_line(&layout.log(&id), r.log_start),
    };
    if let Err(e) = write_status(layout, &id, &r.status) {
        eprintln!("warning: {e}");
    }
    if let Some((left, steps)) = r.csv_from {
        if platefall_record::check_csv_prefix(&layout.csv(&id), steps).is_ok() {
            let _ = std::fs::remove_file(left);
        }
    }
    r.status
}

fn exit_signal(exit: &ExitStatus) -> Option<i32> {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        exit.signal()
    }
    #[cfg(not(unix))]
    {
        let _ = exit;
        None
    }
}

/// The attempt's last `error:` line, else its last `interrupted` line, else its last line.
pub(crate) fn last_error_line(log: &Path, from: u64) -> String {
    let mut text = String::new();
    if let Ok(mut f) = std::fs::File::open(log) {
        if f.seek(SeekFrom::Start(from)).is_ok() {
            let _ = f.read_to_string(&mut text);
        }
    }
    let lines: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    let pick = lines
        .iter()
        .rev()
        .find(|l| l.starts_with("error:"))
        .or_else(|| lines.iter().rev().find(|l| l.starts_with("interrupted")))
        .or_else(|| lines.last())
        .copied()
        .unwrap_or("");
    let mut line = pick.to_string();
    if line.len() > 300 {
        let cut = (0..=300)
            .rev()
            .find(|&i| line.is_char_boundary(i))
            .unwrap_or(0);
        line.truncate(cut);
        line.push('…');
    }
    line
}
