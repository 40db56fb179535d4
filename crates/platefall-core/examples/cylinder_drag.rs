//! The circular cylinder's drag split into pressure and friction (docs/physics.md §5):
//!
//! ```text
//! cargo run --release -p platefall-core --example cylinder_drag -- RE N EXTENT T_END
//! ```
//!
//! prints, every 10 time units, C_D and its pressure and friction parts.
use platefall_core::config::RunBuilder;
use platefall_core::shape::Shape;
use platefall_core::sim::Simulation;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse())
        .collect::<Result<_, _>>()?;
    let [re, n, extent, t_end] = args[..] else {
        return Err("give RE N EXTENT T_END".into());
    };
    let config = RunBuilder::static_plate(0.0)
        .kick(0.0)
        .shape(Shape::Ellipse { thickness: 1.0 })
        .re(re)
        .resolution(n as usize)
        .extent(extent)
        .t_end(t_end)
        .build()?;
    let mut sim = Simulation::new(config)?;
    let mut next = 10.0;
    while !sim.finished() {
        let s = sim.step()?;
        if s.t >= next || sim.finished() {
            next += 10.0;
            let l = sim.flow().loads();
            // The drag is the force along the motion's opposite; split C_D in the ratio of
            // the pressure and friction parts of that force component.
            let pressure = s.cd * l.fx_pressure / l.fx;
            println!(
                "t = {:6.2}: C_D = {:.4}  pressure {:.4}  friction {:.4}",
                s.t,
                s.cd,
                pressure,
                s.cd - pressure
            );
        }
    }
    Ok(())
}
