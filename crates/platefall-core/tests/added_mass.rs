//! Force and moment magnitudes against potential-flow theory (docs/physics.md §6, "Coupling"): in the first step of an
//! impulsive start the pressure impulse is pure added mass, F·Δt = −m ΔV and M·Δt = −I_a Δθ̇.
//! The reference is potential flow around the same plate, the default rectangle 1/64 thick
//! (the boundary-element solution of `panels`; a plate of no thickness has m = π/4 ρc² normal to
//! itself and I_a = π/128 ρc⁴ in pitch).
mod panels;

use std::f64::consts::FRAC_PI_2;

use platefall_core::config::RunBuilder;
use platefall_core::shape::Shape;
use platefall_core::sim::{Simulation, StepSample, ValidatedConfig};

/// Potential flow's added-mass matrix of the default plate.
fn reference() -> [[f64; 3]; 3] {
    let plate = Shape::rect(1.0 / 64.0).outline();
    panels::added_mass(&panels::panelled(plate.points(), 1200))
}

fn first_step(config: ValidatedConfig) -> StepSample {
    let mut sim = Simulation::new(config).unwrap();
    sim.step().unwrap()
}

fn added_mass(n: usize) -> f64 {
    let config = RunBuilder::static_plate(FRAC_PI_2).kick(0.0).resolution(n);
    let s = first_step(config.build().unwrap());
    // ΔV = 1 normal to the plate; drag = −F·ê_V, C_D = 2 D.
    0.5 * s.cd * s.dt
}

fn added_inertia(n: usize) -> f64 {
    let config = RunBuilder::forced(1.0).spinup(0.0).resolution(n);
    let s = first_step(config.build().unwrap());
    // Δθ̇ = 1; the moment opposes the spin-up: C_M = 2 M < 0. (The translation at U adds no
    // moment impulse: the plate starts at α = 0, edge-on.)
    -0.5 * s.cm * s.dt
}

#[test]
fn impulsive_start_gives_the_plate_added_mass() {
    // Measured (default plate): N = 32 +2.3 %, N = 64 +1.1 % (sharp edges: first order).
    let (m32, m64) = (added_mass(32), added_mass(64));
    let exact = reference()[1][1];
    eprintln!("added mass: N=32 {m32:.4}, N=64 {m64:.4}, potential flow {exact:.4}");
    assert!(
        (m64 / exact - 1.0).abs() < 0.02,
        "N=64 added mass {m64} vs {exact}"
    );
    assert!(
        (m64 - exact).abs() < (m32 - exact).abs(),
        "no convergence: {m32} → {m64}"
    );
}

#[test]
fn impulsive_spin_up_gives_the_plate_added_inertia() {
    let (i32_, i64_) = (added_inertia(32), added_inertia(64));
    let exact = reference()[2][2];
    eprintln!("added inertia: N=32 {i32_:.5}, N=64 {i64_:.5}, potential flow {exact:.5}");
    assert!(
        (i64_ / exact - 1.0).abs() < 0.03,
        "N=64 added inertia {i64_} vs {exact}"
    );
    assert!(
        (i64_ - exact).abs() < (i32_ - exact).abs(),
        "no convergence: {i32_} → {i64_}"
    );
}
