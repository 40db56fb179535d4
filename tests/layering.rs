//! What Cargo cannot see of the layering (the crates' dependencies enforce the rest: only the
//! record crate depends on Rerun, only the binary on clap; see `src/lib.rs`): the physics does no
//! I/O and reads no clock, it knows nothing of the run description built on it inside the core
//! crate, post-processing touches no file, and inside the recording crate only `viewer/` knows
//! Rerun. Each part's files are searched for what it must not use; comment lines are skipped (a
//! doc example may show how a caller prints).
use std::path::{Path, PathBuf};

/// Every `.rs` file under `<rel>` of the workspace (a file or a directory).
fn sources(rel: &str) -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    if root.is_file() {
        return vec![root];
    }
    let mut out = Vec::new();
    let mut stack = vec![root];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).expect("source directory") {
            let path = entry.expect("directory entry").path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    out
}

/// The code lines of a file that mention any of `forbidden` (as a whole word).
fn offending_lines(path: &Path, forbidden: &[&str]) -> Vec<String> {
    let text = std::fs::read_to_string(path).expect("readable source");
    let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
    // A match must not be part of a longer identifier on either side where the pattern itself
    // begins or ends with an identifier character.
    let word = |line: &str, w: &str| {
        line.match_indices(w).any(|(k, _)| {
            let before = line[..k].chars().next_back();
            let after = line[k + w.len()..].chars().next();
            (!ident(w.chars().next()) || !ident(before))
                && (!ident(w.chars().next_back()) || !ident(after))
        })
    };
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim_start().starts_with("//"))
        .filter(|(_, l)| forbidden.iter().any(|w| word(l, w)))
        .map(|(n, l)| format!("{}:{}: {}", path.display(), n + 1, l.trim()))
        .collect()
}

fn assert_layer(parts: &[&str], forbidden: &[&str]) {
    let bad: Vec<String> = parts
        .iter()
        .flat_map(|p| sources(p))
        .flat_map(|f| offending_lines(&f, forbidden))
        .collect();
    assert!(bad.is_empty(), "layering violated:\n{}", bad.join("\n"));
}

#[test]
fn the_physics_does_no_io_reads_no_clock_and_knows_no_run_description() {
    let core = |m: &str| format!("crates/platefall-core/src/{m}");
    let physics: Vec<String> = ["param.rs", "grid.rs", "flow", "body", "sim"]
        .iter()
        .map(|m| core(m))
        .collect();
    let physics: Vec<&str> = physics.iter().map(String::as_str).collect();
    assert_layer(&physics, &["crate::config"]);
    assert_layer(
        &["crates/platefall-core/src"],
        &[
            "std::fs",
            "std::io",
            "std::net",
            "Instant",
            "SystemTime",
            "println",
            "eprintln",
            "print",
            "eprint",
        ],
    );
}

#[test]
fn post_processing_touches_no_file_or_network() {
    assert_layer(&["crates/platefall-post/src"], &["std::fs", "std::net"]);
}

#[test]
fn only_the_viewer_knows_rerun() {
    let rec = "crates/platefall-record/src";
    let rerun_free: Vec<String> = std::fs::read_dir(rec)
        .expect("record sources")
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.is_file())
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    assert!(
        rerun_free.len() > 5,
        "the recording crate's files were not found"
    );
    let root = env!("CARGO_MANIFEST_DIR");
    let parts: Vec<&str> = rerun_free
        .iter()
        .map(|p| p.strip_prefix(root).unwrap_or(p).trim_start_matches('/'))
        .collect();
    assert_layer(&parts, &["rerun::", "use rerun"]);
}
