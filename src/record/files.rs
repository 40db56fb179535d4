//! Checks on output paths, made before a run starts so that a bad path costs nothing.
use std::path::{Path, PathBuf};

/// Why `path` cannot take an output: its directory does not exist or is not writable, or the path
/// is a directory or an existing file that cannot be replaced. With `create_dir`, the parent
/// directory is created first (for default paths such as `recordings/`).
pub fn check_writable(path: &Path, create_dir: bool) -> Result<(), String> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if create_dir {
        std::fs::create_dir_all(&dir)
            .map_err(|e| format!("cannot create directory {}: {e}", dir.display()))?;
    }
    match std::fs::metadata(&dir) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => return Err(format!("{} is not a directory", dir.display())),
        Err(_) => {
            return Err(format!(
                "directory {} does not exist (create it first)",
                dir.display()
            ))
        }
    }
    if path.is_dir() {
        return Err("is a directory".into());
    }
    probe_directory(&dir)?;
    if path.exists() {
        std::fs::OpenOptions::new()
            .append(true)
            .open(path)
            .map_err(|e| format!("exists and cannot be overwritten ({e})"))?;
    }
    Ok(())
}

/// Creates and removes a uniquely named file in `dir`.
fn probe_directory(dir: &Path) -> Result<(), String> {
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
        .map_err(|e| format!("directory {} is not writable ({e})", dir.display()))?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}
