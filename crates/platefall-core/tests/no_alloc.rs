//! The flow step allocates nothing after start-up (its workspaces are made once, in the constructor): counted with a
//! global allocator wrapper around the system allocator.
mod counting;

use counting::{allocations, exclusive};

use platefall_core::flow::{FarFieldScheme, FlowParams, FlowSolver, Frame, OuterBc};
use platefall_core::grid::{Grid, GridSpec};

#[test]
fn flow_steps_allocate_nothing() {
    let _alone = exclusive();
    // Each scheme, inside a two-worker pool as a run uses it (the u and v halves of every phase
    // go to the two workers) and on the calling thread alone.
    for scheme in [FarFieldScheme::Explicit, FarFieldScheme::Implicit] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let during = pool.install(|| allocations_in_steps(scheme));
        assert_eq!(
            during, 0,
            "{scheme:?}: {during} allocations in 20 flow steps"
        );
        let single = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let during = single.install(|| allocations_in_steps(scheme));
        assert_eq!(during, 0, "{scheme:?}, one thread: {during} allocations");
    }
}

/// Allocations made by 20 steps after 3 warm-up steps.
fn allocations_in_steps(scheme: FarFieldScheme) -> usize {
    // A translating, spinning plate with the far-field boundary: every phase of the step runs.
    let frame = Frame {
        u0: 0.9,
        v0: -0.4,
        omega: 1.2,
    };
    let params = FlowParams {
        far_field: scheme,
        ..FlowParams::default()
    };
    let mut s = FlowSolver::new(
        Grid::new(&GridSpec::modern(16)).unwrap(),
        params,
        OuterBc::FarField,
        frame,
    )
    .unwrap();
    for _ in 0..3 {
        let dt = s.prepare().unwrap().min(0.01);
        s.advance(dt, frame).unwrap();
    }
    let before = allocations();
    for _ in 0..20 {
        let dt = s.prepare().unwrap().min(0.01);
        s.advance(dt, frame).unwrap();
        let _ = s.coefficients();
    }
    allocations() - before
}
