//! A run that may be continued by `platefall resume` (docs/user-guide.md "Long runs"): the
//! recording id its recording and the continuation share, and the continuation's file name.
use std::path::{Path, PathBuf};

/// A recording id of its own for a run that may be continued (the continuation takes it).
pub(super) fn new_recording_id() -> String {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos())
        .unwrap_or(0);
    format!("platefall-{}-{nanos}", std::process::id())
}

/// The continuation recording beside `rrd`: `NAME-from-STEP.rrd`.
pub(super) fn continuation(rrd: &Path, steps: u64) -> PathBuf {
    let stem = rrd.file_stem().map(|s| s.to_string_lossy().into_owned());
    let stem = stem.unwrap_or_else(|| "run".into());
    let base = stem.split("-from-").next().unwrap_or(&stem).to_string();
    rrd.with_file_name(format!("{base}-from-{steps}.rrd"))
}
