//! `platefall bench`: the flow step's cost per cell on several grids, or with `--card` the time to
//! solution of the card's free fall (see `crate::bench`), or with `--span` the 3-D step's cost
//! (see `crate::bench3`).
use std::path::PathBuf;

use clap::Args;

use super::args::FarFieldArg;
use super::span_arg::parse_span;
use crate::bench::{bench_card, bench_one, card_table, table, BenchRow, CardRow};
use crate::bench3::{bench_grid, bench_one3, table3, Bench3Row};
use platefall_core::flow3d::Span;
use platefall_record::files::check_writable;
use platefall_record::output::write_atomically;

#[derive(Args, Debug)]
pub struct BenchArgs {
    /// Cells per chord of the grids to time (each with the default extent and growth cap)
    /// [default: 32,64,128,384; with --card 32,64,128; with --span 8,16,24].
    #[arg(long, value_delimiter = ',')]
    pub resolutions: Option<Vec<usize>>,
    /// Steps timed per grid (after 5 warm-up steps); with --card, the steps timed on one core.
    #[arg(long, default_value_t = 50)]
    pub steps: usize,
    /// Worker threads (0: one per core) [default: 1, or 0 with --card].
    #[arg(long)]
    pub threads: Option<usize>,
    /// The far-field scheme to time.
    #[arg(long, value_enum, default_value_t = FarFieldArg::Implicit)]
    pub far_field: FarFieldArg,
    /// Time to solution of a rotating plate: the card's free fall (`platefall free`) through
    /// --turns turns after release; steps per turn over turns 2..=T, time per step and per turn
    /// on all cores (--threads) and on one core (--steps more steps).
    #[arg(long)]
    pub card: bool,
    /// Turns after release for --card (at least 2: the first is the spin-up).
    #[arg(long, default_value_t = 2)]
    pub turns: usize,
    /// Time the three-dimensional step instead, around the card's plate with this span: B (a
    /// finite span of B chords) or periodic:P (an infinite span, periodic over P chords); the
    /// grid extends 5 chords each way with growth at most 1.1.
    #[arg(long, value_parser = parse_span, conflicts_with = "card")]
    pub span: Option<Span>,
    /// Write the results as JSON to this file.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
}

/// Runs the benchmark and prints its table (and writes --json).
pub fn run_bench(args: &BenchArgs) -> anyhow::Result<()> {
    if args.steps == 0 {
        anyhow::bail!("--steps 0 is out of range: accepted 1..");
    }
    if args.card && args.turns < 2 {
        anyhow::bail!(
            "--turns {} is out of range: accepted 2.. (with --card)",
            args.turns
        );
    }
    if let Some(p) = &args.json {
        check_writable(p, false).map_err(|r| anyhow::anyhow!("--json {}: {r}", p.display()))?;
    }
    let json = if let Some(span) = args.span {
        serde_json::to_string_pretty(&step_rows3(args, span)?)?
    } else if args.card {
        serde_json::to_string_pretty(&card_rows(args)?)?
    } else {
        serde_json::to_string_pretty(&step_rows(args)?)?
    };
    if let Some(p) = &args.json {
        write_atomically("--json", p, json.as_bytes())?;
    }
    Ok(())
}

/// The step benchmark, one row per resolution, printed as it goes.
fn step_rows(args: &BenchArgs) -> anyhow::Result<Vec<BenchRow>> {
    let threads = args.threads.unwrap_or(1);
    let resolutions = args.resolutions.clone().unwrap_or(vec![32, 64, 128, 384]);
    eprintln!(
        "timing {} steps per grid, prescribed motion (α = 0.4 translation + θ̇ = 1), {:?} far field",
        args.steps, args.far_field
    );
    let mut rows = Vec::new();
    for &n in &resolutions {
        rows.push(bench_one(n, args.steps, args.far_field.into(), threads)?);
        if let Some(line) = table(&rows).lines().last() {
            eprintln!("{line}");
        }
    }
    print!("{}", table(&rows));
    Ok(rows)
}

/// The 3-D step benchmark, one row per resolution, printed as it goes.
fn step_rows3(args: &BenchArgs, span: Span) -> anyhow::Result<Vec<Bench3Row>> {
    let threads = args.threads.unwrap_or(1);
    let resolutions = args.resolutions.clone().unwrap_or(vec![8, 16, 24]);
    // Every grid is checked before the first is timed: bad input gets one line.
    for &n in &resolutions {
        bench_grid(n, span)?;
    }
    eprintln!(
        "timing {} 3-D steps per grid, prescribed motion (α = 0.4 translation + rotation 1 about the span)",
        args.steps
    );
    let mut rows = Vec::new();
    for &n in &resolutions {
        rows.push(bench_one3(n, span, args.steps, threads)?);
        if let Some(line) = table3(&rows).lines().last() {
            eprintln!("{line}");
        }
    }
    print!("{}", table3(&rows));
    Ok(rows)
}

/// The card benchmark, one row per resolution, printed as it goes.
fn card_rows(args: &BenchArgs) -> anyhow::Result<Vec<CardRow>> {
    let threads = args.threads.unwrap_or(0);
    let resolutions = args.resolutions.clone().unwrap_or(vec![32, 64, 128]);
    eprintln!(
        "the card's free fall, {} turns after release, {:?} far field; then {} steps on one core",
        args.turns, args.far_field, args.steps
    );
    let mut rows = Vec::new();
    for &n in &resolutions {
        let row = bench_card(n, args.turns, args.far_field.into(), threads, args.steps)?;
        rows.push(row);
        if let Some(line) = card_table(&rows).lines().last() {
            eprintln!("{line}");
        }
    }
    print!("{}", card_table(&rows));
    Ok(rows)
}
