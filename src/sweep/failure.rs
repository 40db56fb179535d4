//! Why a sweep stops (an [`Exit`] code and one line), and the sweep's writes of whole files,
//! through the recording crate's atomic outputs like every other output of platefall.
use std::path::Path;

use super::plan_error::PlanError;
use crate::exit::Exit;
use platefall_record::output::{write_atomically, OutputError};

/// A sweep that stops: the process exit code and one line saying why.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Failure {
    pub(crate) exit: Exit,
    pub(crate) message: String,
}

impl Failure {
    /// Bad input (a plan, an option, a path that cannot be used): nothing ran; exit 2.
    pub(crate) fn input(message: impl Into<String>) -> Self {
        Failure {
            exit: Exit::BadInput,
            message: message.into(),
        }
    }

    /// An output that could not be written: exit 4.
    pub(crate) fn output(message: impl Into<String>) -> Self {
        Failure {
            exit: Exit::OutputFailed,
            message: message.into(),
        }
    }
}

impl From<PlanError> for Failure {
    fn from(e: PlanError) -> Self {
        Failure::input(e.0)
    }
}

impl From<OutputError> for Failure {
    fn from(e: OutputError) -> Self {
        Failure::output(e.to_string())
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Failure {}

/// Writes a whole file of the sweep atomically: complete at its final name, or not there.
pub(crate) fn write_output(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    write_atomically("sweep output", path, bytes)?;
    Ok(())
}
