//! The process's exit codes, one type for runs and sweeps: each code means one thing, and the
//! help text is made from the same table.
use std::process::ExitCode;

use platefall_core::sim::RunStatus;

/// How platefall ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Exit {
    /// 0: the run completed (a sweep: every case completed).
    Completed,
    /// 2: bad input: nothing was run or written.
    BadInput,
    /// 3: the solution diverged (a sweep: it ended, but some cases did not complete).
    Diverged,
    /// 4: an output could not be written.
    OutputFailed,
    /// 75: interrupted (SIGTERM, SIGUSR1, Ctrl-C) after writing a checkpoint.
    Checkpointed,
    /// 130: interrupted (Ctrl-C, SIGTERM).
    Interrupted,
}

impl Exit {
    /// Every code, in order.
    pub(crate) const ALL: [Exit; 6] = [
        Exit::Completed,
        Exit::BadInput,
        Exit::Diverged,
        Exit::OutputFailed,
        Exit::Checkpointed,
        Exit::Interrupted,
    ];

    /// The numeric code.
    pub(crate) fn code(self) -> u8 {
        match self {
            Exit::Completed => 0,
            Exit::BadInput => 2,
            Exit::Diverged => 3,
            Exit::OutputFailed => 4,
            Exit::Checkpointed => 75,
            Exit::Interrupted => 130,
        }
    }

    /// The exit of a numeric code, if it is one of platefall's.
    pub(crate) fn from_code(code: i32) -> Option<Exit> {
        Exit::ALL.into_iter().find(|e| i32::from(e.code()) == code)
    }

    /// The exit of a run that ended with `status` and wrote every output.
    pub(crate) fn of_status(status: &RunStatus) -> Exit {
        match status {
            RunStatus::Completed => Exit::Completed,
            RunStatus::Diverged(_) => Exit::Diverged,
            RunStatus::Interrupted => Exit::Interrupted,
            RunStatus::OutputFailed(_) => Exit::OutputFailed,
        }
    }

    /// What the code means for a run of one case.
    fn for_run(self) -> &'static str {
        match self {
            Exit::Completed => "completed (every output complete at its final name)",
            Exit::BadInput => {
                "bad input: one line names the value and what is accepted; nothing was run or \
                 written"
            }
            Exit::Diverged => {
                "the solution diverged; the outputs hold the run up to then and say so"
            }
            Exit::OutputFailed => {
                "an output could not be written (disk full, permissions, directory removed, sink \
                 error): nothing incomplete is left at its final name"
            }
            Exit::Checkpointed => {
                "interrupted (SIGTERM, SIGUSR1, Ctrl-C) with checkpoints on (--checkpoint-every, \
                 --checkpoint): the checkpoint was written first and `platefall resume FILE` goes \
                 on exactly; the outputs hold the run up to then and say so"
            }
            Exit::Interrupted => {
                "interrupted (Ctrl-C, SIGTERM); the outputs hold the run up to then and say so. A \
                 second Ctrl-C quits at once, leaving unfinished outputs as .NAME.partial-PID files"
            }
        }
    }

    /// What the code means for a sweep.
    fn for_sweep(self) -> &'static str {
        match self {
            Exit::Completed => "every case completed",
            Exit::BadInput => {
                "bad plan or options, or an output directory that cannot be made (nothing is run \
                 or written)"
            }
            Exit::Diverged => "the sweep ended but some cases did not complete (listed, with why)",
            Exit::OutputFailed => "an output could not be written",
            Exit::Checkpointed => "interrupted; the running cases wrote their checkpoints",
            Exit::Interrupted => {
                "interrupted (the running cases are finalised and the results merged first)"
            }
        }
    }

    /// `text` followed by the exit codes of a sweep (the long help of `sweep` and `converge`).
    pub(crate) fn sweep_long_help(text: &str) -> String {
        format!("{text}\n\n{}", Exit::help(true))
    }

    /// The exit-code table of `--help`: for the case subcommands, or (`sweep`) for sweeps.
    pub(crate) fn help(sweep: bool) -> String {
        let mut text = String::from("Exit codes:");
        for e in Exit::ALL {
            let what = if sweep { e.for_sweep() } else { e.for_run() };
            text.push_str(&format!("\n  {:<4} {what}", e.code()));
        }
        text
    }
}

impl From<Exit> for ExitCode {
    fn from(e: Exit) -> ExitCode {
        ExitCode::from(e.code())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_code_means_one_thing() {
        let codes: Vec<u8> = Exit::ALL.iter().map(|e| e.code()).collect();
        assert_eq!(codes, [0, 2, 3, 4, 75, 130]);
        let help = Exit::help(false);
        assert!(help.contains("\n  130  interrupted"), "{help}");
        assert!(Exit::help(true).contains("\n  3    the sweep ended"));
    }
}
