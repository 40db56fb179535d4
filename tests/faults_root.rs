//! Faults that need root (ignored by a plain `cargo test`; `.ci/run`, which runs as root, runs
//! them with `cargo test --release --test faults_root -- --ignored`): a real full disk (a 3 MB
//! tmpfs; and one that fills while a checkpoint is written) and an unwritable directory (a read-only mount: as root, file permissions do not stop
//! writes). Each mounts its own file system and unmounts it at the end.
mod checkpoint_common;
mod faults_common;
mod record_common;

use std::path::{Path, PathBuf};
use std::process::Command;

use faults_common::*;

/// A tmpfs mounted at a fresh directory; unmounted on drop.
struct Mount(PathBuf);

impl Mount {
    fn tmpfs(name: &str, options: &str) -> Mount {
        let dir = scratch(name).join("mnt");
        std::fs::create_dir_all(&dir).unwrap();
        let ok = Command::new("mount")
            .args(["-t", "tmpfs", "-o", options, "tmpfs"])
            .arg(&dir)
            .status()
            .is_ok_and(|s| s.success());
        assert!(
            ok,
            "mount -t tmpfs -o {options} failed: these tests need root"
        );
        Mount(dir)
    }

    fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for Mount {
    fn drop(&mut self) {
        let _ = Command::new("umount").arg(&self.0).status();
        if let Some(parent) = self.0.parent() {
            let _ = std::fs::remove_dir_all(parent);
        }
    }
}

#[test]
#[ignore = "needs root (mounts a 3 MB tmpfs); run by .ci/run"]
fn a_real_full_disk_mid_run_exits_4_and_leaves_nothing_incomplete() {
    let mnt = Mount::tmpfs("tmpfs-full", "size=3m");
    assert_disk_full_run(mnt.path(), &[], "No space left on device");
}

#[test]
#[ignore = "needs root (mounts a read-only tmpfs); run by .ci/run"]
fn an_unwritable_directory_is_refused_before_the_run() {
    let mnt = Mount::tmpfs("tmpfs-ro", "ro,size=1m");
    let out = run(&with_outputs(static_args("1"), mnt.path()), &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("not writable") && err.contains("Read-only"),
        "{err}"
    );
    assert_eq!(std::fs::read_dir(mnt.path()).unwrap().count(), 0);
}

#[test]
#[ignore = "needs root (mounts a tmpfs sized for one checkpoint); run by .ci/run"]
fn a_full_disk_while_writing_a_checkpoint_keeps_the_previous_one() {
    let dir = scratch("ckpt-full");
    run_full_checkpoint_case(&dir);
    // The size of the first checkpoint (t = 1.5), from a run that ends there.
    let probe = dir.join("probe.ckpt");
    let mut args = checkpointed_case(&dir, "probe", &probe);
    let end = args.iter().position(|a| a == "--t-end").unwrap() + 1;
    args[end] = "1.5".into();
    assert_eq!(run(&args, &[]).status.code(), Some(0));
    let first = std::fs::metadata(&probe).unwrap().len();
    // Room for the first checkpoint and half of it again: the second one (t = 3, no smaller)
    // does not fit beside it.
    let size = (first * 3 / 2).div_ceil(4096) * 4096;
    let mnt = Mount::tmpfs("tmpfs-ckpt", &format!("size={size}"));
    let ckpt = mnt.path().join("run.ckpt");
    let out = run(&checkpointed_case(&dir, "cut", &ckpt), &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(4), "{err}");
    let errors = error_lines(&err);
    assert_eq!(errors.len(), 1, "{err}");
    assert!(
        errors[0].contains("--checkpoint") && errors[0].contains("No space left on device"),
        "{err}"
    );
    // The first checkpoint stays at its final name, nothing else on the disk; the CSV and the
    // summary (elsewhere) say the run stopped for it.
    let names: Vec<_> = std::fs::read_dir(mnt.path())
        .unwrap()
        .flatten()
        .map(|e| e.file_name())
        .collect();
    assert_eq!(names, ["run.ckpt"], "left on the full disk: {names:?}");
    assert_csv_says(&dir.join("cut.csv"), "output_failed");
    assert_eq!(summary_status(&dir.join("cut.json")), "output_failed");
    // It resumes (checkpointing elsewhere) to the uninterrupted run's CSV and summary.
    let out = resume(&dir, &ckpt, &["--checkpoint", "again.ckpt"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_same_as_full(&dir, "cut");
}
