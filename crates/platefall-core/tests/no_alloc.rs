//! The flow step allocates nothing after start-up (DESIGN: caller-owned workspaces): counted with a
//! global allocator wrapper around the system allocator.
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use platefall_core::flow::{FarFieldScheme, FlowParams, FlowSolver, Frame, OuterBc};
use platefall_core::grid::{Grid, GridSpec};

struct Counting;
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn flow_steps_allocate_nothing() {
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
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    for _ in 0..20 {
        let dt = s.prepare().unwrap().min(0.01);
        s.advance(dt, frame).unwrap();
        let _ = s.coefficients();
    }
    ALLOCATIONS.load(Ordering::SeqCst) - before
}
