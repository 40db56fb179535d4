//! A bad checkpoint — truncated, corrupted, of another format, not a checkpoint — or a resume
//! whose options contradict it is refused with one line naming the problem and exit code 2,
//! never a panic, and the run's earlier outputs stay as they were.
mod checkpoint_common;

use std::path::Path;

use checkpoint_common::*;

/// A short static run stopped with a checkpoint in `dir`: `cut.ckpt`, `cut.csv`, `cut.json`.
fn stopped_run(dir: &Path) {
    let args = [
        "static",
        "--resolution",
        "16",
        "--t-end",
        "2",
        "--checkpoint-every",
        "0.25",
    ];
    let mut v: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    v.extend(outputs("cut"));
    v.extend(["--stop-after-steps".into(), "120".into()]);
    expect_code(&run(dir, &strs(&v)), 75);
}

/// Resuming `file` with `extra` options is refused with one line containing `what`, and the
/// earlier outputs are untouched.
fn assert_refused(dir: &Path, file: &str, extra: &[&str], what: &str) {
    let (csv, json) = (read(dir, "cut.csv"), read(dir, "cut.json"));
    let out = run(dir, &[&["resume", file, "-q"], extra].concat());
    expect_one_line_error(&out, what);
    assert!(
        read(dir, "cut.csv") == csv && read(dir, "cut.json") == json,
        "outputs untouched"
    );
}

/// `cut.ckpt` copied to `name` with `edit` applied to its bytes.
fn damaged(dir: &Path, name: &str, edit: impl FnOnce(&mut Vec<u8>)) {
    let mut bytes = read(dir, "cut.ckpt");
    edit(&mut bytes);
    std::fs::write(dir.join(name), bytes).unwrap();
}

#[test]
fn bad_checkpoints_are_refused_in_one_line() {
    let dir = scratch("refusals");
    stopped_run(&dir);
    damaged(&dir, "truncated.ckpt", |b| b.truncate(b.len() / 2));
    assert_refused(&dir, "truncated.ckpt", &[], "truncated");
    damaged(&dir, "flipped.ckpt", |b| {
        let k = b.len() / 3;
        b[k] ^= 0x10;
    });
    assert_refused(&dir, "flipped.ckpt", &[], "corrupted");
    damaged(&dir, "magic.ckpt", |b| b[0] = b'X');
    assert_refused(&dir, "magic.ckpt", &[], "is not a platefall checkpoint");
    damaged(&dir, "format.ckpt", |b| b[8] = 99);
    assert_refused(&dir, "format.ckpt", &[], "format version 99");
    damaged(&dir, "empty.ckpt", Vec::clear);
    assert_refused(&dir, "empty.ckpt", &[], "is not a platefall checkpoint");
    assert_refused(&dir, "missing.ckpt", &[], "cannot read it");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_resume_that_contradicts_its_checkpoint_is_refused() {
    let dir = scratch("contradicts");
    stopped_run(&dir);
    assert_refused(&dir, "cut.ckpt", &["--t-end", "0.1"], "already be over");
    assert_refused(
        &dir,
        "cut.ckpt",
        &["--checkpoint-every", "-1"],
        "--checkpoint-every",
    );
    let _ = std::fs::remove_dir_all(&dir);
}
