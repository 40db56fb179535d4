//! The recording of a resumed run: a continuation `.rrd` beside the first, complete, with the
//! same recording id (the viewer opens both as one run) and the steps after the checkpoint.
mod checkpoint_common;
mod record_common;

use checkpoint_common::*;

#[test]
fn a_resumed_run_records_a_continuation_with_the_same_recording_id() {
    let dir = scratch("recording");
    let case = [
        "static",
        "--resolution",
        "16",
        "--t-end",
        "1.5",
        "--save",
        "a.rrd",
        "-q",
    ];
    let stop = ["--checkpoint-every", "0.5", "--stop-after-steps", "100"];
    expect_code(&run(&dir, &[&case[..], &stop].concat()), 75);
    expect_code(&run(&dir, &["resume", "a.ckpt", "-q"]), 0);
    assert_continues(&dir, ["a.rrd", "a-from-100.rrd"], "/solver/dt", 100);
}

#[test]
fn a_resumed_three_dimensional_run_records_a_continuation_with_the_same_recording_id() {
    let dir = scratch("recording3");
    let case = [&FLIGHT[..], &["--t-end", "0.3", "--save", "c.rrd"]].concat();
    let stop = ["--checkpoint-every", "0.1", "--stop-after-steps", "12"];
    expect_code(&run(&dir, &[&case[..], &stop].concat()), 75);
    expect_code(&run(&dir, &["resume", "free.ckpt", "--progress", "off"]), 0);
    assert_continues(&dir, ["c.rrd", "c-from-12.rrd"], "/coefficients/C_L", 12);
}

/// Both recordings in `dir` are complete and share one recording id; the first holds `steps`
/// samples of the per-step `series`, the continuation the later ones. Removes `dir`.
fn assert_continues(dir: &std::path::Path, [first, next]: [&str; 2], series: &str, steps: usize) {
    let first = record_common::decode(&dir.join(first));
    let next = record_common::decode(&dir.join(next));
    assert!(
        first.has_footer && next.has_footer,
        "both recordings are complete"
    );
    assert_eq!(first.recording_ids.len(), 1, "{:?}", first.recording_ids);
    assert_eq!(first.recording_ids, next.recording_ids);
    let count = |d: &record_common::Decoded| d.scalars(series).len();
    assert_eq!(count(&first), steps);
    assert!(count(&next) > 0, "the continuation holds the later steps");
    let _ = std::fs::remove_dir_all(dir);
}
