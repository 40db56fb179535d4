//! The sweep directory: where everything lives, the manifest that ties a directory to one plan,
//! and the lock that keeps two local sweeps out of one directory.
use std::fs::File;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::clock::hostname;
use super::failure::{write_output, Failure};
use super::plan::{CaseSpec, Outputs, Plan};
use platefall_core::sim::CaseKind;

/// Version of `sweep.json`.
const MANIFEST_FORMAT: u32 = 1;

/// Paths inside one sweep directory (absolute).
#[derive(Clone, Debug)]
pub(crate) struct Layout {
    pub(crate) dir: PathBuf,
}

impl Layout {
    /// The layout of `dir`, made absolute against the current directory.
    pub(crate) fn new(dir: &Path) -> Layout {
        let dir = std::path::absolute(dir).unwrap_or_else(|_| dir.to_path_buf());
        Layout { dir }
    }
    pub(crate) fn case_dir(&self, id: &str) -> PathBuf {
        self.dir.join("cases").join(id)
    }
    pub(crate) fn summary(&self, id: &str) -> PathBuf {
        self.case_dir(id).join("summary.json")
    }
    pub(crate) fn csv(&self, id: &str) -> PathBuf {
        self.case_dir(id).join("run.csv")
    }
    /// The case's checkpoint (a stopped case resumes from it on the next sweep).
    pub(crate) fn checkpoint(&self, id: &str) -> PathBuf {
        self.case_dir(id).join("run.ckpt")
    }
    pub(crate) fn recording(&self, id: &str) -> PathBuf {
        self.case_dir(id).join("run.rrd")
    }
    pub(crate) fn vtk(&self, id: &str) -> PathBuf {
        self.case_dir(id).join("vtk")
    }
    pub(crate) fn log(&self, id: &str) -> PathBuf {
        self.case_dir(id).join("log.txt")
    }
    pub(crate) fn status(&self, id: &str) -> PathBuf {
        self.case_dir(id).join("status.json")
    }
    pub(crate) fn plan(&self) -> PathBuf {
        self.dir.join("plan.toml")
    }
    pub(crate) fn manifest(&self) -> PathBuf {
        self.dir.join("sweep.json")
    }
    pub(crate) fn output(&self, name: &str) -> PathBuf {
        self.dir.join(name)
    }
    pub(crate) fn slurm_logs(&self) -> PathBuf {
        self.dir.join("slurm")
    }
}

/// `sweep.json`: the expanded cases; a directory belongs to the plan that made it.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub(crate) struct Manifest {
    pub(crate) format: u32,
    /// The plan's name (titles); not part of what makes two plans different.
    #[serde(default)]
    pub(crate) name: String,
    pub(crate) case: CaseKind,
    pub(crate) recording: bool,
    /// `[outputs] vtk` (absent in manifests written before it existed: false).
    #[serde(default)]
    pub(crate) vtk: bool,
    pub(crate) cases: Vec<CaseSpec>,
}

impl Manifest {
    pub(crate) fn of(plan: &Plan, cases: &[CaseSpec]) -> Manifest {
        Manifest {
            format: MANIFEST_FORMAT,
            name: plan.name.clone(),
            case: plan.case,
            recording: plan.outputs.recording,
            vtk: plan.outputs.vtk,
            cases: cases.to_vec(),
        }
    }

    /// The per-case outputs the plan asked for.
    pub(crate) fn outputs(&self) -> Outputs {
        Outputs {
            recording: self.recording,
            vtk: self.vtk,
        }
    }
}

/// Reads `sweep.json` (None if there is none).
pub(crate) fn read_manifest(layout: &Layout) -> Result<Option<Manifest>, Failure> {
    let path = layout.manifest();
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(Failure::input(format!("{}: {e}", path.display()))),
    };
    serde_json::from_str(&text)
        .map(Some)
        .map_err(|e| Failure::input(format!("{}: not a sweep manifest ({e})", path.display())))
}

/// Why `new` is not the plan that made `old`, if it is not.
pub(crate) fn difference(old: &Manifest, new: &Manifest) -> Option<String> {
    if old.case != new.case {
        return Some(format!("case {} there, {} here", old.case, new.case));
    }
    if old.recording != new.recording {
        return Some(format!(
            "[outputs] recording = {} there, {} here",
            old.recording, new.recording
        ));
    }
    if old.vtk != new.vtk {
        return Some(format!(
            "[outputs] vtk = {} there, {} here",
            old.vtk, new.vtk
        ));
    }
    if old.cases.len() != new.cases.len() {
        return Some(format!(
            "{} cases there, {} here",
            old.cases.len(),
            new.cases.len()
        ));
    }
    let (a, b) = old.cases.iter().zip(&new.cases).find(|(a, b)| a != b)?;
    Some(format!(
        "case {} is `{}` there, `{}` here",
        a.index,
        a.args.join(" "),
        b.args.join(" ")
    ))
}

/// Creates the directory (or checks that it was made from this plan), copies the plan into it
/// and writes the manifest and the case directories.
pub(crate) fn prepare(layout: &Layout, plan: &Plan, cases: &[CaseSpec]) -> Result<(), Failure> {
    let new = Manifest::of(plan, cases);
    if let Some(old) = read_manifest(layout)? {
        if let Some(why) = difference(&old, &new) {
            return Err(Failure::input(format!(
                "{} was made from a different plan ({why}); use another output directory or remove it",
                layout.dir.display()
            )));
        }
    }
    let mkdir = |p: &Path| {
        std::fs::create_dir_all(p)
            .map_err(|e| Failure::output(format!("cannot create {}: {e}", p.display())))
    };
    mkdir(&layout.dir)?;
    for c in cases {
        mkdir(&layout.case_dir(&c.id))?;
    }
    write_output(&layout.plan(), plan.text.as_bytes())?;
    let json = serde_json::to_string_pretty(&new).map_err(|e| Failure::output(e.to_string()))?;
    write_output(&layout.manifest(), json.as_bytes())
}

/// An exclusive lock on the directory, held while a local sweep runs (released on exit, even
/// after SIGKILL).
pub(crate) struct DirLock {
    _file: File,
}

/// Takes the lock of `layout`'s directory, or says who holds it.
pub(crate) fn lock(layout: &Layout) -> Result<DirLock, Failure> {
    let path = layout.dir.join(".lock");
    let file = std::fs::OpenOptions::new()
        .create(true)
        .truncate(false)
        .read(true)
        .write(true)
        .open(&path)
        .map_err(|e| Failure::output(format!("cannot create {}: {e}", path.display())))?;
    if !try_lock(&file)
        .map_err(|e| Failure::output(format!("cannot lock {}: {e}", path.display())))?
    {
        let holder = std::fs::read_to_string(&path).unwrap_or_default();
        return Err(Failure::input(format!(
            "{} is in use by another sweep ({}); wait for it to end or stop it",
            layout.dir.display(),
            holder.trim()
        )));
    }
    let _ = file.set_len(0);
    let _ = std::io::Write::write_all(
        &mut &file,
        format!("pid {} on {}", std::process::id(), hostname()).as_bytes(),
    );
    Ok(DirLock { _file: file })
}

/// An exclusive, non-blocking `flock`: Ok(false) if another process holds it.
#[cfg(unix)]
fn try_lock(file: &File) -> std::io::Result<bool> {
    use std::os::unix::io::AsRawFd;
    // SAFETY: flock on a descriptor we own for the duration of the call.
    if unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) } == 0 {
        return Ok(true);
    }
    let e = std::io::Error::last_os_error();
    if e.raw_os_error() == Some(libc::EWOULDBLOCK) {
        Ok(false)
    } else {
        Err(e)
    }
}

/// Elsewhere there is no lock.
#[cfg(not(unix))]
fn try_lock(_file: &File) -> std::io::Result<bool> {
    Ok(true)
}
