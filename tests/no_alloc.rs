//! The flow step allocates nothing after start-up (DESIGN: caller-owned workspaces): counted with a
//! global allocator wrapper around the system allocator.
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use platefall::flow::{FlowParams, FlowSolver, Frame, OuterBc};
use platefall::grid::{Grid, GridSpec};

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
    // A translating, spinning plate with the far-field boundary: every phase of the step runs.
    let frame = Frame {
        u0: 0.9,
        v0: -0.4,
        omega: 1.2,
    };
    let mut s = FlowSolver::new(
        Grid::new(&GridSpec::modern(16)).unwrap(),
        FlowParams::default(),
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
    let during = ALLOCATIONS.load(Ordering::SeqCst) - before;
    assert_eq!(during, 0, "{during} allocations in 20 flow steps");
}
