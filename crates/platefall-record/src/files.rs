//! Checks on output paths, made before a run starts so that a bad path costs nothing: each output
//! can be written ([`check_writable`]), and no two outputs are the same file ([`check_outputs`]).
use std::path::{Path, PathBuf};

/// Why a path cannot take an output (the message says it in one line).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PathRefusal {
    /// The directory could not be created (default paths only).
    #[error("cannot create directory {}: {reason}", .dir.display())]
    CannotCreateDirectory {
        /// The directory.
        dir: PathBuf,
        /// The system's error.
        reason: String,
    },
    /// The parent exists and is not a directory.
    #[error("{} is not a directory", .0.display())]
    NotADirectory(PathBuf),
    /// The directory does not exist.
    #[error("directory {} does not exist (create it first)", .0.display())]
    NoDirectory(PathBuf),
    /// The path names a directory.
    #[error("is a directory")]
    IsADirectory,
    /// The path names something other than a directory where a directory is wanted.
    #[error("exists and is not a directory")]
    ExistsNotADirectory,
    /// The path names something that is not a regular file (a FIFO, a device).
    #[error("exists and is not a regular file")]
    NotARegularFile,
    /// No file can be created in the directory.
    #[error("directory {} is not writable ({reason})", .dir.display())]
    NotWritable {
        /// The directory.
        dir: PathBuf,
        /// The system's error.
        reason: String,
    },
    /// The file exists and cannot be replaced.
    #[error("exists and cannot be overwritten ({0})")]
    CannotOverwrite(String),
    /// Another output of the run names the same file.
    #[error("is the same file as {flag} {}; each output needs its own file", .path.display())]
    SameFileAs {
        /// The other output's option.
        flag: &'static str,
        /// The other output's path, as given.
        path: PathBuf,
    },
}

/// Why `path` cannot take an output: its directory does not exist or is not writable, or the path
/// is a directory or an existing file that cannot be replaced. With `create_dir`, the parent
/// directory is created first (for default paths such as `recordings/`).
pub fn check_writable(path: &Path, create_dir: bool) -> Result<(), PathRefusal> {
    let dir = directory_of(path);
    if create_dir {
        std::fs::create_dir_all(&dir).map_err(|e| PathRefusal::CannotCreateDirectory {
            dir: dir.clone(),
            reason: e.to_string(),
        })?;
    }
    match std::fs::metadata(&dir) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => return Err(PathRefusal::NotADirectory(dir)),
        Err(_) => return Err(PathRefusal::NoDirectory(dir)),
    }
    if path.is_dir() {
        return Err(PathRefusal::IsADirectory);
    }
    if path.exists() && !path.is_file() {
        return Err(PathRefusal::NotARegularFile);
    }
    probe_directory(&directory_of(&resolve_links(path)))?;
    if path.exists() {
        std::fs::OpenOptions::new()
            .append(true)
            .open(path)
            .map_err(|e| PathRefusal::CannotOverwrite(e.to_string()))?;
    }
    Ok(())
}

/// Why `dir` cannot take a directory of outputs (`--vtk`): it exists and is not a directory, or
/// no file can be created in it; or it does not exist and cannot be created in its parent
/// (which must exist: only the last component is created, when the run starts).
pub fn check_directory(dir: &Path) -> Result<(), PathRefusal> {
    match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => probe_directory(dir),
        Ok(_) => Err(PathRefusal::ExistsNotADirectory),
        Err(_) => {
            let parent = directory_of(dir);
            match std::fs::metadata(&parent) {
                Ok(m) if m.is_dir() => probe_directory(&parent),
                Ok(_) => Err(PathRefusal::NotADirectory(parent)),
                Err(_) => Err(PathRefusal::NoDirectory(parent)),
            }
        }
    }
}

/// The directory a path's file lives in ("." for a bare file name).
fn directory_of(path: &Path) -> PathBuf {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Creates and removes a uniquely named file in `dir`.
fn probe_directory(dir: &Path) -> Result<(), PathRefusal> {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos())
        .unwrap_or(0);
    let probe = dir.join(format!(
        ".platefall-write-probe-{}-{nanos}",
        std::process::id()
    ));
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
        .map_err(|e| PathRefusal::NotWritable {
            dir: dir.to_path_buf(),
            reason: e.to_string(),
        })?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}

/// The file a path really names: `.`/`..` and symbolic links resolved, in the directory and in
/// the file name itself (a link to a file that does not exist yet is followed too). An output
/// written through a symbolic link replaces the link's target, as a direct write would.
pub fn resolve_links(path: &Path) -> PathBuf {
    let mut current = path.to_path_buf();
    for _ in 0..40 {
        let dir = directory_of(&current);
        let dir = dir.canonicalize().unwrap_or(dir);
        let Some(name) = current.file_name() else {
            return current;
        };
        let full = dir.join(name);
        match std::fs::read_link(&full) {
            Ok(target) => current = dir.join(target),
            Err(_) => return full,
        }
    }
    current
}

/// One output a run writes: the option that names it, its path, and whether its directory may be
/// created (default paths only).
#[derive(Clone, Copy, Debug)]
pub struct OutputPath<'a> {
    /// The option that names it, e.g. "--csv".
    pub flag: &'static str,
    /// The path as given.
    pub path: &'a Path,
    /// Whether its directory may be created.
    pub create_dir: bool,
}

/// A refused output path: the option, the path as given, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct PathProblem {
    /// The option that names it.
    pub flag: &'static str,
    /// The path as given.
    pub path: PathBuf,
    /// Why it is refused.
    pub reason: PathRefusal,
}

/// Checks every output of a run: each must be writable ([`check_writable`]) and no two may be
/// the same file, whether named alike, through `..`, a symbolic link or a hard link.
pub fn check_outputs(outputs: &[OutputPath]) -> Result<(), PathProblem> {
    let mut seen: Vec<(&OutputPath, PathBuf)> = Vec::new();
    for out in outputs {
        let problem = |reason: PathRefusal| PathProblem {
            flag: out.flag,
            path: out.path.to_path_buf(),
            reason,
        };
        check_writable(out.path, out.create_dir).map_err(problem)?;
        let real = resolve_links(out.path);
        if let Some((other, _)) = seen
            .iter()
            .find(|(o, r)| *r == real || same_existing_file(o.path, out.path))
        {
            return Err(problem(PathRefusal::SameFileAs {
                flag: other.flag,
                path: other.path.to_path_buf(),
            }));
        }
        seen.push((out, real));
    }
    Ok(())
}

/// True if both paths exist and are one file (hard links included).
fn same_existing_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt as _;
        match (std::fs::metadata(a), std::fs::metadata(b)) {
            (Ok(x), Ok(y)) => (x.dev(), x.ino()) == (y.dev(), y.ino()),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        let _ = (a, b);
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_file_under_other_names_is_refused() {
        let d = std::env::temp_dir().join(format!("pf-files-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(d.join("sub")).unwrap();
        let a = d.join("a.rrd");
        fn out<'a>(flag: &'static str, path: &'a Path) -> OutputPath<'a> {
            OutputPath {
                flag,
                path,
                create_dir: false,
            }
        }
        let dotted = d.join("sub/../a.rrd");
        let e = check_outputs(&[out("--save", &a), out("--summary", &dotted)]).unwrap_err();
        assert_eq!(e.flag, "--summary");
        assert!(
            e.reason.to_string().contains("same file as --save"),
            "{e:?}"
        );
        #[cfg(unix)]
        {
            let link = d.join("link.json");
            std::os::unix::fs::symlink(&a, &link).unwrap();
            let e = check_outputs(&[out("--save", &a), out("--summary", &link)]).unwrap_err();
            assert_eq!(e.flag, "--summary");
        }
        let b = d.join("b.csv");
        assert!(check_outputs(&[out("--save", &a), out("--csv", &b)]).is_ok());
        let _ = std::fs::remove_dir_all(&d);
    }
}
