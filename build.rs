//! Names the commit the program is built from, for `platefall --version`, the summaries and the
//! recordings (`src/version.rs`): `PLATEFALL_COMMIT` is "commit " and the commit's hash, with
//! ", modified" when the work tree differs from it; from a `git archive` source archive, the hash that
//! `commit.txt` received on export; otherwise "commit unknown".
use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    let commit = from_git().or_else(from_archive);
    let text = commit.unwrap_or_else(|| "commit unknown".to_string());
    println!("cargo:rustc-env=PLATEFALL_COMMIT={text}");
    for path in watched() {
        println!("cargo:rerun-if-changed={}", path.display());
    }
}

/// Git's answer, if this is a git work tree with git installed.
fn from_git() -> Option<String> {
    let hash = git(&["rev-parse", "--short=12", "HEAD"])?;
    // Untracked files do not change what is built from the tracked ones; no optional locks: a
    // refreshed index would look like a new commit to the next build.
    let status = [
        "--no-optional-locks",
        "status",
        "--porcelain",
        "--untracked-files=no",
    ];
    let status = git(&status).unwrap_or_default();
    Some(if status.is_empty() {
        format!("commit {hash}")
    } else {
        format!("commit {hash}, modified")
    })
}

/// The hash `git archive` wrote into `commit.txt` (its `export-subst` attribute).
fn from_archive() -> Option<String> {
    let text = std::fs::read_to_string("commit.txt").ok()?;
    let hash = text.trim();
    let ok = !hash.is_empty() && hash.chars().all(|c| c.is_ascii_hexdigit());
    ok.then(|| format!("commit {}", &hash[..hash.len().min(12)]))
}

/// A git command's trimmed output, if it succeeds.
fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// What the answer depends on: the sources (edits make the tree modified) and git's HEAD, the
/// branch it names and the index (a commit, a checkout).
fn watched() -> Vec<PathBuf> {
    let mut paths: Vec<PathBuf> = [
        "build.rs",
        "commit.txt",
        "Cargo.toml",
        "Cargo.lock",
        "src",
        "crates",
        "tests",
        "docs",
        "examples",
    ]
    .iter()
    .map(PathBuf::from)
    .filter(|p| p.exists())
    .collect();
    let git_path = |name: &str| git(&["rev-parse", "--git-path", name]).map(PathBuf::from);
    let branch = git(&["symbolic-ref", "-q", "HEAD"]);
    for name in ["HEAD", "index", "packed-refs"]
        .into_iter()
        .map(str::to_string)
        .chain(branch)
    {
        if let Some(p) = git_path(&name).filter(|p| Path::new(p).exists()) {
            paths.push(p);
        }
    }
    paths
}
