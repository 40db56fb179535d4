//! `platefall reproduce`'s options, below the command that takes them (`command.rs`) and the
//! reproduction itself (`reproduce.rs`), which makes the recorded run with that command.
use std::path::PathBuf;

use clap::Args;

/// `platefall reproduce`'s options.
#[derive(Args, Debug, Clone)]
#[command(
    after_help = "Exit codes:\n  0    identical: every recorded step reproduced bit for bit\n  \
    1    the rerun differs from the recording (the first difference is printed)\n  \
    2    bad input: not a complete platefall recording, or its run cannot be made here"
)]
pub struct ReproduceArgs {
    /// The recording (.rrd) a platefall run wrote
    pub file: PathBuf,
    /// Where the recording's input files (a --polygon) are written for the rerun [default: the
    /// recording's name with .inputs, beside it; only made when there are input files]
    #[arg(long, value_name = "DIR")]
    pub dir: Option<PathBuf>,
    /// Compare the first N steps only [default: every recorded step]
    #[arg(long, value_name = "N")]
    pub steps: Option<u64>,
    /// Print the command line that reruns the recording (after writing its input files) and stop
    #[arg(long)]
    pub print: bool,
    /// Worker threads (0: one per core); the results do not depend on it
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
}
