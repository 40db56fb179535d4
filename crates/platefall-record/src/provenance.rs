//! How a run was started, carried inside its recording (`/run/invocation`, a JSON text document)
//! and its summary: the program's version and commit, the arguments, the working directory and
//! the text of every input file the arguments name (a `--polygon`), so that `platefall info`
//! can describe a recording and `platefall reproduce` can run it again anywhere.
use serde::{Deserialize, Serialize};

/// The format of the invocation document; a reader refuses others.
pub const INVOCATION_FORMAT: &str = "platefall invocation 1";

/// An input file named on the command line, with its text as the run read it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct InputFile {
    /// The option naming it, e.g. "--polygon".
    pub flag: String,
    /// The path as given.
    pub path: String,
    /// Its text.
    pub text: String,
}

/// How a run was started.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Invocation {
    /// [`INVOCATION_FORMAT`].
    pub format: String,
    /// The program, version and commit, e.g. "platefall 0.1.0 (commit 0123456789ab)".
    pub version: String,
    /// The arguments after the program's name, exactly as given.
    pub args: Vec<String>,
    /// The working directory the relative paths in `args` are relative to.
    pub directory: String,
    /// The input files `args` name.
    pub inputs: Vec<InputFile>,
}

impl Invocation {
    /// This process's invocation, by the program `version`, reading `inputs`.
    pub fn of_this_process(version: String, inputs: Vec<InputFile>) -> Invocation {
        Invocation {
            format: INVOCATION_FORMAT.to_string(),
            version,
            args: std::env::args().skip(1).collect(),
            directory: std::env::current_dir()
                .map(|d| d.display().to_string())
                .unwrap_or_default(),
            inputs,
        }
    }
}

/// The invocation document of a recording: the invocation and what the run was.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RecordedInvocation {
    /// How it was started.
    #[serde(flatten)]
    pub invocation: Invocation,
    /// The case ("static", "forced", "pinned", "free").
    pub case: String,
    /// The run's one-line title.
    pub title: String,
    /// The resolved configuration.
    pub config: serde_json::Value,
}
