//! The card's free fall in 2-D and as a plate of short periodic span in 3-D, flying planar, on
//! the same x–y grid (docs/three-d.md "Free flight"): the 3-D solver with a spanwise-uniform
//! flow must reproduce the 2-D solver's first turns.
//!
//! `cargo run --release -p platefall-core --example planar_card -- [N] [TURNS]` (defaults 16, 2)
//! prints, per half turn after the release, the time both runs reach it and their speeds.
use std::f64::consts::PI;

use platefall_core::body::six::{Constraint6, Plate6, RigidBody6, State6};
use platefall_core::body::AbStart;
use platefall_core::config::{Plate, RunBuilder};
use platefall_core::flow3d::{
    FlowParams3, FlowSolver3, Grid3, GridSpec3, OuterBc3, Span, Stretch3,
};
use platefall_core::sim::Simulation;
use platefall_core::sim3::{frame_of, Flight3};

/// The shared section and grid: thickness (one cell at N = 16), extent and growth cap of 2-D.
const THICKNESS: f64 = 1.0 / 16.0;
const EXTENT: f64 = 15.0;
const GROWTH: f64 = 1.045;
/// The 2-D free fall's launch (docs/physics.md §1 D): V₀ = 1 along γ₀ at α₀, held 5 c/U.
const GAMMA0: f64 = -PI / 4.0;
const ALPHA0: f64 = 0.1;
const DEVELOP: f64 = 5.0;
const DT_MAX: f64 = 0.01;

/// (t, θ, speed) after each step from the release on.
type Path = Vec<(f64, f64, f64)>;

fn two_d(n: usize, t_end: f64) -> Result<Path, Box<dyn std::error::Error>> {
    let config = RunBuilder::free(Plate::card())
        .resolution(n)
        .thickness(THICKNESS)
        .extent(EXTENT)
        .growth(GROWTH)
        .dt_max(DT_MAX)
        .t_end(t_end)
        .build()?;
    let mut sim = Simulation::new(config)?;
    let mut path = Path::new();
    while !sim.finished() {
        let s = sim.step()?;
        if s.t >= DEVELOP - 1e-9 {
            path.push((s.t, s.theta, s.speed));
        }
    }
    Ok(path)
}

fn three_d(n: usize, t_end: f64) -> Result<(Path, usize), Box<dyn std::error::Error>> {
    let period = 4.0 / n as f64;
    let card = Plate::card();
    let (p, re) = (card.props(), card.reynolds().unwrap_or(4770.0));
    let plate = Plate6::principal(
        p.mass * period,
        [p.inertia * period; 3],
        p.gravity,
        p.displaced * period,
    )?;
    let start = State6::release(1.0, GAMMA0, ALPHA0);
    let grid = Grid3::new(&GridSpec3 {
        resolution: n,
        thickness: THICKNESS,
        span: Span::Periodic(period),
        extent: [EXTENT; 3],
        stretch: Stretch3::GrowthCap(GROWTH),
        memory_limit: 8e9,
        shape: Default::default(),
    })?;
    let cells = grid.cells();
    let params = FlowParams3 {
        re,
        ..FlowParams3::default()
    };
    let flow = FlowSolver3::new(grid, params, OuterBc3::FarField, frame_of(&start))?;
    let body = RigidBody6::new(plate, Constraint6::Planar, start, 2, AbStart::Ramp)?;
    let mut flight = Flight3::new(flow, body)?.hold_until(DEVELOP)?;
    let mut path = Path::new();
    while flight.flow().t() < t_end - 1e-9 {
        let s = flight.step(DT_MAX)?;
        if s.t >= DEVELOP - 1e-9 {
            let (_, _, theta) = s.state.orientation.euler_angles();
            path.push((s.t, theta, s.state.velocity.norm()));
        }
    }
    Ok((path, cells))
}

/// The times the path's pitch, unwrapped from the release, passes each half turn.
fn half_turns(path: &Path) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let (mut unwrapped, mut last) = (0.0, path[0].1);
    for &(t, theta, speed) in &path[1..] {
        let mut d = theta - last;
        d -= 2.0 * PI * (d / (2.0 * PI)).round();
        unwrapped += d;
        last = theta;
        if unwrapped.abs() >= PI * (out.len() + 1) as f64 {
            out.push((t, speed));
        }
    }
    out
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args.first().map_or(Ok(16), |a| a.parse())?;
    let turns: f64 = args.get(1).map_or(Ok(2.0), |a| a.parse())?;
    let t_end = DEVELOP + 6.0 * turns;
    let clock = std::time::Instant::now();
    let flat = half_turns(&two_d(n, t_end)?);
    let t2 = clock.elapsed().as_secs_f64();
    let (path, cells) = three_d(n, t_end)?;
    let span = half_turns(&path);
    let t3 = clock.elapsed().as_secs_f64() - t2;
    println!("N = {n}: 2-D {t2:.0} s; 3-D periodic span of 4 cells, {cells} cells, {t3:.0} s");
    println!("half turn | t (2-D) | t (3-D) | Δt/t | speed (2-D) | speed (3-D) | Δ");
    for (k, (a, b)) in flat.iter().zip(&span).enumerate() {
        println!(
            "{:9} | {:7.3} | {:7.3} | {:+.2} % | {:11.4} | {:11.4} | {:+.2} %",
            k + 1,
            a.0,
            b.0,
            100.0 * (b.0 - a.0) / (a.0 - DEVELOP),
            a.1,
            b.1,
            100.0 * (b.1 / a.1 - 1.0)
        );
    }
    Ok(())
}
