//! The cost of strong coupling (docs/physics.md §6), `platefall bench`-style: the card released at once
//! (no development) steps with `--coupling strong` and `--coupling explicit` in alternating blocks
//! on one thread; the best block of each gives ns per cell per step. Also times the set-up of the
//! added-mass matrix K (three projections).
//!
//! `cargo run --release -p platefall-core --example coupling_cost [N ...]` (default 32 64).
use std::time::Instant;

use platefall_core::body::{Coupling, Dof, StrongCoupling};
use platefall_core::config::{Plate, RunBuilder};
use platefall_core::flow::{AddedMass, FlowSolver, OuterBc};
use platefall_core::sim::{Simulation, ValidatedConfig};

const WARMUP: usize = 20;
const BLOCK: usize = 100;
const ROUNDS: usize = 4;

/// `platefall free --develop 0 --coupling C --resolution N`.
fn config(n: usize, coupling: Coupling) -> ValidatedConfig {
    RunBuilder::free(Plate::card())
        .develop(0.0)
        .coupling(coupling)
        .resolution(n)
        .build()
        .expect("valid")
}

fn simulation(n: usize, coupling: Coupling) -> Simulation {
    Simulation::new(config(n, coupling)).expect("builds")
}

/// Milliseconds to set up K (three projections) on a fresh flow solver of the run.
fn k_setup_ms(n: usize) -> (f64, AddedMass) {
    let (config, grid) = config(n, Coupling::Strong).into_parts();
    let frame = config.case.prescribed_state(0.0).frame();
    let mut flow = FlowSolver::new(grid, config.flow.clone(), OuterBc::FarField, frame).unwrap();
    let t = Instant::now();
    let k = flow.added_mass();
    (1e3 * t.elapsed().as_secs_f64(), k)
}

/// Seconds for `BLOCK` steps.
fn block(sim: &mut Simulation) -> f64 {
    let t = Instant::now();
    for _ in 0..BLOCK {
        sim.step().expect("step");
    }
    t.elapsed().as_secs_f64()
}

/// Nanoseconds of the strong coupling's own work per step (removing K Δq/Δt from the loads and
/// solving the body's equations), timed over many calls.
fn coupling_ns(sim: &Simulation, k: AddedMass) -> f64 {
    let props = sim.config().body.as_ref().unwrap().props;
    let sc = StrongCoupling::new(&props, k).unwrap();
    let (flow, mut state) = (sim.flow(), *sim.state());
    let calls = 1_000_000;
    let t = Instant::now();
    let mut acc = 0.0;
    for i in 0..calls {
        state.omega += 1e-9 * i as f64;
        let rest = k.rest(
            &flow.loads(),
            flow.frame(),
            flow.frame_prev(),
            flow.dt_prev(),
        );
        acc += sc.derivative(&props, Dof::Free, &state, rest, 1e-3)[3];
    }
    let ns = 1e9 * t.elapsed().as_secs_f64() / calls as f64;
    std::hint::black_box(acc);
    ns
}

fn main() {
    let ns: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let ns = if ns.is_empty() { vec![32, 64] } else { ns };
    println!("   N     cells   K set-up ms   explicit   strong   (ns per cell per step, best of {ROUNDS} blocks of {BLOCK})   extra");
    for n in ns {
        let mut strong = simulation(n, Coupling::Strong);
        let mut explicit = simulation(n, Coupling::Explicit);
        let (setup_ms, k) = k_setup_ms(n);
        assert_eq!(Some(k), strong.added_mass());
        for _ in 0..WARMUP {
            strong.step().unwrap();
            explicit.step().unwrap();
        }
        let (mut best_s, mut best_x) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..ROUNDS {
            best_x = best_x.min(block(&mut explicit));
            best_s = best_s.min(block(&mut strong));
        }
        let cells = strong.flow().grid().cells();
        let per = 1e9 / (BLOCK as f64 * cells as f64);
        let own = coupling_ns(&strong, k);
        println!(
            "{n:4} {cells:9} {setup_ms:13.1} {:10.1} {:8.1} {:+41.1} %",
            best_x * per,
            best_s * per,
            100.0 * (best_s / best_x - 1.0)
        );
        println!(
            "      the coupling's own work: {own:.0} ns per step = {:.4} % of an explicit step",
            100.0 * own / (best_x * 1e9 / BLOCK as f64)
        );
    }
}
