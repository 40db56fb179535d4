//! What a run records about how it was started (`platefall_record::provenance`): this process's
//! arguments and directory, the text of its input files and the program's commit; and the
//! summary JSON as `--summary` writes it, with the version and arguments first and last.
use serde::Serialize;

use super::command::Command;
use crate::version::program_and_commit;
use platefall_record::provenance::{InputFile, Invocation};

/// This process's invocation of the case `cmd`, with the text of the `--polygon` it names.
pub fn invocation(cmd: &Command) -> Invocation {
    let polygon = cmd
        .case_args()
        .and_then(|(solver, _)| solver.section.polygon.as_ref());
    let inputs = polygon.map(|path| InputFile {
        flag: "--polygon".to_string(),
        path: path.display().to_string(),
        // Read and checked when the run was validated.
        text: std::fs::read_to_string(path).unwrap_or_default(),
    });
    Invocation::of_this_process(program_and_commit(), inputs.into_iter().collect())
}

/// The summary file: the program and commit (`version`), the summary's keys, the arguments
/// (`args`, after the program's name).
#[derive(Serialize)]
struct SummaryFile<'a, S: Serialize> {
    version: &'a str,
    #[serde(flatten)]
    summary: &'a S,
    args: &'a [String],
}

/// The summary JSON (pretty) of a run started as `invocation` says.
pub fn summary_json<S: Serialize>(invocation: &Invocation, summary: &S) -> String {
    let file = SummaryFile {
        version: &invocation.version,
        summary,
        args: &invocation.args,
    };
    // (Cannot fail for plain data; never leave the logger unfinished over it.)
    serde_json::to_string_pretty(&file).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}

/// The report `text` with the program, version and commit of `invocation` as its second line
/// (after the title line).
pub fn with_version(text: &str, invocation: &Invocation) -> String {
    let (title, rest) = text.split_once('\n').unwrap_or((text, ""));
    format!("{title}\nprogram {}\n{rest}", invocation.version)
}
