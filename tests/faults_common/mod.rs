//! Shared helpers of the fault-injection tests: run the binary, signal it, and check that every
//! output at its final name is complete (the .rrd verifies, the CSV and summary say how the run
//! ended) and that no temporary file is left behind.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::checkpoint_common;
pub use crate::record_common::{decode, rerun_cli};

pub const PF: &str = env!("CARGO_BIN_EXE_platefall");

/// A fresh scratch directory for one test.
pub fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("platefall-faults-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Owned arguments.
pub fn strings(parts: &[&str]) -> Vec<String> {
    parts.iter().map(|s| s.to_string()).collect()
}

/// A run of the static case at N = 8 (about 150 steps, 1.5 convective times, a second here).
pub fn static_args(t_end: &str) -> Vec<String> {
    strings(&[
        "static",
        "--resolution",
        "8",
        "--t-end",
        t_end,
        "--progress",
        "off",
    ])
}

/// The three outputs of a run in `dir`: --save a.rrd --csv a.csv --summary a.json.
pub fn outputs(dir: &Path) -> Vec<String> {
    let p = |f: &str| dir.join(f).to_string_lossy().into_owned();
    vec![
        "--save".into(),
        p("a.rrd"),
        "--csv".into(),
        p("a.csv"),
        "--summary".into(),
        p("a.json"),
    ]
}

/// `base` followed by the three outputs in `dir`.
pub fn with_outputs(mut base: Vec<String>, dir: &Path) -> Vec<String> {
    base.extend(outputs(dir));
    base
}

/// A long static run writing to `dir` on a disk that fills up (`env` may inject it): exit 4,
/// one error line naming the .rrd and `reason`, no .rrd at its final name, the outputs that fit
/// complete and saying the run stopped for it, no temporary file left.
pub fn assert_disk_full_run(dir: &Path, env: &[(&str, &str)], reason: &str) {
    let out = run(&with_outputs(static_args("100"), dir), env);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(4), "{err}");
    let errors = error_lines(&err);
    assert_eq!(errors.len(), 1, "{err}");
    assert!(
        errors[0].contains("--save") && errors[0].contains(reason),
        "{err}"
    );
    assert!(errors[0].contains("the run stopped at t ="), "{err}");
    assert!(
        !dir.join("a.rrd").exists(),
        "a failed .rrd at its final name"
    );
    assert_final_outputs_complete(dir, "output_failed");
    assert!(partial_files(dir).is_empty(), "{:?}", partial_files(dir));
}

/// Runs platefall with `args` and the environment `env` to its end.
pub fn run(args: &[String], env: &[(&str, &str)]) -> Output {
    Command::new(PF)
        .args(args)
        .envs(env.iter().copied())
        .output()
        .expect("platefall runs")
}

/// Starts platefall in the background, stderr captured to `dir/stderr`.
pub fn start(args: &[String], env: &[(&str, &str)], dir: &Path) -> Child {
    let err = std::fs::File::create(dir.join("stderr")).unwrap();
    Command::new(PF)
        .args(args)
        .envs(env.iter().copied())
        .stdout(Stdio::null())
        .stderr(err)
        .spawn()
        .expect("platefall starts")
}

/// Sends a signal ("INT", "KILL") to a child.
pub fn signal(child: &Child, sig: &str) {
    let ok = Command::new("kill")
        .args([format!("-{sig}"), child.id().to_string()])
        .status()
        .unwrap()
        .success();
    assert!(ok, "kill -{sig}");
}

/// Waits (at most `limit`) for `cond`.
pub fn wait_for(limit: Duration, mut cond: impl FnMut() -> bool) -> bool {
    let t0 = Instant::now();
    while t0.elapsed() < limit {
        if cond() {
            return true;
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    false
}

/// Waits for a child to exit (at most `limit`); its exit code and how long it took.
pub fn exit_code(child: &mut Child, limit: Duration) -> (i32, Duration) {
    let t0 = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return (status.code().unwrap_or(-1), t0.elapsed());
        }
        if t0.elapsed() > limit {
            let _ = child.kill();
            panic!("platefall did not exit within {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Files in `dir` whose names say they are temporary (`.NAME.partial-PID`).
pub fn partial_files(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .map(|rd| {
            rd.flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| n.contains(".partial-"))
                .collect()
        })
        .unwrap_or_default()
}

/// True once the run has written a few rows to its temporary CSV (it is running).
pub fn running(dir: &Path) -> bool {
    partial_files(dir).iter().any(|n| {
        n.starts_with(".a.rrd.partial-")
            && std::fs::metadata(dir.join(n)).is_ok_and(|m| m.len() > 100_000)
    })
}

/// The lines of stderr that are errors, warnings or the outcome (what a user reads).
pub fn error_lines(stderr: &str) -> Vec<String> {
    stderr
        .lines()
        .filter(|l| l.starts_with("error:") || l.starts_with("interrupted:"))
        .map(String::from)
        .collect()
}

/// Asserts the .rrd at `path` is complete: `rerun rrd verify` passes (the real CLI when it is
/// installed: `.ci/run` sets PLATEFALL_RERUN_CLI), and Rerun's decoder finds its footer.
pub fn assert_rrd_complete(path: &Path) {
    assert!(decode(path).has_footer, "{} has no footer", path.display());
    if let Some(cli) = rerun_cli() {
        let out = Command::new(cli)
            .args(["rrd", "verify"])
            .arg(path)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "rerun rrd verify {}: {}",
            path.display(),
            String::from_utf8_lossy(&out.stderr)
        );
    } else {
        eprintln!("note: no rerun CLI (set PLATEFALL_RERUN_CLI); checked the footer only");
    }
}

/// Asserts the CSV at `path` ends with the trailer of a run that ended with `status`, its row
/// count equal to the data rows.
pub fn assert_csv_says(path: &Path, status: &str) {
    let text = std::fs::read_to_string(path).unwrap();
    let last = text.lines().last().unwrap_or("");
    let prefix = format!("# platefall: status={status} steps=");
    assert!(last.starts_with(&prefix), "{}: {last}", path.display());
    let rows = text.lines().filter(|l| !l.starts_with('#')).count() - 1;
    let steps: usize = last[prefix.len()..]
        .split(' ')
        .next()
        .and_then(|n| n.parse().ok())
        .unwrap();
    assert_eq!(rows, steps, "{}", path.display());
}

/// The summary's `status`.
pub fn summary_status(path: &Path) -> String {
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["status"].as_str().unwrap_or("").to_string()
}

/// Every output at a final name in `dir` is complete and says how the run ended (`status`).
pub fn assert_final_outputs_complete(dir: &Path, status: &str) {
    let (rrd, csv, json) = (dir.join("a.rrd"), dir.join("a.csv"), dir.join("a.json"));
    if rrd.exists() {
        assert_rrd_complete(&rrd);
    }
    if csv.exists() {
        assert_csv_says(&csv, status);
    }
    if json.exists() {
        assert_eq!(summary_status(&json), status);
    }
}

/// The case of the checkpoint fault tests: static at N = 16 to t = 4 (about 700 steps, two
/// seconds here), its CSV and summary `NAME.csv` and `NAME.json` in `dir`, no recording.
pub fn checkpoint_case(dir: &Path, name: &str) -> Vec<String> {
    let p = |ext: &str| {
        dir.join(format!("{name}.{ext}"))
            .to_string_lossy()
            .into_owned()
    };
    let mut args = strings(&["static", "--resolution", "16", "--t-end", "4"]);
    args.extend(["--csv".into(), p("csv"), "--summary".into(), p("json")]);
    args.extend(strings(&["--no-save", "--progress", "off"]));
    args
}

/// `checkpoint_case` with a checkpoint to `ckpt` every 1.5 convective times (t = 1.5, 3 and
/// the end; the CSV's rows are written out before each).
pub fn checkpointed_case(dir: &Path, name: &str, ckpt: &Path) -> Vec<String> {
    let mut args = checkpoint_case(dir, name);
    args.extend([
        "--checkpoint-every".into(),
        "1.5".into(),
        "--checkpoint".into(),
    ]);
    args.push(ckpt.to_string_lossy().into_owned());
    args
}

/// Runs `checkpoint_case` uninterrupted as `full` in `dir`.
pub fn run_full_checkpoint_case(dir: &Path) {
    let out = run(&checkpoint_case(dir, "full"), &[]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `platefall resume CKPT` with `extra` arguments, run in `dir`; its output.
pub fn resume(dir: &Path, ckpt: &Path, extra: &[&str]) -> Output {
    Command::new(PF)
        .arg("resume")
        .arg(ckpt)
        .args(["-q"].iter().chain(extra))
        .current_dir(dir)
        .output()
        .expect("platefall runs")
}

/// `NAME.csv` in `dir` is the uninterrupted run's `full.csv` byte for byte, and `NAME.json`
/// its summary but for the wall time.
pub fn assert_same_as_full(dir: &Path, name: &str) {
    let (a, b) = (
        checkpoint_common::read(dir, "full.csv"),
        checkpoint_common::read(dir, &format!("{name}.csv")),
    );
    assert!(
        a == b,
        "{name}.csv differs from full.csv ({} and {} bytes)",
        b.len(),
        a.len()
    );
    assert_eq!(
        checkpoint_common::summary(dir, "full.json"),
        checkpoint_common::summary(dir, &format!("{name}.json"))
    );
}

/// `out` is a refusal: exit 2 and one line on stderr, which contains `needle`.
pub fn assert_one_line_refusal(out: &Output, needle: &str) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "not one line: {err}");
    assert!(err.contains(needle), "expected {needle:?}: {err}");
}
