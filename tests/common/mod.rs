//! Shared helpers: build a run from a command line exactly as the binary does, and run it.
#![allow(dead_code)]
use clap::Parser;
use platefall::cli::{run_config, Cli};
use platefall_core::sim::RunConfig;
use platefall_core::sim::{FieldSnapshot, StepSample};
use platefall_core::sim::{Observer, RunRecord, Simulation};
use platefall_post::report::report;
use platefall_post::summary::{summarize, Summary};

/// Discards everything; never stops early.
pub struct Quiet;
impl Observer for Quiet {
    fn step(&mut self, _: &StepSample) {}
    fn wants_field(&mut self, _: f64) -> bool {
        false
    }
    fn field(&mut self, _: FieldSnapshot) {}
    fn should_stop(&self) -> bool {
        false
    }
}

/// The configuration the binary would run for these arguments (after `platefall`).
pub fn config(args: &[&str]) -> RunConfig {
    let cli = Cli::try_parse_from(std::iter::once("platefall").chain(args.iter().copied()))
        .expect("arguments parse");
    run_config(&cli.command).expect("configuration is valid")
}

/// Runs the case to its end and summarises it.
pub fn run(args: &[&str]) -> (RunConfig, RunRecord, Summary) {
    let cfg = config(args);
    let mut sim = Simulation::new(cfg.clone()).expect("simulation builds");
    let rec = sim.run(&mut Quiet);
    let sum = summarize(&cfg, &rec, 0.0);
    eprintln!("{}", report(&cfg, &sum));
    (cfg, rec, sum)
}
