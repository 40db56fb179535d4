//! Shared helpers of the checkpoint tests: run the binary in a scratch directory, run a case
//! uninterrupted and stopped-and-resumed, and compare what they wrote.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub const PF: &str = env!("CARGO_BIN_EXE_platefall");

/// A small 3-D flight: the card's section on a span of one chord at N = 6 in a box of 2 chords,
/// released at t = 0.1 (its end and outputs are the test's).
pub const FLIGHT: [&str; 11] = [
    "free",
    "--span",
    "1",
    "--resolution",
    "6",
    "--extent",
    "2",
    "--develop",
    "0.1",
    "--progress",
    "off",
];

/// A fresh scratch directory for one test.
pub fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("platefall-ckpt-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs platefall with `args` in `dir`.
pub fn run(dir: &Path, args: &[&str]) -> Output {
    Command::new(PF)
        .args(args)
        .current_dir(dir)
        .output()
        .expect("platefall runs")
}

/// The exit code, with stderr in the message when it is not `want`.
pub fn expect_code(out: &Output, want: i32) {
    assert_eq!(
        out.status.code(),
        Some(want),
        "stderr:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The run was refused as bad input: exit code 2 and one non-empty line on stderr, an
/// `error: ` naming `what`. Returns that stderr.
pub fn expect_one_line_error(out: &Output, what: &str) -> String {
    expect_code(out, 2);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    let lines: Vec<&str> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "one line: {err}");
    assert!(
        lines[0].starts_with("error: ") && lines[0].contains(what),
        "{err}"
    );
    err
}

/// The case's outputs under `name` in `dir`: --csv NAME.csv --summary NAME.json --no-save -q.
pub fn outputs(name: &str) -> Vec<String> {
    [
        "--csv",
        &format!("{name}.csv"),
        "--summary",
        &format!("{name}.json"),
    ]
    .iter()
    .map(|s| s.to_string())
    .chain(["--no-save".into(), "-q".into()])
    .collect()
}

/// `case` (a case's arguments) run uninterrupted as `full` in `dir`.
pub fn run_full(dir: &Path, case: &[&str]) {
    let args: Vec<String> = case
        .iter()
        .map(|s| s.to_string())
        .chain(outputs("full"))
        .collect();
    expect_code(&run(dir, &strs(&args)), 0);
}

/// `&str`s of owned arguments.
pub fn strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

/// `case` run as `cut` with checkpoints every `every`, stopped after each of `stops` steps (the
/// test hook, as SIGTERM would) and resumed each time with `--threads` from `threads` in turn,
/// to its end.
pub fn run_stopped(dir: &Path, case: &[&str], every: &str, stops: &[u64], threads: &[&str]) {
    let mut args: Vec<String> = case.iter().map(|s| s.to_string()).collect();
    args.extend(outputs("cut"));
    args.extend(["--checkpoint-every".into(), every.into()]);
    let first = [String::from("--stop-after-steps"), stops[0].to_string()];
    expect_code(&run(dir, &strs(&[args, first.to_vec()].concat())), 75);
    for (k, stop) in stops[1..].iter().map(Some).chain([None]).enumerate() {
        let t = threads[k % threads.len()];
        let mut r = vec![
            "resume".to_string(),
            "cut.ckpt".into(),
            "--threads".into(),
            t.into(),
        ];
        r.push("-q".into());
        if let Some(n) = stop {
            r.extend(["--stop-after-steps".into(), n.to_string()]);
        }
        expect_code(&run(dir, &strs(&r)), if stop.is_some() { 75 } else { 0 });
    }
}

/// The uninterrupted and the resumed run wrote the same CSV, byte for byte, and the same
/// summary but for the wall time and the arguments.
pub fn assert_same_outputs(dir: &Path) {
    let (a, b) = (read(dir, "full.csv"), read(dir, "cut.csv"));
    assert!(
        a == b,
        "the CSVs differ ({} and {} bytes)",
        a.len(),
        b.len()
    );
    assert_eq!(summary(dir, "full.json"), summary(dir, "cut.json"));
}

/// A file's bytes.
pub fn read(dir: &Path, name: &str) -> Vec<u8> {
    std::fs::read(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// A summary without its wall time and the arguments that started it (a resumed run's are
/// `resume …`).
pub fn summary(dir: &Path, name: &str) -> serde_json::Value {
    let mut v: serde_json::Value = serde_json::from_slice(&read(dir, name)).unwrap();
    let obj = v.as_object_mut().unwrap();
    obj.remove("wall_seconds");
    assert!(obj.remove("args").is_some(), "{name} records no arguments");
    v
}
