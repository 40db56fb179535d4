//! An ensemble member's branch from a checkpoint: `platefall resume --perturb-omega D`. A zero
//! perturbation is the plain resume byte for byte; a small one changes θ̇ from the branch on by
//! about D and leaves the rows before the branch as they were; a branch writes only the outputs
//! it names. A perturbation that is not a number, one from a checkpoint before the plate's
//! release, one of a static run and one that would write over the checkpoint it branches from
//! are refused with one line and exit code 2.
mod checkpoint_common;

use std::path::Path;

use checkpoint_common::*;

/// The card's free fall at N = 16, released at t = 1, to t = 3.
const FREE: &[&str] = &[
    "free",
    "--resolution",
    "16",
    "--develop",
    "1",
    "--t-end",
    "3",
];

/// The free fall stopped after `steps` steps (after the release) as `cut`, its checkpoint
/// copied to `branch.ckpt` (every resume below starts from that copy).
fn stopped(dir: &Path, steps: u64) {
    let mut args: Vec<String> = FREE.iter().map(|s| s.to_string()).collect();
    args.extend(outputs("cut"));
    args.extend(["--checkpoint-every", "0.5", "--stop-after-steps"].map(String::from));
    args.push(steps.to_string());
    expect_code(&run(dir, &strs(&args)), 75);
    std::fs::copy(dir.join("cut.ckpt"), dir.join("branch.ckpt")).unwrap();
}

/// `resume branch.ckpt` with `extra` options, writing `name.csv` from `cut.csv`'s rows.
fn branch(dir: &Path, name: &str, extra: &[&str]) -> std::process::Output {
    let (csv, ckpt) = (format!("{name}.csv"), format!("{name}.ckpt"));
    let (json, from) = (format!("{name}.json"), "cut.csv".to_string());
    let mut args = vec!["resume", "branch.ckpt", "-q", "--no-save", "--csv", &csv];
    args.extend([
        "--csv-from",
        &from,
        "--summary",
        &json,
        "--checkpoint",
        &ckpt,
    ]);
    args.extend(extra);
    run(dir, &args)
}

/// The (t, θ̇) columns of a CSV's rows.
fn thetadot(dir: &Path, name: &str) -> Vec<(f64, f64)> {
    let text = String::from_utf8(read(dir, name)).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let w = header.iter().position(|h| *h == "thetadot").unwrap();
    lines
        .map(|l| {
            let f: Vec<f64> = l
                .split(',')
                .map(|v| v.parse().unwrap_or(f64::NAN))
                .collect();
            (f[0], f[w])
        })
        .collect()
}

#[test]
fn a_branch_is_the_resume_plus_its_perturbation() {
    let dir = scratch("branch");
    stopped(&dir, 400);
    expect_code(&branch(&dir, "plain", &[]), 0);
    expect_code(&branch(&dir, "zero", &["--perturb-omega", "0"]), 0);
    assert!(
        read(&dir, "plain.csv") == read(&dir, "zero.csv"),
        "zero: the plain resume"
    );
    expect_code(&branch(&dir, "up", &["--perturb-omega", "1e-3"]), 0);
    let (plain, up) = (thetadot(&dir, "plain.csv"), thetadot(&dir, "up.csv"));
    assert_eq!(plain.len(), up.len());
    // Rows up to the branch (400 steps) are the same; the first row after it differs by about
    // D (the flow reacts within the step: 0.1 D to 2 D), and the two runs stay apart.
    let k = plain.iter().zip(&up).position(|(a, b)| a != b).unwrap();
    assert!((400..=402).contains(&k), "first difference at row {k}");
    let d = up[k].1 - plain[k].1;
    assert!(d > 1e-4 && d < 2e-3, "θ̇ after the branch differs by {d}");
    assert!(plain.last() != up.last());
    // A branch that names no CSV or summary writes none: the stopped run's stay as they were.
    let (csv, json) = (read(&dir, "cut.csv"), read(&dir, "cut.json"));
    let args = [
        "resume",
        "branch.ckpt",
        "-q",
        "--no-save",
        "--perturb-omega",
        "1e-3",
    ];
    expect_code(
        &run(&dir, &[&args[..], &["--checkpoint", "alone.ckpt"]].concat()),
        0,
    );
    assert!(read(&dir, "cut.csv") == csv && read(&dir, "cut.json") == json);
    assert!(dir.join("alone.ckpt").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_branches_are_refused_in_one_line() {
    let dir = scratch("branch-refusals");
    stopped(&dir, 400);
    for (extra, what) in [
        (&["--perturb-omega", "NaN"][..], "--perturb-omega NaN"),
        (&["--perturb-omega", "inf"][..], "--perturb-omega inf"),
    ] {
        let out = branch(&dir, "bad", extra);
        let err = expect_one_line_error(&out, what);
        assert!(err.contains("accepted a finite number"), "{err}");
    }
    assert!(!dir.join("bad.csv").exists());
    // Without --checkpoint the branch would write over the checkpoint it branches from.
    let before = read(&dir, "branch.ckpt");
    let args = [
        "resume",
        "branch.ckpt",
        "-q",
        "--no-save",
        "--perturb-omega",
        "1e-3",
    ];
    let out = run(&dir, &args);
    expect_one_line_error(&out, "give it its own --checkpoint");
    assert!(read(&dir, "branch.ckpt") == before);
    // 20 steps (t = 0.2) is before the release at t = 1: the hold would undo the perturbation.
    stopped(&dir, 20);
    let out = branch(&dir, "held", &["--perturb-omega", "1e-3"]);
    expect_one_line_error(&out, "before the plate's release");
    assert!(!dir.join("held.csv").exists());
    // A static plate moves as prescribed: it has no θ̇ of its own.
    let args = [
        "static",
        "--resolution",
        "16",
        "--t-end",
        "0.2",
        "--no-save",
    ];
    expect_code(
        &run(
            &dir,
            &[&args[..], &["--checkpoint", "branch.ckpt"]].concat(),
        ),
        0,
    );
    let out = branch(
        &dir,
        "static",
        &["--perturb-omega", "1e-3", "--t-end", "0.4"],
    );
    expect_one_line_error(&out, "moves as prescribed");
    let _ = std::fs::remove_dir_all(&dir);
}
