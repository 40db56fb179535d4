//! Fault injection: for each fault, the exit code of docs/user-guide.md's table, a one-line message, and
//! no file at a final name that is not complete (every .rrd there verifies, every CSV and summary
//! there says how the run ended, no temporary file is left unless the process was killed).
//!
//! A full disk is injected here (`PLATEFALL_INJECT=disk-full-after=…`, see `record/inject.rs`);
//! the same fault on a real full tmpfs and an unwritable (read-only) directory need root and are
//! in `tests/faults_root.rs`, run by `.ci/run`.
mod checkpoint_common;
mod faults_common;
mod record_common;

use std::path::{Path, PathBuf};
use std::time::Duration;

use faults_common::*;

/// A long static run writing its three outputs in a fresh `name` directory, with `env`, once it
/// has written a first part of its recording.
fn start_running(name: &str, env: &[(&str, &str)]) -> (std::path::PathBuf, std::process::Child) {
    let dir = scratch(name);
    let child = start(&with_outputs(static_args("1000"), &dir), env, &dir);
    assert!(wait_for(Duration::from_secs(60), || running(&dir)));
    (dir, child)
}

/// No output of `dir` is at its final name.
fn assert_none_at_final_names(dir: &std::path::Path) {
    for f in ["a.rrd", "a.csv", "a.json"] {
        assert!(!dir.join(f).exists(), "{f} at its final name");
    }
}

#[test]
fn a_completed_run_renames_complete_outputs_into_place() {
    let dir = scratch("completed");
    let out = run(&with_outputs(static_args("0.5"), &dir), &[]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("status completed"));
    assert_final_outputs_complete(&dir, "completed");
    for f in ["a.rrd", "a.csv", "a.json"] {
        assert!(dir.join(f).exists(), "{f}");
    }
    assert!(partial_files(&dir).is_empty(), "{:?}", partial_files(&dir));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn outputs_naming_the_same_file_are_refused_up_front() {
    let dir = scratch("same");
    let rrd = dir.join("a.rrd");
    std::fs::write(&rrd, b"precious").unwrap();
    let link = dir.join("link.json");
    std::os::unix::fs::symlink(&rrd, &link).unwrap();
    let rrd_s = rrd.to_string_lossy().into_owned();
    let dotted = dir.join("x/../a.rrd").to_string_lossy().into_owned();
    std::fs::create_dir_all(dir.join("x")).unwrap();
    let csv = dir.join("b.csv").to_string_lossy().into_owned();
    let cases: Vec<Vec<String>> = vec![
        vec![
            "--save".into(),
            rrd_s.clone(),
            "--summary".into(),
            rrd_s.clone(),
        ],
        vec!["--save".into(), rrd_s.clone(), "--summary".into(), dotted],
        vec![
            "--save".into(),
            rrd_s.clone(),
            "--summary".into(),
            link.to_string_lossy().into(),
        ],
        vec![
            "--no-save".into(),
            "--csv".into(),
            csv.clone(),
            "--summary".into(),
            csv,
        ],
    ];
    for extra in cases {
        let mut a = static_args("0.5");
        a.extend(extra.iter().cloned());
        let out = run(&a, &[]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {err}");
        assert_eq!(err.lines().count(), 1, "one line: {err}");
        assert!(err.contains("is the same file as"), "{err}");
    }
    assert_eq!(std::fs::read(&rrd).unwrap(), b"precious", "untouched");
    assert!(!dir.join("b.csv").exists());
    assert!(partial_files(&dir).is_empty());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Runs `argv` expecting a refusal: exit 2 within a few seconds (nothing allocated), one line
/// containing every one of `needles`, nothing written in the scratch directory.
fn assert_refused(name: &str, argv: &[&str], needles: &[&str]) {
    let dir = scratch(name);
    let a = with_outputs(strings(argv), &dir);
    let t0 = std::time::Instant::now();
    let out = run(&a, &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{argv:?}: {err}");
    assert!(
        t0.elapsed() < Duration::from_secs(10),
        "{argv:?} took {:?}",
        t0.elapsed()
    );
    let first = err.lines().next().unwrap_or("");
    assert!(first.starts_with("error: "), "{err}");
    for n in needles {
        assert!(first.contains(n), "{argv:?}: {first:?} lacks {n:?}");
    }
    assert!(!err.contains("panicked"), "{err}");
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().flatten().collect();
    assert!(left.is_empty(), "{argv:?} wrote {left:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_huge_grid_is_refused_before_allocating() {
    assert_refused(
        "huge",
        &[
            "static",
            "--resolution",
            "1024",
            "--growth",
            "1.001",
            "--extent",
            "200",
        ],
        &[
            "--resolution 1024",
            "124738384 cells",
            "nonzeros",
            "reduce --resolution",
        ],
    );
    // Within the index range but above the memory limit.
    assert_refused(
        "big",
        &[
            "static",
            "--resolution",
            "64",
            "--growth",
            "1.01",
            "--extent",
            "100",
            "--max-memory",
            "200MB",
        ],
        &["760264", "--max-memory 200MB", "raise --max-memory"],
    );
}

#[test]
fn a_tiny_reynolds_number_is_refused_with_the_step_estimate() {
    assert_refused(
        "tinyre",
        &["static", "--re", "1e-300"],
        &["--re 1e-300", "viscous limit", "--max-steps", "raise --re"],
    );
    assert_refused(
        "tinydt",
        &["static", "--dt-max", "1e-12"],
        &["--dt-max 1e-12", "8.000e13 steps"],
    );
}

#[test]
fn options_that_cannot_work_together_are_refused() {
    assert_refused(
        "develop",
        &["free", "--develop", "10", "--t-end", "5"],
        &["--develop 10", "t_end = 5", "never released"],
    );
    assert_refused(
        "spinup",
        &["forced", "--spinup", "5", "--t-end", "3"],
        &["--spinup 5", "t_end = 3"],
    );
    for flag in [
        ["--extent", "20"],
        ["--growth", "1.1"],
        ["--thickness", "0.1"],
    ] {
        let mut argv = vec!["static", "--seed-grid"];
        argv.extend(flag);
        assert_refused("seed", &argv, &["--seed-grid", flag[0]]);
    }
}

#[test]
fn an_unwritable_directory_is_refused_before_the_run() {
    if is_root() {
        eprintln!("skipped: as root permissions do not stop writes (tests/faults_root.rs mounts a read-only directory instead)");
        return;
    }
    use std::os::unix::fs::PermissionsExt as _;
    let dir = scratch("readonly");
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o555)).unwrap();
    let out = run(&with_outputs(static_args("0.5"), &dir), &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("not writable"), "{err}");
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o755)).unwrap();
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    let _ = std::fs::remove_dir_all(&dir);
}

fn is_root() -> bool {
    std::process::Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
}

#[test]
fn a_full_disk_mid_run_stops_the_run_with_exit_4_and_leaves_nothing_incomplete() {
    let dir = scratch("diskfull");
    let env = [("PLATEFALL_INJECT", "disk-full-after=1500000")];
    assert_disk_full_run(&dir, &env, "no space left on device");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn removing_the_output_directory_mid_run_stops_the_run_with_exit_4() {
    let dir = scratch("removed");
    let out_dir = dir.join("out");
    std::fs::create_dir_all(&out_dir).unwrap();
    let mut child = start(&with_outputs(static_args("1000"), &out_dir), &[], &dir);
    assert!(wait_for(Duration::from_secs(60), || running(&out_dir)));
    std::fs::remove_dir_all(&out_dir).unwrap();
    let (code, took) = exit_code(&mut child, Duration::from_secs(60));
    let err = std::fs::read_to_string(dir.join("stderr")).unwrap();
    assert_eq!(code, 4, "{err}");
    assert!(took < Duration::from_secs(10), "noticed after {took:?}");
    let errors = error_lines(&err);
    assert_eq!(errors.len(), 1, "{err}");
    assert!(errors[0].contains("disappeared"), "{err}");
    assert!(!out_dir.exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn ctrl_c_finalises_every_output_and_exits_130() {
    let (dir, mut child) = start_running("sigint", &[]);
    signal(&child, "INT");
    let (code, _) = exit_code(&mut child, Duration::from_secs(60));
    let err = std::fs::read_to_string(dir.join("stderr")).unwrap();
    assert_eq!(code, 130, "{err}");
    assert_eq!(error_lines(&err).len(), 1, "{err}");
    assert!(error_lines(&err)[0].starts_with("interrupted: "), "{err}");
    for f in ["a.rrd", "a.csv", "a.json"] {
        assert!(dir.join(f).exists(), "{f}");
    }
    assert_final_outputs_complete(&dir, "interrupted");
    assert!(partial_files(&dir).is_empty(), "{:?}", partial_files(&dir));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_second_ctrl_c_quits_a_hanging_finalisation_at_once() {
    // Every commit hangs for a minute, as on a dead disk.
    let (dir, mut child) = start_running("sigint2", &[("PLATEFALL_INJECT", "commit-delay=60")]);
    signal(&child, "INT");
    let stderr = dir.join("stderr");
    assert!(wait_for(Duration::from_secs(30), || {
        std::fs::read_to_string(&stderr).is_ok_and(|s| s.contains("platefall: interrupted:"))
    }));
    std::thread::sleep(Duration::from_millis(300));
    signal(&child, "INT");
    let (code, took) = exit_code(&mut child, Duration::from_secs(30));
    let err = std::fs::read_to_string(&stderr).unwrap();
    assert_eq!(code, 130, "{err}");
    assert!(took < Duration::from_secs(5), "quit after {took:?}");
    assert!(err.contains("second Ctrl-C"), "{err}");
    assert_none_at_final_names(&dir);
    assert!(
        !partial_files(&dir).is_empty(),
        "the partial files stay, named so"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn sigkill_leaves_only_partial_files() {
    let (dir, mut child) = start_running("sigkill", &[]);
    signal(&child, "KILL");
    let (code, _) = exit_code(&mut child, Duration::from_secs(30));
    assert_eq!(code, -1, "killed by a signal");
    assert_none_at_final_names(&dir);
    let partial = partial_files(&dir);
    assert!(
        partial.iter().any(|n| n.starts_with(".a.rrd.partial-")),
        "{partial:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_diverging_run_exits_3_with_complete_outputs_that_say_so() {
    let dir = scratch("diverged");
    let forced = [
        "forced",
        "--rate",
        "2",
        "--resolution",
        "16",
        "--t-end",
        "5",
        "--cfl",
        "1.0",
        // The implicit far field is stable at this Courant number; the explicit one is not
        // (around the dissertation's plate, one cell of 1/16 thick).
        "--far-field",
        "explicit",
        "--thickness",
        "0.0625",
    ];
    let a = with_outputs(strings(&forced), &dir);
    let out = run(&a, &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert_eq!(error_lines(&err).len(), 1, "{err}");
    assert!(error_lines(&err)[0].contains("diverged"), "{err}");
    assert_final_outputs_complete(&dir, "diverged");
    assert!(dir.join("a.rrd").exists() && dir.join("a.csv").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_summary_that_cannot_be_written_after_the_run_leaves_the_recording_completed() {
    let dir = scratch("summaryfail");
    let gone = dir.join("gone");
    std::fs::create_dir_all(&gone).unwrap();
    let mut a = static_args("10");
    let p = |f: &str| dir.join(f).to_string_lossy().into_owned();
    a.extend(["--save".into(), p("a.rrd"), "--csv".into(), p("a.csv")]);
    a.extend(["--summary".into(), p("gone/a.json")]);
    let mut child = start(&a, &[], &dir);
    assert!(wait_for(Duration::from_secs(60), || running(&dir)));
    std::fs::remove_dir_all(&gone).unwrap();
    let (code, _) = exit_code(&mut child, Duration::from_secs(120));
    let err = std::fs::read_to_string(dir.join("stderr")).unwrap();
    assert_eq!(code, 4, "{err}");
    let errors = error_lines(&err);
    assert_eq!(errors.len(), 1, "{err}");
    assert!(errors[0].contains("--summary"), "{err}");
    assert_final_outputs_complete(&dir, "completed");
    let status = decode(&dir.join("a.rrd")).texts("/run/status");
    assert_eq!(
        status.last().map(String::as_str),
        Some("completed"),
        "{status:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn help_lists_the_exit_codes() {
    for cmd in [vec!["--help"], vec!["free", "--help"]] {
        let out = std::process::Command::new(PF).args(&cmd).output().unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        for code in ["Exit codes:", "  2 ", "  3 ", "  4 ", "  130 "] {
            assert!(text.contains(code), "{cmd:?} lacks {code:?}");
        }
    }
}

/// The data rows of a CSV's text: whole lines (ending in a line break) that are not the header
/// or a comment.
fn whole_rows(text: &str) -> Vec<&str> {
    let whole = text.rfind('\n').map_or("", |end| &text[..=end]);
    whole
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with('#'))
        .collect()
}

/// Runs `checkpointed_case` as `cut` in `dir` with every checkpoint write pausing 5 s half-way
/// through its temporary file, and SIGKILLs it during the second one (t = 3), once the first
/// (t = 1.5) is in place at `ckpt`. Returns the first checkpoint's bytes and the temporary file.
fn kill_mid_checkpoint(dir: &Path, ckpt: &Path) -> (Vec<u8>, PathBuf) {
    let env = [("PLATEFALL_INJECT", "checkpoint-delay=5")];
    let mut child = start(&checkpointed_case(dir, "cut", ckpt), &env, dir);
    let temp = dir.join(format!(".run.ckpt.partial-{}", child.id()));
    let placed = wait_for(Duration::from_secs(60), || ckpt.exists());
    assert!(placed, "no first checkpoint");
    let first = std::fs::read(ckpt).unwrap();
    // Magic and version, then at least half the payload (the second one is no smaller).
    let half = 12 + (first.len() as u64 - 24) / 2;
    let mid_write = || std::fs::metadata(&temp).is_ok_and(|m| m.len() >= half);
    assert!(
        wait_for(Duration::from_secs(60), mid_write),
        "no second checkpoint being written"
    );
    signal(&child, "KILL");
    let (code, _) = exit_code(&mut child, Duration::from_secs(30));
    assert_eq!(code, -1, "killed by a signal");
    (first, temp)
}

/// The first `rows` data rows of the CSV `text` and half of the next one.
fn cut_after_row(text: &str, rows: usize) -> &str {
    let end_of_row = |n: usize| text.match_indices('\n').nth(n).unwrap().0 + 1;
    &text[..end_of_row(rows) + (end_of_row(rows + 1) - end_of_row(rows)) / 2]
}

#[test]
fn sigkill_while_writing_a_checkpoint_leaves_the_previous_one_resumable() {
    let dir = scratch("ckpt-kill");
    run_full_checkpoint_case(&dir);
    let ckpt = dir.join("run.ckpt");
    let (first, temp) = kill_mid_checkpoint(&dir, &ckpt);

    // The previous checkpoint is untouched; the temporary one is half a file, refused as such.
    assert!(
        std::fs::read(&ckpt).unwrap() == first,
        "the checkpoint at its final name changed"
    );
    let left = std::fs::metadata(&temp).unwrap().len();
    assert!(
        left < first.len() as u64,
        "{left} bytes left of a ≥ {} byte file",
        first.len()
    );
    assert_one_line_refusal(&resume(&dir, &temp, &[]), "truncated");

    // The run's CSV never reached its final name: resume refuses in one line and writes nothing.
    let out = resume(&dir, &ckpt, &["--checkpoint", "again.ckpt"]);
    assert_one_line_refusal(&out, "--csv: cannot resume it: cannot read the earlier CSV");
    assert!(!dir.join("cut.csv").exists() && !dir.join("again.ckpt").exists());

    // The killed run's own CSV (its temporary file: no trailer, the last row often cut short)
    // holds the rows up to the checkpoint being written, since the logger writes them out
    // before each checkpoint: `resume --csv-from` it goes on. A CSV cut short of the
    // checkpoint's step is refused in one line saying how many whole rows it has and the step
    // it needs.
    let partial = partial_files(&dir)
        .into_iter()
        .find(|n| n.starts_with(".cut.csv.partial-"))
        .expect("the killed run's temporary CSV");
    let cut = std::fs::read_to_string(dir.join(&partial)).unwrap();
    assert!(
        !cut.contains("# platefall:"),
        "a killed run's CSV has no trailer"
    );
    std::fs::write(dir.join("short.csv"), cut_after_row(&cut, 10)).unwrap();
    let again = ["--checkpoint", "again.ckpt", "--csv-from"];
    let out = resume(&dir, &ckpt, &[&again[..], &["short.csv"]].concat());
    let says = "holds 10 whole rows, the checkpoint ";
    assert_one_line_refusal(&out, says);
    let err = String::from_utf8_lossy(&out.stderr);
    let k: usize = err.split(says).nth(1).unwrap().trim().parse().unwrap();
    let whole = whole_rows(&cut).len();
    assert!(
        whole >= k,
        "the killed run's CSV holds {whole} whole rows, the checkpoint {k}"
    );
    eprintln!("note: the killed run's CSV holds {whole} whole rows; the checkpoint, {k}");
    // Resumed into the same checkpoint name, the run's first checkpoint removes the killed
    // write's temporary file (its process is gone).
    let out = resume(&dir, &ckpt, &["--csv-from", partial.as_str()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_same_as_full(&dir, "cut");
    assert!(!temp.exists(), "{} stayed", temp.display());
    let _ = std::fs::remove_dir_all(&dir);
}
