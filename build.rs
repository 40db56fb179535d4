//! Names the commit the program is built from, for `platefall --version`, the summaries and the
//! recordings (`src/version.rs`): `PLATEFALL_COMMIT` is "commit " and the commit's hash, with
//! ", modified" when the program's sources (`src/`, the crates' `src/`, the manifests and
//! `Cargo.lock`) differ from it; from a `git archive` source archive, the hash that `commit.txt`
//! received on export; otherwise "commit unknown".
//!
//! It runs again only when its answer can change: a commit or checkout (git's `HEAD` and the
//! branch it names) or an edit of the program's sources (which rebuilds the program anyway);
//! edits of tests, docs or examples and git's index do not rebuild the program.
use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    let root = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default());
    let sources = program_sources(&root);
    let commit = from_git(&root, &sources).or_else(|| from_archive(&root));
    let text = commit.unwrap_or_else(|| "commit unknown".to_string());
    println!("cargo:rustc-env=PLATEFALL_COMMIT={text}");
    let watched = sources.iter().map(|p| root.join(p));
    let watched = watched.chain([root.join("build.rs"), root.join("commit.txt")]);
    for path in watched.chain(git_refs(&root)) {
        println!("cargo:rerun-if-changed={}", path.display());
    }
}

/// The program's sources relative to `root`: what a change of makes it "modified".
fn program_sources(root: &Path) -> Vec<String> {
    let mut paths = vec![
        "src".to_string(),
        "Cargo.toml".to_string(),
        "Cargo.lock".to_string(),
    ];
    let crates = std::fs::read_dir(root.join("crates")).into_iter().flatten();
    for entry in crates.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        paths.push(format!("crates/{name}/src"));
        paths.push(format!("crates/{name}/Cargo.toml"));
    }
    paths.retain(|p| root.join(p).exists());
    paths
}

/// Git's answer, if `root` is the top of a git work tree (not a source archive unpacked inside
/// another repository) and git is installed.
fn from_git(root: &Path, sources: &[String]) -> Option<String> {
    let top = git(root, &["rev-parse", "--show-toplevel"])?;
    let same = |a: &Path, b: &Path| a.canonicalize().ok() == b.canonicalize().ok();
    if !same(Path::new(&top), root) {
        return None;
    }
    let hash = git(root, &["rev-parse", "--short=12", "HEAD"])?;
    // No optional locks: a refreshed index is no change of the sources.
    let mut status = vec!["--no-optional-locks", "status", "--porcelain", "--"];
    status.extend(sources.iter().map(String::as_str));
    let modified = !git(root, &status).unwrap_or_default().is_empty();
    Some(match modified {
        false => format!("commit {hash}"),
        true => format!("commit {hash}, modified"),
    })
}

/// The hash `git archive` wrote into `commit.txt` (its `export-subst` attribute); a checkout's
/// `commit.txt` holds the unexpanded placeholder instead.
fn from_archive(root: &Path) -> Option<String> {
    let text = std::fs::read_to_string(root.join("commit.txt")).ok()?;
    let hash = text.trim();
    let ok = hash.len() >= 12 && hash.chars().all(|c| c.is_ascii_hexdigit());
    ok.then(|| format!("commit {}", &hash[..12]))
}

/// A git command's trimmed output, run in `root`, if it succeeds.
fn git(root: &Path, args: &[&str]) -> Option<String> {
    let out = Command::new("git")
        .current_dir(root)
        .args(args)
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Git's `HEAD` and the branch it names: its loose ref file, or, for a packed ref, `packed-refs`
/// and the directory a commit writes the loose ref into. None outside a git work tree.
fn git_refs(root: &Path) -> Vec<PathBuf> {
    let path = |name: &str| git(root, &["rev-parse", "--git-path", name]).map(|p| root.join(p));
    let mut refs: Vec<PathBuf> = path("HEAD").into_iter().collect();
    if let Some(branch) = git(root, &["symbolic-ref", "-q", "HEAD"]) {
        match path(&branch).filter(|p| p.exists()) {
            Some(loose) => refs.push(loose),
            None => {
                refs.extend(path("packed-refs"));
                refs.extend(path(&branch).and_then(|p| p.parent().map(Path::to_path_buf)));
            }
        }
    }
    // A missing file would make every build run this again.
    refs.retain(|p| p.exists());
    refs
}
