//! Faults that need root (ignored by a plain `cargo test`; `.ci/run`, which runs as root, runs
//! them with `cargo test --release --test faults_root -- --ignored`): a real full disk (a 3 MB
//! tmpfs) and an unwritable directory (a read-only mount: as root, file permissions do not stop
//! writes). Each mounts its own file system and unmounts it at the end.
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
