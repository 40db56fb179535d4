//! The program's name and version, as recordings, checkpoints and a sweep's children state it.

/// "platefall X.Y.Z": what a checkpoint must have been written by to be read back, and the
/// version a recording names.
pub(crate) fn program_version() -> String {
    format!("platefall {}", env!("CARGO_PKG_VERSION"))
}
