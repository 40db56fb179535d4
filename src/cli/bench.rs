//! `platefall bench`: the flow step's cost per cell on several grids (see [`crate::bench`]).
use super::args::BenchArgs;
use crate::bench::{bench_one, table};
use crate::record::files::check_writable;
use crate::record::output::write_atomically;

/// Runs the benchmark and prints its table (and writes --json).
pub fn run_bench(args: &BenchArgs) -> anyhow::Result<()> {
    if args.steps == 0 {
        anyhow::bail!("--steps 0 is out of range: accepted 1..");
    }
    if let Some(p) = &args.json {
        check_writable(p, false).map_err(|r| anyhow::anyhow!("--json {}: {r}", p.display()))?;
    }
    let mut rows = Vec::new();
    eprintln!(
        "timing {} steps per grid, single-threaded, prescribed motion (α = 0.4 translation + θ̇ = 1)",
        args.steps
    );
    for &n in &args.resolutions {
        rows.push(bench_one(n, args.steps)?);
        if let Some(line) = table(&rows).lines().last() {
            eprintln!("{line}");
        }
    }
    print!("{}", table(&rows));
    if let Some(p) = &args.json {
        write_atomically("--json", p, serde_json::to_string_pretty(&rows)?.as_bytes())?;
    }
    Ok(())
}
