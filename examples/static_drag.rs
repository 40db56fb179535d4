//! A static plate at α = 0.4 run from Rust: describe the run, step it to the end, print C_D.
use platefall_core::grid::GridSpec;
use platefall_core::sim::{Case, RunConfig, Simulation};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let case = Case::Static {
        alpha: 0.4,
        kick: 0.0,
    };
    let mut config = RunConfig::new(case, GridSpec::modern(16));
    config.time.t_end = 10.0;
    let mut sim = Simulation::new(config)?;
    while !sim.finished() {
        sim.step()?;
    }
    let s = sim.sample();
    println!("t = {:.2}: C_D = {:.3}, C_L = {:.3}", s.t, s.cd, s.cl);
    Ok(())
}
