//! The layers read top-down (see `src/lib.rs`): physics ← run description ← post-processing ←
//! recording ← command line. Each layer's files are searched for what it must not use; comment
//! lines are skipped (a doc example may show how a caller prints).
use std::path::{Path, PathBuf};

/// Every `.rs` file under `src/<rel>` (a file or a directory).
fn sources(rel: &str) -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src").join(rel);
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
fn the_physics_does_no_io_reads_no_clock_and_knows_no_layer_above_it() {
    assert_layer(
        &["param.rs", "grid.rs", "flow", "body", "sim"],
        &[
            "crate::config",
            "crate::post",
            "crate::record",
            "crate::cli",
            "crate::bench",
            "rerun::",
            "clap",
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
fn the_run_description_and_post_processing_know_no_recording_viewer_or_command_line() {
    assert_layer(
        &["config"],
        &[
            "crate::post",
            "crate::record",
            "crate::cli",
            "rerun::",
            "clap",
            "std::fs",
            "std::net",
        ],
    );
    assert_layer(
        &["post"],
        &[
            "crate::record",
            "crate::cli",
            "rerun::",
            "clap",
            "std::fs",
            "std::net",
        ],
    );
}

#[test]
fn only_the_viewer_knows_rerun_and_only_the_command_line_knows_clap() {
    let below_cli = [
        "param.rs", "grid.rs", "flow", "body", "sim", "config", "post", "record",
    ];
    assert_layer(&below_cli, &["clap", "crate::cli"]);
    let rerun_free = [
        "record/logger.rs",
        "record/csv.rs",
        "record/files.rs",
        "record/messages.rs",
        "record/options.rs",
        "record/progress.rs",
        "record/mod.rs",
        "record/viewer_off.rs",
        "cli",
    ];
    assert_layer(&rerun_free, &["rerun::", "use rerun"]);
}
