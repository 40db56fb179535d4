//! Every output file (recording, CSV, summary, bench JSON) is written through a [`PendingFile`]:
//! under a temporary name in its own directory (`.NAME.partial-PID`), synced, checked, and renamed
//! to its final name only when complete. A file at its final name is therefore always complete;
//! a run that ends early writes what it has and says so inside the file before the rename.
//!
//! What is left on disk after each kind of failure:
//! - a write error (disk full, I/O error), an output removed while being written, a failed sync or
//!   rename: the temporary file is removed and nothing appears at the final name
//!   ([`OutputError`] says what happened; the command exits with code 4);
//! - the process killed (SIGKILL, a second Ctrl-C, power loss): the temporary
//!   `.NAME.partial-PID` file stays, clearly partial, and the final name is untouched (a
//!   checkpoint's is removed once a later run puts a complete checkpoint at that name,
//!   [`remove_orphaned_partials`]).
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use super::files::resolve_links;
use super::inject;

/// An output could not be written: which option, which file, and why (one line).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{label} {}: {reason}", .path.display())]
pub struct OutputError {
    /// The option that names the file, e.g. "--csv".
    pub label: &'static str,
    /// The final name of the file.
    pub path: PathBuf,
    /// Why it could not be written, in one line.
    pub reason: String,
}

impl OutputError {
    /// The error of the output named by option `label` with final name `path`, for `reason`.
    pub fn new(label: &'static str, path: &Path, reason: impl Into<String>) -> Self {
        OutputError {
            label,
            path: path.to_path_buf(),
            reason: reason.into(),
        }
    }
}

/// The temporary name of an output of this process: `.NAME.partial-PID` beside its final name.
pub fn partial_path(final_path: &Path) -> PathBuf {
    partial_path_of(final_path, std::process::id())
}

/// The temporary name under which process `pid` writes (or, killed, left) an output.
pub fn partial_path_of(final_path: &Path, pid: u32) -> PathBuf {
    let name = final_path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "output".into());
    final_path.with_file_name(format!(".{name}.partial-{pid}"))
}

/// The temporary files beside the output at `final_path` (`.NAME.partial-SUFFIX`, symbolic
/// links resolved as [`PendingFile`] resolves them), each with the PID its suffix names, if it
/// names one; none when the directory cannot be read.
pub fn partials_of(final_path: &Path) -> Vec<(PathBuf, Option<u32>)> {
    let real = resolve_links(final_path);
    let Some(name) = real.file_name() else {
        return Vec::new();
    };
    let prefix = format!(".{}.partial-", name.to_string_lossy());
    let dir = real.parent().filter(|d| !d.as_os_str().is_empty());
    let Ok(entries) = std::fs::read_dir(dir.unwrap_or(Path::new("."))) else {
        return Vec::new();
    };
    entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter_map(|p| {
            let file = p.file_name()?.to_string_lossy().into_owned();
            let suffix = file.strip_prefix(&prefix)?;
            let pid = suffix.parse::<u32>().ok();
            Some((p, pid))
        })
        .collect()
}

/// Removes the temporary files that killed processes left for the output at `final_path`
/// (`.NAME.partial-PID` of a PID that no longer runs here); returns how many. Only for outputs
/// whose partial state is of no use once a newer complete file is in place (checkpoints): a
/// killed run's partial CSV is what `resume --csv-from` reads. Does nothing where running
/// processes cannot be told (no `/proc`).
pub fn remove_orphaned_partials(final_path: &Path) -> usize {
    let proc = Path::new("/proc");
    if !proc.join("self").exists() {
        return 0;
    }
    let orphaned = |pid: u32| pid != std::process::id() && !proc.join(pid.to_string()).exists();
    partials_of(final_path)
        .into_iter()
        .filter(|(_, pid)| pid.is_some_and(orphaned))
        .filter(|(p, _)| std::fs::remove_file(p).is_ok())
        .count()
}

/// The temporary file of an output is no longer where it was written.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LinkLost {
    /// It is gone (deleted, or its directory removed or renamed).
    #[error("the file being written ({}) disappeared ({reason}); was its directory removed?", .path.display())]
    Disappeared {
        /// The temporary file.
        path: PathBuf,
        /// The system's error.
        reason: String,
    },
    /// Another file is at its path.
    #[error("the file being written ({}) was replaced by another", .0.display())]
    Replaced(PathBuf),
}

/// Identifies the temporary file on disk, to notice when it is removed (or its directory is)
/// while it is being written; see [`LinkCheck::verify`].
#[derive(Clone, Debug)]
pub struct LinkCheck {
    path: PathBuf,
    #[cfg(unix)]
    id: (u64, u64),
}

impl LinkCheck {
    fn of(file: &File, path: &Path) -> io::Result<Self> {
        #[cfg(unix)]
        let id = {
            use std::os::unix::fs::MetadataExt as _;
            let m = file.metadata()?;
            (m.dev(), m.ino())
        };
        #[cfg(not(unix))]
        let _ = file;
        Ok(LinkCheck {
            path: path.to_path_buf(),
            #[cfg(unix)]
            id,
        })
    }

    /// Fails if the temporary file is no longer at its path (deleted, or its directory removed
    /// or renamed): the output could never be renamed into place.
    pub fn verify(&self) -> Result<(), LinkLost> {
        let m = std::fs::metadata(&self.path).map_err(|e| LinkLost::Disappeared {
            path: self.path.clone(),
            reason: e.to_string(),
        })?;
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt as _;
            if (m.dev(), m.ino()) != self.id {
                return Err(LinkLost::Replaced(self.path.clone()));
            }
        }
        #[cfg(not(unix))]
        let _ = m;
        Ok(())
    }
}

/// Why a pending file could not be finished (its reason in an [`OutputError`]). The system's
/// errors are part of the message, as the reason has always been one line.
#[derive(Debug, thiserror::Error)]
enum Unfinished {
    /// An earlier write failed; its reason.
    #[error("{0}")]
    Earlier(String),
    /// The file was committed before.
    #[error("already committed")]
    Committed,
    /// Flushing the buffer failed.
    #[error("write failed: {0}")]
    Flush(io::Error),
    /// Syncing the data to disk failed.
    #[error("sync failed: {0}")]
    Sync(io::Error),
    /// The file's size could not be read.
    #[error("{0}")]
    Metadata(io::Error),
    /// The file holds fewer (or more) bytes than were written.
    #[error("the file holds {size} bytes of the {written} written")]
    Size {
        /// Bytes in the file.
        size: u64,
        /// Bytes written.
        written: u64,
    },
    /// The temporary file was removed or replaced.
    #[error("{0}")]
    Link(LinkLost),
}

/// An output file being written under its temporary name; see the module docs.
///
/// `Write` calls fail after the first error (which is kept). Dropping it without
/// [`commit`](Self::commit) removes the temporary file.
#[derive(Debug)]
pub struct PendingFile {
    label: &'static str,
    /// The final name as given (for messages).
    final_path: PathBuf,
    /// The file it really names (symbolic links resolved): the rename's target.
    target_path: PathBuf,
    temp_path: PathBuf,
    out: Option<BufWriter<File>>,
    written: u64,
    error: Option<String>,
    link: LinkCheck,
}

impl PendingFile {
    /// Creates the temporary file for the output `label` (e.g. "--csv") at `final_path`.
    pub fn create(label: &'static str, final_path: &Path) -> Result<Self, OutputError> {
        let real = resolve_links(final_path);
        let temp_path = partial_path(&real);
        let fail =
            |e: io::Error| OutputError::new(label, final_path, format!("cannot create: {e}"));
        let file = File::create(&temp_path).map_err(fail)?;
        let link = LinkCheck::of(&file, &temp_path).map_err(fail)?;
        Ok(PendingFile {
            label,
            final_path: final_path.to_path_buf(),
            target_path: real,
            temp_path,
            out: Some(BufWriter::with_capacity(1 << 16, file)),
            written: 0,
            error: None,
            link,
        })
    }

    /// The final name, as given.
    pub fn final_path(&self) -> &Path {
        &self.final_path
    }

    /// The temporary name the bytes go to until the commit.
    pub fn temp_path(&self) -> &Path {
        &self.temp_path
    }

    /// A handle that checks, from any thread, that the temporary file is still there.
    pub fn link_check(&self) -> LinkCheck {
        self.link.clone()
    }

    /// The first error, if a write has failed.
    pub fn error(&self) -> Option<OutputError> {
        self.error.as_ref().map(|r| self.fail(r.clone()))
    }

    /// An error about this output.
    pub fn fail(&self, reason: impl Into<String>) -> OutputError {
        OutputError::new(self.label, &self.final_path, reason)
    }

    /// Flushes, syncs and checks the file, then renames it to its final name. Returns the final
    /// name (as given) and the size. On any failure the temporary file is removed.
    pub fn commit(mut self) -> Result<(PathBuf, u64), OutputError> {
        let result = self.finish_writing();
        if let Err(reason) = result {
            return Err(self.fail(reason.to_string()));
        }
        inject::commit_delay();
        std::fs::rename(&self.temp_path, &self.target_path)
            .map_err(|e| self.fail(format!("cannot rename the finished file into place: {e}")))?;
        self.out = None; // committed: nothing to remove on drop
        sync_directory(&self.target_path);
        Ok((self.final_path.clone(), self.written))
    }

    /// Flushes and syncs the data and checks that the file holds every byte written.
    fn finish_writing(&mut self) -> Result<(), Unfinished> {
        if let Some(e) = &self.error {
            return Err(Unfinished::Earlier(e.clone()));
        }
        let out = self.out.as_mut().ok_or(Unfinished::Committed)?;
        out.flush().map_err(Unfinished::Flush)?;
        let file = out.get_ref();
        file.sync_all().map_err(Unfinished::Sync)?;
        let size = file.metadata().map_err(Unfinished::Metadata)?.len();
        if size != self.written {
            return Err(Unfinished::Size {
                size,
                written: self.written,
            });
        }
        self.link.verify().map_err(Unfinished::Link)
    }
}

impl Write for PendingFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if let Some(e) = &self.error {
            return Err(io::Error::other(e.clone()));
        }
        let out = self
            .out
            .as_mut()
            .ok_or_else(|| io::Error::other("committed"))?;
        let result = inject::reserve(buf.len()).and_then(|()| out.write(buf));
        match result {
            Ok(n) => {
                self.written += n as u64;
                Ok(n)
            }
            Err(e) => {
                self.error = Some(format!("write failed: {e}"));
                Err(e)
            }
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        let out = self
            .out
            .as_mut()
            .ok_or_else(|| io::Error::other("committed"))?;
        out.flush().inspect_err(|e| {
            self.error.get_or_insert(format!("write failed: {e}"));
        })
    }
}

impl Drop for PendingFile {
    fn drop(&mut self) {
        if self.out.take().is_some() {
            let _ = std::fs::remove_file(&self.temp_path);
        }
    }
}

/// Makes a rename durable (best effort: not every file system can sync a directory).
fn sync_directory(path: &Path) {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if let Ok(d) = File::open(dir) {
        let _ = d.sync_all();
    }
}

/// Writes a whole small file (summary, bench JSON) atomically; returns its size.
pub fn write_atomically(
    label: &'static str,
    path: &Path,
    bytes: &[u8],
) -> Result<u64, OutputError> {
    let mut f = PendingFile::create(label, path)?;
    if let Err(e) = f.write_all(bytes) {
        return Err(f.fail(format!("write failed: {e}")));
    }
    f.commit().map(|(_, n)| n)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("pf-output-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn nothing_appears_at_the_final_name_before_the_commit() {
        let d = dir("commit");
        let target = d.join("a.csv");
        let mut f = PendingFile::create("--csv", &target).unwrap();
        f.write_all(b"x,y\n1,2\n").unwrap();
        assert!(!target.exists());
        assert!(f.temp_path().exists());
        let temp = f.temp_path().to_path_buf();
        assert_eq!(f.commit().unwrap(), (target.clone(), 8));
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "x,y\n1,2\n");
        assert!(!temp.exists());
        let _ = std::fs::remove_dir_all(&d);
    }

    #[test]
    fn an_abandoned_or_orphaned_file_leaves_nothing_at_its_final_name() {
        let d = dir("orphan");
        let target = d.join("b.json");
        let f = PendingFile::create("--summary", &target).unwrap();
        let temp = f.temp_path().to_path_buf();
        drop(f);
        assert!(!temp.exists() && !target.exists());
        let mut f = PendingFile::create("--summary", &target).unwrap();
        f.write_all(b"{}").unwrap();
        std::fs::remove_file(f.temp_path()).unwrap();
        assert!(f.link_check().verify().is_err());
        let e = f.commit().unwrap_err();
        assert!(e.to_string().starts_with("--summary "), "{e}");
        assert!(!target.exists());
        let _ = std::fs::remove_dir_all(&d);
    }

    /// Linux PIDs are below `PID_MAX_LIMIT` = 2²²: this one never runs; PID 1 always does.
    #[test]
    #[cfg(target_os = "linux")]
    fn only_the_partial_files_of_processes_gone_are_removed() {
        let d = dir("orphans");
        let target = d.join("run.ckpt");
        let dead = partial_path_of(&target, (1 << 22) + 1);
        let kept = [
            partial_path_of(&target, 1),
            partial_path(&target),
            partial_path_of(&d.join("run.csv"), (1 << 22) + 1),
            d.join(".run.ckpt.partial-x"),
        ];
        for p in kept.iter().chain([&dead]) {
            std::fs::write(p, b"half").unwrap();
        }
        assert_eq!(remove_orphaned_partials(&target), 1);
        assert!(!dead.exists());
        assert!(kept.iter().all(|p| p.exists()), "{kept:?}");
        let _ = std::fs::remove_dir_all(&d);
    }
}
