//! `platefall info FILE.rrd`: what a recording is, read from the recording alone: its title,
//! the program and commit that made it, the command line and directory, the input files it
//! carries, its steps and time span, the configuration and the report with its summary
//! (docs/user-guide.md, "A recording for a bug report").
use std::path::PathBuf;

use clap::Args;

use super::shell::shell_line;
use crate::exit::Exit;
use crate::version::program_and_commit;
use platefall_record::recorded::Recorded;
use platefall_record::viewer::read_recording;

/// `platefall info`'s options.
#[derive(Args, Debug, Clone)]
pub struct InfoArgs {
    /// The recording (.rrd) a platefall run wrote
    pub file: PathBuf,
    /// Also print the summary as JSON (as --summary writes it)
    #[arg(long)]
    pub json: bool,
}

/// Prints what the recording is; bad input (exit 2) when it is not a complete platefall
/// recording.
pub fn run_info(args: &InfoArgs) -> anyhow::Result<Exit> {
    let recorded = read_recording(&args.file)?;
    print!("{}", describe(&args.file, &recorded));
    if args.json {
        let summary = recorded.summary_json.as_deref().unwrap_or("null");
        println!("\nSummary (JSON):\n{summary}");
    }
    Ok(Exit::Completed)
}

/// The description: one line a fact, then the report.
pub fn describe(file: &std::path::Path, r: &Recorded) -> String {
    let inv = &r.invocation.invocation;
    let ours = program_and_commit();
    let made_by = if inv.version == ours {
        inv.version.clone()
    } else {
        format!("{} (this is {ours})", inv.version)
    };
    let mut out = format!(
        "{}: {}\n  program:   {made_by}\n  case:      {}\n  command:   {}\n  directory: {}\n",
        file.display(),
        r.invocation.title,
        r.invocation.case,
        shell_line(std::iter::once("platefall").chain(inv.args.iter().map(String::as_str))),
        inv.directory,
    );
    for input in &inv.inputs {
        out += &format!(
            "  input:     {} {} ({} lines, carried in the recording)\n",
            input.flag,
            input.path,
            input.text.lines().count()
        );
    }
    out += &format!("  steps:     {}\n", span(r));
    // (Cannot fail for a JSON value.)
    let config = serde_json::to_string_pretty(&r.invocation.config).unwrap_or_default();
    out += &format!("\nConfiguration:\n{config}\n");
    match &r.report {
        Some(report) => out += &format!("\nReport:\n{report}"),
        None => out += "\nThe recording ends before the run did: it has no report.\n",
    }
    out
}

/// "N steps (1 … N), t = a … b c/U".
fn span(r: &Recorded) -> String {
    match (r.steps.first(), r.steps.last()) {
        (Some(a), Some(b)) => format!(
            "{} recorded (step {} … {}), t = {:.4} … {:.4} c/U",
            r.steps.len(),
            a.step,
            b.step,
            a.t,
            b.t
        ),
        _ => "none recorded".to_string(),
    }
}
