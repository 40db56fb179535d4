//! What Cargo cannot see of the layering (the crates' dependencies enforce the rest: only the
//! record crate depends on Rerun, only the binary on clap; see `src/lib.rs`): the physics does no
//! I/O and reads no clock, it knows nothing of the run description built on it inside the core
//! crate, post-processing touches no file, and inside the recording crate only `viewer/` knows
//! Rerun. Each part's files are searched for what it must not use; comment lines are skipped (a
//! doc example may show how a caller prints), and so are files compiled for unit tests only.
//!
//! Inside each crate the files read top-down: the file graph of every crate (an arrow from a file
//! to each file whose module it names, see `file_graph`) has no circle.
mod file_graph;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use file_graph::{circles, crate_graph};

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

/// The files of the workspace's crates compiled for unit tests only: like the tests under
/// `tests/`, they may print, read files and use any layer.
fn unit_test_files() -> BTreeSet<PathBuf> {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR"));
    CRATE_ROOTS
        .iter()
        .flat_map(|r| crate_graph(workspace, r).unit_test_files)
        .map(|f| workspace.join(f))
        .collect()
}

fn assert_layer(parts: &[&str], forbidden: &[&str]) {
    let unit_tests = unit_test_files();
    let bad: Vec<String> = parts
        .iter()
        .flat_map(|p| sources(p))
        .filter(|f| !unit_tests.contains(f))
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

/// The root file of each crate of the workspace (the binary's library and its `main`).
const CRATE_ROOTS: &[&str] = &[
    "crates/platefall-core/src/lib.rs",
    "crates/platefall-post/src/lib.rs",
    "crates/platefall-record/src/lib.rs",
    "src/lib.rs",
    "src/main.rs",
];

/// The circles of the crate rooted at `root`, each as its path with the line behind every arrow.
fn unexpected_circles(root: &str) -> Vec<String> {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR"));
    let graph = crate_graph(workspace, root);
    assert!(
        graph.files.len() > 1 || root.ends_with("main.rs"),
        "{root}: no modules found"
    );
    circles(&graph.named())
        .into_iter()
        .map(|c| {
            let why: Vec<String> = c
                .path
                .windows(2)
                .map(|w| format!("    {}", graph.evidence(&w[0], &w[1])))
                .collect();
            format!(
                "{} (the circle's files: {})\n{}",
                c.path.join(" -> "),
                c.members.join(", "),
                why.join("\n")
            )
        })
        .collect()
}

#[test]
fn no_two_files_of_a_crate_use_each_other() {
    let found: Vec<String> = CRATE_ROOTS
        .iter()
        .flat_map(|r| unexpected_circles(r))
        .collect();
    assert!(
        found.is_empty(),
        "files that use each other in a circle (a crate's files must read top-down):\n{}",
        found.join("\n")
    );
}

#[test]
fn the_circle_finder_finds_each_circle_and_only_circles() {
    let graph = |arrows: &[(&str, &str)]| {
        let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (a, b) in arrows {
            g.entry(a.to_string()).or_default().insert(b.to_string());
            g.entry(b.to_string()).or_default();
        }
        g
    };
    let names = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    // A diamond and a chain: no circle.
    let tree = graph(&[("a", "b"), ("a", "c"), ("b", "d"), ("c", "d"), ("d", "e")]);
    assert!(circles(&tree).is_empty());
    // a → b → c → a with a shortcut c → b, and a separate pair d ⇄ e reached from c; f hangs off.
    let two = graph(&[
        ("a", "b"),
        ("b", "c"),
        ("c", "a"),
        ("c", "b"),
        ("c", "d"),
        ("d", "e"),
        ("e", "d"),
        ("e", "f"),
    ]);
    let found = circles(&two);
    assert_eq!(found.len(), 2, "{found:?}");
    assert_eq!(found[0].members, names(&["a", "b", "c"]));
    assert_eq!(found[0].path, names(&["a", "b", "c", "a"]));
    assert_eq!(found[1].members, names(&["d", "e"]));
    assert_eq!(found[1].path, names(&["d", "e", "d"]));
    // A file that names itself is no circle.
    assert!(circles(&graph(&[("a", "a"), ("a", "b")])).is_empty());
}
