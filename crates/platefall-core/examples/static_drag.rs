//! A static plate at α = 0.4 run from Rust: describe the run, step it to the end, print C_D.
//!
//! `cargo run --release -p platefall-core --example static_drag`
use platefall_core::config::RunBuilder;
use platefall_core::sim::Simulation;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let config = RunBuilder::static_plate(0.4)
        .kick(0.0)
        .resolution(16)
        .t_end(10.0)
        .build()?;
    let mut sim = Simulation::new(config)?;
    while !sim.finished() {
        sim.step()?;
    }
    let s = sim.sample();
    println!("t = {:.2}: C_D = {:.3}, C_L = {:.3}", s.t, s.cd, s.cl);
    Ok(())
}
