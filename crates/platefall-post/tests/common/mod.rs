//! Shared helper: run a case built by the library to its end and summarise it.
#![allow(dead_code)]
use platefall_core::sim::{RunConfig, RunRecord, Silent, Simulation, ValidatedConfig};
use platefall_post::report::report;
use platefall_post::summary::{summarize, Summary};

/// Runs the case to its end, summarises it and prints its report.
pub fn run(config: ValidatedConfig) -> (RunConfig, RunRecord, Summary) {
    let mut sim = Simulation::new(config).expect("simulation builds");
    let rec = sim.run(&mut Silent);
    let cfg = sim.config().clone();
    let sum = summarize(&cfg, &rec, 0.0);
    eprintln!("{}", report(&cfg, &sum));
    (cfg, rec, sum)
}
