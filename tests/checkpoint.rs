//! Checkpoints and `platefall resume`: a run stopped (by the test hook, by SIGTERM, by SIGUSR1) and
//! resumed, any number of times, writes the CSV of the uninterrupted run byte for byte and the
//! same summary (but for the wall time); killed by SIGKILL, it resumes as well from the CSV it left
//! under its temporary name. See also `tests/checkpoint_refusals.rs`.
mod checkpoint_common;

use std::time::{Duration, Instant};

use checkpoint_common::*;

/// The card's free fall at N = 16, released at t = 1, to t = 4 (≈ 840 steps).
const FREE: &[&str] = &[
    "free",
    "--resolution",
    "16",
    "--develop",
    "1",
    "--t-end",
    "4",
];

#[test]
fn a_free_fall_stopped_three_times_resumes_exactly() {
    let dir = scratch("free");
    run_full(&dir, FREE);
    // Before the release, just after it, and late; resumed on 2, 1 and 2 threads.
    run_stopped(&dir, FREE, "0.5", &[90, 260, 700], &["1", "2"]);
    assert_same_outputs(&dir);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_static_run_resumes_exactly() {
    let dir = scratch("static");
    let case = ["static", "--resolution", "16", "--t-end", "3"];
    run_full(&dir, &case);
    run_stopped(&dir, &case, "1", &[150, 400], &["2"]);
    assert_same_outputs(&dir);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A light plate in water, described physically (c/U = 0.175 s).
const WATER: [&str; 15] = [
    "free",
    "--chord-mm",
    "16",
    "--thickness-mm",
    "0.5",
    "--plate-density",
    "2700",
    "--fluid",
    "water",
    "--theta0",
    "0.3",
    "--resolution",
    "16",
    "--t-end",
    "2",
];

#[test]
fn a_light_plate_in_water_resumes_exactly() {
    let dir = scratch("water");
    run_full(&dir, &WATER);
    run_stopped(&dir, &WATER, "0.5", &[120, 250], &["1"]);
    assert_same_outputs(&dir);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_physical_plate_is_extended_to_an_end_in_seconds() {
    let dir = scratch("water-seconds");
    let mut args: Vec<String> = WATER.iter().map(|s| s.to_string()).collect();
    args.extend(outputs("cut"));
    args.extend(["--checkpoint-every".into(), "1".into()]);
    expect_code(&run(&dir, &strs(&args)), 0);
    let s = summary(&dir, "cut.json");
    let c_over_u = s["chord_m"].as_f64().unwrap() / s["velocity_scale_m_s"].as_f64().unwrap();
    expect_code(
        &run(&dir, &["resume", "cut.ckpt", "--t-end", "0.5s", "-q"]),
        0,
    );
    let t = summary(&dir, "cut.json")["t_end"].as_f64().unwrap();
    assert!(
        (t * c_over_u - 0.5).abs() < 1e-12,
        "0.5 s is {} c/U; the run went on to {t}",
        0.5 / c_over_u
    );
    let out = run(&dir, &["resume", "cut.ckpt", "--t-end", "0.1s", "-q"]);
    expect_one_line_error(&out, "--t-end 0.1s: the checkpoint is at t = ");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Starts the free fall in `dir` as `cut` with checkpoints every 1.5 c/U (after the release)
/// after running it uninterrupted as `full`, and waits for its first checkpoint.
fn start_until_checkpoint(dir: &std::path::Path) -> std::process::Child {
    run_full(dir, FREE);
    let mut args: Vec<String> = FREE.iter().map(|s| s.to_string()).collect();
    args.extend(outputs("cut"));
    args.extend(["--checkpoint-every".into(), "1.5".into()]);
    let child = std::process::Command::new(PF)
        .args(&args)
        .current_dir(dir)
        .stderr(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while !dir.join("cut.ckpt").exists() && start.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(20));
    }
    child
}

/// Sends `signal` to `child` and waits for it.
fn signal(child: &mut std::process::Child, signal: i32) -> std::process::ExitStatus {
    // SAFETY: signalling our own child process by its id.
    unsafe { libc::kill(child.id() as libc::pid_t, signal) };
    child.wait().unwrap()
}

/// The free fall stopped by `sig` after its first periodic checkpoint, resumed to its end.
fn stop_by_signal(name: &str, sig: i32) {
    let dir = scratch(name);
    let mut child = start_until_checkpoint(&dir);
    let status = signal(&mut child, sig);
    assert_eq!(status.code(), Some(75), "{status:?}");
    let trailer = String::from_utf8(read(&dir, "cut.csv")).unwrap();
    assert!(
        trailer.contains("status=interrupted"),
        "the CSV says it stopped"
    );
    expect_code(&run(&dir, &["resume", "cut.ckpt", "-q"]), 0);
    assert_same_outputs(&dir);
    let _ = std::fs::remove_dir_all(&dir);
}

/// SIGKILL leaves the CSV under its temporary name; it holds the rows up to the last
/// checkpoint (the logger writes them out before each one), so `resume --csv-from` it goes on
/// to the uninterrupted run's outputs.
#[test]
fn a_free_fall_killed_after_a_checkpoint_resumes_with_its_partial_csv() {
    let dir = scratch("sigkill");
    let mut child = start_until_checkpoint(&dir);
    let partial = format!(".cut.csv.partial-{}", child.id());
    let status = signal(&mut child, libc::SIGKILL);
    assert_eq!(status.code(), None, "killed: {status:?}");
    assert!(!dir.join("cut.csv").exists(), "no CSV at its final name");
    let plain = run(&dir, &["resume", "cut.ckpt", "-q"]);
    expect_code(&plain, 2);
    let refusal = String::from_utf8_lossy(&plain.stderr);
    assert!(
        refusal.trim_end().ends_with(&format!(
            "add --csv-from {} (it holds them)",
            dir.join(&partial).display()
        )),
        "the refusal names the partial CSV that holds the rows: {refusal}"
    );
    let resume = ["resume", "cut.ckpt", "--csv-from", &partial, "-q"];
    expect_code(&run(&dir, &resume), 0);
    assert_same_outputs(&dir);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_free_fall_stopped_by_sigterm_resumes_exactly() {
    stop_by_signal("sigterm", libc::SIGTERM);
}

#[test]
fn a_free_fall_stopped_by_sigusr1_resumes_exactly() {
    stop_by_signal("sigusr1", libc::SIGUSR1);
}

#[test]
fn a_completed_run_is_extended_from_its_last_checkpoint() {
    let dir = scratch("extend");
    let case = ["static", "--resolution", "16", "--t-end", "1"];
    let mut args: Vec<String> = case.iter().map(|s| s.to_string()).collect();
    args.extend(outputs("cut"));
    args.extend(["--checkpoint-every".into(), "0.5".into()]);
    expect_code(&run(&dir, &strs(&args)), 0);
    let before = read(&dir, "cut.csv");
    expect_code(
        &run(&dir, &["resume", "cut.ckpt", "--t-end", "1.5", "-q"]),
        0,
    );
    let after = String::from_utf8(read(&dir, "cut.csv")).unwrap();
    let rows = |s: &str| s.lines().filter(|l| !l.starts_with('#')).count();
    let old = String::from_utf8(before).unwrap();
    assert!(rows(&after) > rows(&old), "more rows after the extension");
    let kept: Vec<&str> = old.lines().filter(|l| !l.starts_with('#')).collect();
    assert!(
        after.lines().zip(&kept).all(|(a, b)| a == *b),
        "the earlier rows kept"
    );
    let trailer = after.lines().last().unwrap();
    assert!(trailer.contains("status=completed"), "{trailer}");
    let t: f64 = after
        .lines()
        .rev()
        .nth(1)
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        (t - 1.5).abs() < 1e-9,
        "the run goes on to the new end: {t}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
