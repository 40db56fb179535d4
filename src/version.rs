//! The program's name, version and the commit its sources come from (`build.rs`), as
//! `platefall --version`, the summaries, the recordings, checkpoints and a sweep's children state
//! it (docs/user-guide.md, "Recordings").

/// The commit the program is built from: "commit 0123456789ab", "commit 0123456789ab, modified"
/// (the work tree differed from it), or "commit unknown" (no git and no `git archive` stamp).
pub const COMMIT: &str = env!("PLATEFALL_COMMIT");

/// The version `--version` prints, e.g. "0.1.0 (commit 0123456789ab)".
pub const VERSION: &str = concat!(
    env!("CARGO_PKG_VERSION"),
    " (",
    env!("PLATEFALL_COMMIT"),
    ")"
);

/// "platefall X.Y.Z": what a checkpoint must have been written by to be read back (a checkpoint
/// stays readable across commits of one release).
pub(crate) fn program_version() -> String {
    format!("platefall {}", env!("CARGO_PKG_VERSION"))
}

/// The program, its version and commit, as the summaries and recordings name it, e.g.
/// "platefall 0.1.0 (commit 0123456789ab)".
pub fn program_and_commit() -> String {
    format!("platefall {VERSION}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_version_names_a_commit_or_says_it_is_unknown() {
        let hash = COMMIT.strip_prefix("commit ").unwrap_or("");
        let hash = hash.strip_suffix(", modified").unwrap_or(hash);
        let named = hash.len() == 12 && hash.chars().all(|c| c.is_ascii_hexdigit());
        assert!(named || COMMIT == "commit unknown", "{COMMIT}");
        assert!(VERSION.starts_with(env!("CARGO_PKG_VERSION")));
        assert!(program_and_commit().starts_with(&program_version()));
        assert!(program_and_commit().ends_with(&format!("({COMMIT})")));
    }
}
